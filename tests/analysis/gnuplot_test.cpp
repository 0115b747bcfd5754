// File names reach gnuplot as data, never as script text: a quote cannot run
// a command and no name is rewritten; a chart gnuplot leaves incomplete is
// an error that leaves no file.
#include "analysis/gnuplot.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "engine/image/image_io.h"
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
  const char* old = getenv("TMPDIR");
  const std::string kept = old ? old : "";
  setenv("TMPDIR", folder.c_str(), 1);
  const fs::path out = folder / "OUTPUT DATA.svg";
  EXPECT_NO_THROW(runGnuplot("set output OUTPUT\n" + kLine, kData, out, 200, 120));
  if (old)
    setenv("TMPDIR", kept.c_str(), 1);
  else
    unsetenv("TMPDIR");
  EXPECT_TRUE(fs::is_regular_file(out));
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
