// File names reach gnuplot as data, never as script text: a quote cannot run
// a command and no name is rewritten; a chart gnuplot leaves incomplete is
// an error that leaves no file.
#include "analysis/gnuplot.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
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

// The message of the error drawing a chart to `out` raises; empty where
// it raises none.
std::string chartError(const fs::path& out) {
  try {
    runGnuplot("set output OUTPUT\n" + kLine, kData, out, 200, 120);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

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
  EXPECT_EQ(chartError(out), "--out: cannot make a folder for gnuplot's script and data in the temporary folder '" +
                                 (dir_ / "no_such_folder").string() +
                                 "' (TMPDIR): no such folder; set TMPDIR to a writable folder");
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

// gnuplot runs as the other programs facet runs: found on PATH, ended at
// its time limit, and a chart it does not finish is an error with no file.
TEST_F(Gnuplot, AGnuplotThatNeverFinishesIsEndedAndLeavesNoChart) {
  const fs::path bin = dir_ / "bin";
  fs::create_directories(bin);
  {
    std::ofstream script(bin / "gnuplot");
    script << "#!/bin/sh\nexec /usr/bin/tail -f /dev/null\n";
  }
  fs::permissions(bin / "gnuplot", fs::perms::owner_all);
  const facet::testing::ScopedEnv path("PATH", bin.string());
  const facet::testing::ScopedEnv limit("FACET_CHILD_TIME_LIMIT", "1");
  const fs::path out = dir_ / "chart.svg";
  const std::string error = chartError(out);
  EXPECT_NE(error.find("did not finish within 1 s, and was ended"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir_ / "chart.svg.partial"));
}

TEST_F(Gnuplot, AMissingGnuplotIsOneErrorSayingWhatToInstall) {
  const facet::testing::ScopedEnv path("PATH", (dir_ / "empty").string());
  const fs::path out = dir_ / "chart.svg";
  EXPECT_EQ(chartError(out), "gnuplot not found on PATH; install it (Debian: gnuplot-nox)");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace facet::analysis
