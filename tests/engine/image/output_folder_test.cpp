// A staged output folder: nothing reaches the destination before publish,
// everything does at publish (subfolders included), and a run that never
// publishes, or was killed, leaves the destination as it was.
#include "engine/image/output_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "engine/image/image_io.h"
#include "tests/support/scoped_env.h"
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

// A scratch folder goes with its command whatever it holds, and one a
// killed run left (its process ended) goes with the next of its kind; a
// running process's and another kind's stay.
TEST_F(OutputFolder, AScratchFolderLeavesNothingAndClearsWhatAKilledRunLeft) {
  const facet::testing::ScopedEnv tmpdir("TMPDIR", dir_.string());
  // pid_max is at most 2^22, so no process has this id.
  const fs::path killed = dir_ / "facet-preview-4194305-7", running = dir_ / ("facet-preview-1-7"),
                 other = dir_ / "facet-plot-4194305-7";
  for (const fs::path& left : {killed, running, other}) fs::create_directories(left / "frames");
  fs::path made;
  {
    const ScratchFolder folder("--movie", "the turntable's frames", "preview");
    made = folder.path();
    EXPECT_EQ(made.parent_path(), dir_);
    std::ofstream(made / "frame_00000.png") << "png";
    EXPECT_FALSE(fs::exists(killed));
  }
  EXPECT_FALSE(fs::exists(made));
  EXPECT_TRUE(fs::exists(running));
  EXPECT_TRUE(fs::exists(other));
}

TEST_F(OutputFolder, AnUnusableTemporaryFolderIsOneErrorNamingItAndWhy) {
  const fs::path file = dir_ / "a_file";
  std::ofstream(file) << "x";
  const std::pair<fs::path, std::string> cases[] = {{dir_ / "no_such_folder", "no such folder"},
                                                    {file, "it is not a folder"}};
  for (const auto& [folder, why] : cases) {
    const facet::testing::ScopedEnv tmpdir("TMPDIR", folder.string());
    try {
      const ScratchFolder scratch("--movie", "the turntable's frames", "preview");
      ADD_FAILURE() << folder << ": no error";
    } catch (const OutputError& e) {
      EXPECT_EQ(std::string(e.what()),
                "--movie: cannot make a folder for the turntable's frames in the temporary "
                "folder '" +
                    folder.string() + "' (TMPDIR): " + why + "; set TMPDIR to a writable folder");
    }
  }
}

}  // namespace
}  // namespace facet
