// A staged output folder: nothing reaches the destination before publish,
// everything does at publish (subfolders included), and a run that never
// publishes, or was killed, leaves the destination as it was.
#include "engine/image/output_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/temp_dir.h"

namespace facet {
namespace {

namespace fs = std::filesystem;

class OutputFolder : public facet::testing::TempDirTest {
 protected:
  static std::string contents(const fs::path& file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  std::size_t entries(const fs::path& folder) const {
    return std::size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
  }
};

TEST_F(OutputFolder, FilesReachTheDestinationAtPublishOnly) {
  const fs::path out = dir_ / "bench";
  fs::create_directories(out);
  std::ofstream(out / "report.md") << "old";
  {
    StagedOutputFolder folder(out);
    std::ofstream(folder.path() / "report.md") << "new";
    fs::create_directories(folder.path() / "scaling");
    std::ofstream(folder.path() / "scaling" / "points.csv") << "1,2";
    EXPECT_EQ(contents(out / "report.md"), "old");
    EXPECT_FALSE(fs::exists(out / "scaling" / "points.csv"));
    folder.publish();
  }
  EXPECT_EQ(contents(out / "report.md"), "new");
  EXPECT_EQ(contents(out / "scaling" / "points.csv"), "1,2");
  EXPECT_EQ(entries(out), 2u) << "the staging folder is gone";
}

TEST_F(OutputFolder, ARunThatFailsLeavesTheDestinationAsItWas) {
  const fs::path out = dir_ / "chart";
  fs::create_directories(out);
  std::ofstream(out / "ibl_chart.csv") << "old";
  try {
    StagedOutputFolder folder(out);
    std::ofstream(folder.path() / "ibl_chart.csv") << "half";
    throw std::runtime_error("disk full");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(contents(out / "ibl_chart.csv"), "old");
  EXPECT_EQ(entries(out), 1u);
}

TEST_F(OutputFolder, AKilledRunsStagingIsRemovedByTheNextRun) {
  const fs::path out = dir_ / "bench";
  const fs::path orphan = out / ".facet-staging-999999999";  // no pid is this large
  fs::create_directories(orphan);
  std::ofstream(orphan / "report.md") << "half";
  StagedOutputFolder folder(out);
  EXPECT_FALSE(fs::exists(orphan));
  EXPECT_TRUE(fs::is_directory(folder.path()));
}

}  // namespace
}  // namespace facet
