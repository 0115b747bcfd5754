// cachedPrefilter and cachedDfgTable: a hit skips the build and returns what
// was stored; a damaged file, other settings or an unwritable directory only
// cost a build; processes building one key at once leave one whole file.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "engine/ibl/prefiltered_environment.h"
#include "tests/support/environment_maps.h"
#include "tests/support/temp_dir.h"

namespace facet::ibl {
namespace {

namespace fs = std::filesystem;

class PrefilterCache : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    setenv("FACET_CACHE_DIR", dir_.c_str(), 1);
    map_ = testing::mapOf(32, 16, testing::skyWithSun);
    settings_.firstLevelWidth = 16;
    settings_.samples = 16;
    settings_.dfgSize = 8;
    settings_.dfgSamples = 16;
  }
  void TearDown() override {
    unsetenv("FACET_CACHE_DIR");
    TempDirTest::TearDown();
  }

  PrefilteredEnvironment cached(const PrefilterSettings& settings) {
    return cachedPrefilter(map_, models_, settings, "cpu", [&] {
      ++builds_;
      return prefilterOnCpu(map_, models_, settings);
    });
  }

  std::vector<fs::path> files() const {
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(dir_)) found.push_back(entry.path());
    return found;
  }

  static void expectSame(const PrefilteredEnvironment& a, const PrefilteredEnvironment& b) {
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (std::size_t i = 0; i < a.levels.size(); ++i) {
      EXPECT_EQ(a.levels[i].width, b.levels[i].width);
      EXPECT_EQ(a.levels[i].height, b.levels[i].height);
      EXPECT_EQ(a.levels[i].alpha, b.levels[i].alpha);
      EXPECT_EQ(a.levels[i].rgb, b.levels[i].rgb);
    }
    EXPECT_EQ(a.irradianceSh, b.irradianceSh);
    EXPECT_EQ(a.irradianceMap.width, b.irradianceMap.width);
    EXPECT_EQ(a.irradianceMap.rgb, b.irradianceMap.rgb);
    EXPECT_EQ(a.irradianceFromMap, b.irradianceFromMap);
    ASSERT_EQ(a.dfg.size(), b.dfg.size());
    for (std::size_t i = 0; i < a.dfg.size(); ++i) {
      EXPECT_EQ(a.dfg[i].distribution, b.dfg[i].distribution);
      EXPECT_EQ(a.dfg[i].geometry, b.dfg[i].geometry);
      EXPECT_EQ(a.dfg[i].scaleBias, b.dfg[i].scaleBias);
    }
  }

  scene::EnvironmentMap map_;
  PrefilterSettings settings_;
  ModelPairs models_{{0, 4}, {1, 6}};
  int builds_ = 0;
};

TEST_F(PrefilterCache, SecondCallReadsTheFile) {
  const PrefilteredEnvironment first = cached(settings_);
  EXPECT_EQ(builds_, 1);
  ASSERT_EQ(files().size(), 1u);
  const PrefilteredEnvironment second = cached(settings_);
  EXPECT_EQ(builds_, 1);
  expectSame(first, second);
}

TEST_F(PrefilterCache, DamagedFileIsRebuilt) {
  const PrefilteredEnvironment reference = cached(settings_);
  const fs::path file = files().at(0);
  const auto size = fs::file_size(file);

  fs::resize_file(file, size / 2);
  expectSame(cached(settings_), reference);
  EXPECT_EQ(builds_, 2);
  EXPECT_EQ(fs::file_size(file), size);

  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(0);
    f.put('X');
  }
  expectSame(cached(settings_), reference);
  EXPECT_EQ(builds_, 3);

  std::ofstream(file, std::ios::app) << "trailing";
  expectSame(cached(settings_), reference);
  EXPECT_EQ(builds_, 4);
  expectSame(cached(settings_), reference);
  EXPECT_EQ(builds_, 4);
}

// A changed byte inside the maps (no longer at the magic) is caught by the
// checksum: without it, the file would read as another image.
TEST_F(PrefilterCache, AChangedValueInsideTheFileIsRebuilt) {
  const PrefilteredEnvironment reference = cached(settings_);
  const fs::path file = files().at(0);
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(fs::file_size(file) / 2));
    f.put('\x7f');
  }
  expectSame(cached(settings_), reference);
  EXPECT_EQ(builds_, 2);
}

// A whole file whose contents do not fit the request (written by a faulty
// build: no DFG tables, a NaN texel, a level or the irradiance map 1 x 1, a
// level at another roughness) is rebuilt, never used.
TEST_F(PrefilterCache, AFileThatDoesNotFitTheRequestIsRebuilt) {
  const PrefilteredEnvironment reference = prefilterOnCpu(map_, models_, settings_);
  const auto oneTexel = [](RadianceLevel& level) {
    level.width = level.height = 1;
    level.rgb.resize(3);
  };
  for (int fault = 0; fault < 6; ++fault) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    cachedPrefilter(map_, models_, settings_, "cpu", [&] {
      PrefilteredEnvironment broken = reference;
      if (fault == 0) broken.dfg.clear();
      if (fault == 1) broken.levels[1].rgb[4] = std::nanf("");
      if (fault == 2) oneTexel(broken.levels[2]);
      if (fault == 3) oneTexel(broken.levels[0]);
      if (fault == 4) oneTexel(broken.irradianceMap);
      if (fault == 5) broken.levels[1].alpha = broken.levels[2].alpha;
      return broken;
    });
    builds_ = 0;
    expectSame(cached(settings_), reference);
    EXPECT_EQ(builds_, 1) << "fault " << fault;
  }
}

// A FIFO where a cache file belongs is a miss, never a read that blocks.
TEST_F(PrefilterCache, AFifoInTheCacheFolderIsAMiss) {
  cached(settings_);
  const fs::path file = files().at(0);
  fs::remove(file);
  ASSERT_EQ(mkfifo(file.c_str(), 0600), 0);
  const PrefilteredEnvironment again = cached(settings_);
  EXPECT_EQ(builds_, 2);
  EXPECT_FALSE(again.dfg.empty());
}

// The DFG tables energy compensation reads go through the same files: a hit
// returns the table dfgTable builds, a damaged file is rebuilt, and another
// pair or grid is another file.
TEST_F(PrefilterCache, DfgTablesAreCachedLikeEnvironments) {
  const DfgTable built = dfgTable(0, 4, settings_);
  EXPECT_EQ(cachedDfgTable(0, 4, settings_).scaleBias, built.scaleBias);
  ASSERT_EQ(files().size(), 1u);
  const fs::path file = files().at(0);
  EXPECT_EQ(file.filename().string().rfind("dfg-", 0), 0u);
  const auto modified = fs::last_write_time(file);
  EXPECT_EQ(cachedDfgTable(0, 4, settings_).scaleBias, built.scaleBias);
  EXPECT_EQ(fs::last_write_time(file), modified);  // read, not rebuilt

  fs::resize_file(file, fs::file_size(file) - 1);
  EXPECT_EQ(cachedDfgTable(0, 4, settings_).scaleBias, built.scaleBias);
  const DfgTable other = cachedDfgTable(1, 6, settings_);
  EXPECT_EQ(other.distribution, 1);
  EXPECT_EQ(other.scaleBias, dfgTable(1, 6, settings_).scaleBias);
  EXPECT_EQ(files().size(), 2u);
}

TEST_F(PrefilterCache, OtherSettingsModelsOrMapUseAnotherFile) {
  cached(settings_);
  PrefilterSettings other = settings_;
  other.samples = 32;
  cached(other);
  EXPECT_EQ(files().size(), 2u);
  models_.pop_back();
  cached(settings_);
  EXPECT_EQ(files().size(), 3u);
  map_.rgb[0] += 1;
  cached(settings_);
  EXPECT_EQ(files().size(), 4u);
  EXPECT_EQ(builds_, 4);
  cachedPrefilter(map_, models_, settings_, "gpu", [&] {
    ++builds_;
    return prefilterOnCpu(map_, models_, settings_);
  });
  EXPECT_EQ(files().size(), 5u);
  EXPECT_EQ(builds_, 5);
}

TEST_F(PrefilterCache, UnwritableDirectoryOnlyCostsTheBuild) {
  const fs::path blocker = dir_ / "not-a-directory";
  std::ofstream(blocker) << "a file where the cache directory should be";
  setenv("FACET_CACHE_DIR", (blocker / "cache").c_str(), 1);
  const PrefilteredEnvironment first = cached(settings_);
  const PrefilteredEnvironment second = cached(settings_);
  EXPECT_EQ(builds_, 2);
  expectSame(first, second);
}

TEST_F(PrefilterCache, WithoutFacetCacheDirTheFolderIsUnderXdgCacheHome) {
  unsetenv("FACET_CACHE_DIR");
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const std::string kept = xdg ? xdg : "";
  setenv("XDG_CACHE_HOME", (dir_ / "xdg").c_str(), 1);
  cached(settings_);
  if (xdg)
    setenv("XDG_CACHE_HOME", kept.c_str(), 1);
  else
    unsetenv("XDG_CACHE_HOME");
  ASSERT_TRUE(fs::is_directory(dir_ / "xdg" / "facet"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "xdg" / "facet"), fs::directory_iterator()), 1);
}

// Many renders of one environment at once (a farm's array tasks sharing a
// cache folder): each process builds and writes the same key; every one
// must return the right maps, and one whole file must remain.
TEST_F(PrefilterCache, ProcessesBuildingOneKeyAtOnceDoNotCorruptIt) {
  const PrefilteredEnvironment reference = prefilterOnCpu(map_, models_, settings_);
  const auto same = [](const PrefilteredEnvironment& a, const PrefilteredEnvironment& b) {
    bool equal = a.levels.size() == b.levels.size() && a.irradianceSh == b.irradianceSh &&
                 a.irradianceMap.rgb == b.irradianceMap.rgb && a.irradianceFromMap == b.irradianceFromMap &&
                 a.dfg.size() == b.dfg.size();
    for (std::size_t i = 0; equal && i < a.levels.size(); ++i) equal = a.levels[i].rgb == b.levels[i].rgb;
    for (std::size_t i = 0; equal && i < a.dfg.size(); ++i) equal = a.dfg[i].scaleBias == b.dfg[i].scaleBias;
    return equal;
  };
  int start[2];
  ASSERT_EQ(pipe(start), 0);
  constexpr int kProcesses = 6;
  std::vector<pid_t> children;
  for (int i = 0; i < kProcesses; ++i) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {  // waits for the parent's go, so that the builds overlap
      close(start[1]);
      char go = 0;
      if (read(start[0], &go, 1) != 1) _exit(2);
      _exit(same(cached(settings_), reference) ? 0 : 1);
    }
    children.push_back(pid);
  }
  close(start[0]);
  const std::string go(kProcesses, 'g');
  ASSERT_EQ(write(start[1], go.data(), go.size()), ssize_t(go.size()));
  close(start[1]);
  for (pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a process got wrong maps";
  }
  ASSERT_EQ(files().size(), 1u) << "one file, and no temporary left behind";
  EXPECT_TRUE(same(cached(settings_), reference));
  EXPECT_EQ(builds_, 0) << "the file the processes left is read";
}

}  // namespace
}  // namespace facet::ibl
