// File names reach gnuplot as data, never as script text: a quote cannot run
// a command and no name is rewritten; a chart gnuplot leaves incomplete is
// an error that leaves no file.
#include "analysis/gnuplot.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string>

#include "engine/image/image_io.h"
#include "tests/support/scoped_env.h"
#include "tests/support/temp_dir.h"

namespace facet::analysis {
namespace {

namespace fs = std::filesystem;

class Gnuplot : public facet::testing::TempDirTest {};

const std::string kLine = "plot DATA using 1:2 with lines title 'y'\n";
const std::string kData = "0 0\n1 2\n2 1\n";

TEST_F(Gnuplot, AQuoteInTheOutputNameRunsNothing) {
  const fs::path before = fs::current_path();
  fs::current_path(dir_);
  const fs::path out = dir_ / "chart'; system('touch injected'); x='.png";
  EXPECT_NO_THROW(runGnuplot("set output OUTPUT\n" + kLine, kData, out, 200, 120));
  fs::current_path(before);
  EXPECT_TRUE(fs::is_regular_file(out));
  EXPECT_FALSE(fs::exists(dir_ / "injected"));
}

TEST_F(Gnuplot, NamesThatSpellThePlaceholdersAreKeptAsTheyAre) {
  const fs::path folder = dir_ / "DATA OUTPUT";
  fs::create_directories(folder);
  const facet::testing::ScopedEnv tmpdir("TMPDIR", folder.string());
  const fs::path out = folder / "OUTPUT DATA.svg";
  EXPECT_NO_THROW(runGnuplot("set output OUTPUT\n" + kLine, kData, out, 200, 120));
  EXPECT_TRUE(fs::is_regular_file(out));
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1) << "gnuplot's files stayed";
}

// gnuplot's script and data go to a folder of their own in TMPDIR: an
// unusable one is one error naming it, before gnuplot runs.
TEST_F(Gnuplot, AnUnusableTemporaryFolderIsOneErrorNamingIt) {
  const facet::testing::ScopedEnv tmpdir("TMPDIR", (dir_ / "no_such_folder").string());
  const fs::path out = dir_ / "chart.svg";
  try {
    runGnuplot("set output OUTPUT\n" + kLine, kData, out, 200, 120);
    ADD_FAILURE() << "no error";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--out: cannot make a folder for gnuplot's script and data in the temporary folder '" +
                  (dir_ / "no_such_folder").string() + "' (TMPDIR): no such folder; set TMPDIR to a writable folder");
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Gnuplot, AnImageGnuplotDoesNotFinishIsAnErrorAndNoFile) {
  // gnuplot opens the output and exits 0 without drawing: an empty file.
  const fs::path out = dir_ / "unfinished.png";
  EXPECT_THROW(runGnuplot("set output OUTPUT\nexit\n", kData, out, 200, 120), std::runtime_error);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir_ / "unfinished.png.partial"));
}

// Where gnuplot's finished chart cannot be renamed to (a folder), the
// output is refused as any command's is, before gnuplot runs.
TEST_F(Gnuplot, AFolderAsTheOutputIsRefusedBeforeGnuplotRuns) {
  const fs::path out = dir_ / "chart.png";
  fs::create_directories(out);
  EXPECT_THROW(runGnuplot("set output OUTPUT\n" + kLine, kData, out, 200, 120), OutputError);
  EXPECT_TRUE(fs::is_directory(out));
  EXPECT_FALSE(fs::exists(dir_ / "chart.png.partial"));
}

}  // namespace
}  // namespace facet::analysis
