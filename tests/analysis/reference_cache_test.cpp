// The parity reference's cache: what is stored reads back whole under its
// key alone; a changed byte, another size or count reads as nothing; the
// key follows every input's contents and every flag; the folder is held to
// its budget, the oldest files going first.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <random>

#include "analysis/reference_cache.h"
#include "tests/support/noisy_square.h"
#include "tests/support/scoped_env.h"
#include "tests/support/temp_dir.h"

namespace facet::analysis {
namespace {

namespace fs = std::filesystem;

class ReferenceCache : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    recordProgramAtStart();
    cacheFolder_.emplace("FACET_CACHE_DIR", (dir_ / "cache").string());
  }
  void TearDown() override {
    cacheFolder_.reset();
    TempDirTest::TearDown();
  }
  // `count` renders of a noisy square, seeds apart.
  static CachedReference renders(int count) {
    CachedReference reference;
    reference.device = "CPU reference, double precision";
    std::mt19937 random(5);
    std::uniform_real_distribution<float> noise(0.0f, 1.0f);
    for (int i = 0; i < count; ++i) reference.add(testing::noisySquare([&] { return noise(random); }));
    return reference;
  }
  std::vector<fs::path> referenceFiles() const {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir_ / "cache"))
      if (entry.path().filename().string().rfind("parity-reference-", 0) == 0) files.push_back(entry.path());
    return files;
  }
  std::optional<testing::ScopedEnv> cacheFolder_;
};

TEST_F(ReferenceCache, WhatIsStoredReadsBackWholeUnderItsKey) {
  const CachedReference stored = renders(3);
  storeReference("key one", stored);
  const std::optional<CachedReference> back = loadReference("key one", 20, 20, 3);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->device, stored.device);
  EXPECT_EQ(back->renders(), 3);
  EXPECT_EQ(back->first.beauty, stored.first.beauty);
  EXPECT_EQ(back->first.depth, stored.first.depth);
  EXPECT_EQ(back->first.patchId, stored.first.patchId);
  EXPECT_EQ(back->first.shadingNormal, stored.first.shadingNormal);
  for (int i = 1; i < 3; ++i) EXPECT_EQ(back->render(i).beauty, stored.render(i).beauty) << i;
  // Another key, size or count finds nothing.
  EXPECT_FALSE(loadReference("key two", 20, 20, 3));
  EXPECT_FALSE(loadReference("key one", 20, 10, 3));
  EXPECT_FALSE(loadReference("key one", 20, 20, 4));
  EXPECT_FALSE(loadReference("", 20, 20, 3));
}

TEST_F(ReferenceCache, AChangedByteReadsAsNothing) {
  storeReference("key", renders(2));
  const std::vector<fs::path> files = referenceFiles();
  ASSERT_EQ(files.size(), 1u);
  {
    std::fstream file(files[0], std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(std::streamoff(fs::file_size(files[0]) / 2));
    file.put('\x5a');
  }
  EXPECT_FALSE(loadReference("key", 20, 20, 2));
}

TEST_F(ReferenceCache, TheKeyFollowsEveryInputEveryFlagAndTheSettings) {
  const fs::path input = dir_ / "cage.obj";
  std::ofstream(input) << "v 0 0 0\n";
  const scene::Scene scene;
  const std::string key = referenceKey(scene, {input}, "size 16x12");
  ASSERT_FALSE(key.empty());
  EXPECT_EQ(referenceKey(scene, {input}, "size 16x12"), key);
  EXPECT_NE(referenceKey(scene, {input}, "size 16x13"), key);
  scene::Scene wider = scene;
  wider.render.width = 17;
  EXPECT_NE(referenceKey(wider, {input}, "size 16x12"), key);
  std::ofstream(input) << "v 0 0 1\n";  // the same path, other contents
  EXPECT_NE(referenceKey(scene, {input}, "size 16x12"), key);
  EXPECT_NE(rendersKey(key, 4), rendersKey(key, 8));
  EXPECT_EQ(rendersKey("", 4), "");
  // A file that can no longer be read: no key, nothing cached.
  fs::remove(input);
  EXPECT_EQ(referenceKey(scene, {input}, "size 16x12"), "");
}

// Two files made hours ago, the older read since: the one not read goes first.
TEST_F(ReferenceCache, TheFolderIsHeldToItsBudgetTheLeastRecentlyUsedFirst) {
  const CachedReference reference = renders(2);
  const auto hoursAgo = [](int hours) { return fs::file_time_type::clock::now() - std::chrono::hours(hours); };
  storeReference("read since", reference);
  const std::uintmax_t one = fs::file_size(referenceFiles().at(0));
  fs::last_write_time(referenceFiles().at(0), hoursAgo(2));
  storeReference("not read", reference);
  for (const fs::path& file : referenceFiles())
    if (fs::last_write_time(file) > hoursAgo(1)) fs::last_write_time(file, hoursAgo(1));
  ASSERT_TRUE(loadReference("read since", 20, 20, 2));
  storeReference("newest", reference, 2 * one + one / 2);
  EXPECT_EQ(referenceFiles().size(), 2u);
  EXPECT_FALSE(loadReference("not read", 20, 20, 2));
  EXPECT_TRUE(loadReference("read since", 20, 20, 2));
  EXPECT_TRUE(loadReference("newest", 20, 20, 2));
  // One file over the budget is not stored.
  storeReference("too large", reference, one / 2);
  EXPECT_FALSE(loadReference("too large", 20, 20, 2));
}

TEST_F(ReferenceCache, AFileHoldsThePlanesTheByteCountSays) {
  storeReference("key", renders(3));
  EXPECT_LE(referenceBytes(20, 20, 3), fs::file_size(referenceFiles().at(0)));
  EXPECT_GT(referenceBytes(20, 20, 3) + 4096, fs::file_size(referenceFiles().at(0)));
}

// Another writer's temporary file is not the cache's to remove, unless its writer is long gone.
TEST_F(ReferenceCache, TheBudgetLeavesLiveWritersTemporaryFiles) {
  storeReference("key", renders(2));
  const std::uintmax_t one = fs::file_size(referenceFiles().at(0));
  const fs::path temporary = referenceFiles().at(0).string() + ".tmp123";
  std::ofstream(temporary) << std::string(3 * one, 'x');
  const fs::path abandoned = referenceFiles().at(0).string() + ".tmp456";
  std::ofstream(abandoned) << "x";
  fs::last_write_time(abandoned, fs::file_time_type::clock::now() - std::chrono::hours(2));
  // Both references fit; counted, the temporary file would not.
  storeReference("other", renders(2), 2 * one + one / 2);
  EXPECT_TRUE(fs::exists(temporary));
  EXPECT_TRUE(loadReference("key", 20, 20, 2));
  // A temporary file hours old is no live writer's.
  EXPECT_FALSE(fs::exists(abandoned));
}

}  // namespace
}  // namespace facet::analysis
