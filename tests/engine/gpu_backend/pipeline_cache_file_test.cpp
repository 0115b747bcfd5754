// The device's pipeline cache on disk: written, read back, a damaged or
// another driver's file ignored with one warning and written again, and the
// pixels the same with the cache as without; the start-up stages a render
// reports.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "engine/gpu_backend/pipeline_cache_file.h"
#include "engine/renderer.h"
#include "scenes/scene_file.h"
#include "tests/support/image_windows.h"
#include "tests/support/temp_dir.h"

namespace facet::gpu_backend {
namespace {

using ::testing::HasSubstr;
using ::testing::IsEmpty;

std::vector<char> bytesOf(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void overwrite(const std::filesystem::path& file, const std::vector<char>& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
}

bool reports(const RenderReport& report, Stage stage) {
  for (const StageTime& s : report.stages)
    if (s.stage == stage) return true;
  return false;
}

class PipelineCacheFileTest : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    setenv("FACET_CACHE_DIR", (dir_ / "cache").c_str(), 1);
    instance_ = gpu::Instance::create({gpu::Validation::IfInstalled});
    device_ = instance_.requestAdapter().requestDevice({"cache test"});
    file_ = *pipelineCacheFile(device_.adapterInfo());
  }
  void TearDown() override {
    device_ = gpu::Device();
    unsetenv("FACET_CACHE_DIR");
    TempDirTest::TearDown();
  }

  gpu::Instance instance_;
  gpu::Device device_;
  std::filesystem::path file_;
};

TEST_F(PipelineCacheFileTest, NoFileIsAnEmptyCacheAndNoWarning) {
  const StoredPipelineCache stored = loadPipelineCache(device_.adapterInfo());
  EXPECT_THAT(stored.data, IsEmpty());
  EXPECT_THAT(stored.warning, IsEmpty());
}

TEST_F(PipelineCacheFileTest, AStoredCacheIsReadBackAsTheDevicesData) {
  storePipelineCache(device_);
  EXPECT_EQ(file_.parent_path(), dir_ / "cache");
  ASSERT_TRUE(std::filesystem::is_regular_file(file_));
  const StoredPipelineCache stored = loadPipelineCache(device_.adapterInfo());
  EXPECT_THAT(stored.warning, IsEmpty());
  EXPECT_EQ(stored.data, device_.pipelineCacheData());
}

TEST_F(PipelineCacheFileTest, ADamagedFileIsIgnoredWithAWarningAndWrittenAgain) {
  storePipelineCache(device_);
  std::vector<char> bytes = bytesOf(file_);
  for (std::size_t at : {bytes.size() / 2, std::size_t(0), bytes.size() - 1}) {
    std::vector<char> damaged = bytes;
    damaged[at] ^= 0x10;
    overwrite(file_, damaged);
    const StoredPipelineCache stored = loadPipelineCache(device_.adapterInfo());
    EXPECT_THAT(stored.data, IsEmpty()) << "byte " << at;
    EXPECT_THAT(stored.warning, HasSubstr(file_.string())) << "byte " << at;
    EXPECT_THAT(stored.warning, HasSubstr("ignored")) << "byte " << at;
  }
  overwrite(file_, {bytes.begin(), bytes.begin() + std::ptrdiff_t(bytes.size() / 3)});  // truncated
  EXPECT_THAT(loadPipelineCache(device_.adapterInfo()).warning, HasSubstr("ignored"));
  storePipelineCache(device_);
  EXPECT_THAT(loadPipelineCache(device_.adapterInfo()).warning, IsEmpty());
}

TEST_F(PipelineCacheFileTest, AnotherDriversFileIsNeverHandedOn) {
  storePipelineCache(device_);
  gpu::AdapterInfo other = device_.adapterInfo();
  other.pipelineCacheUuid[0] ^= 1;
  // This driver's file where the other's belongs: its key names this driver.
  const std::filesystem::path otherFile = *pipelineCacheFile(other);
  ASSERT_NE(otherFile, file_);
  std::filesystem::copy_file(file_, otherFile);
  const StoredPipelineCache stored = loadPipelineCache(other);
  EXPECT_THAT(stored.data, IsEmpty());
  EXPECT_THAT(stored.warning, HasSubstr(otherFile.string()));
}

TEST_F(PipelineCacheFileTest, RendersAreTheSameWithTheCacheWithoutItAndWithADamagedOne) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "superball.obj");
  scene.render.width = 16;
  scene.render.height = 12;
  const PixelRect whole = PixelRect::whole(16, 12);

  Renderer first;
  const RenderReport fresh = first.render(scene, Backend::Gpu);
  EXPECT_TRUE(reports(fresh, Stage::Device));
  EXPECT_TRUE(reports(fresh, Stage::Pipelines));
  EXPECT_THAT(fresh.warnings, IsEmpty());
  ASSERT_TRUE(std::filesystem::is_regular_file(file_));
  // A kept renderer starts up once.
  const RenderReport again = first.render(scene, Backend::Gpu);
  EXPECT_FALSE(reports(again, Stage::Device));
  EXPECT_FALSE(reports(again, Stage::Pipelines));
  EXPECT_THAT(facet::testing::pixelsThatDiffer(fresh.image, again.image, whole), IsEmpty());

  const RenderReport cached = Renderer().render(scene, Backend::Gpu);
  EXPECT_THAT(cached.warnings, IsEmpty());
  EXPECT_THAT(facet::testing::pixelsThatDiffer(fresh.image, cached.image, whole), IsEmpty());

  std::vector<char> bytes = bytesOf(file_);
  bytes[bytes.size() / 2] ^= 0x10;
  overwrite(file_, bytes);
  Renderer damaged;
  const RenderReport rebuilt = damaged.render(scene, Backend::Gpu);
  ASSERT_EQ(rebuilt.warnings.size(), 1u);
  EXPECT_THAT(rebuilt.warnings[0], HasSubstr(file_.string()));
  EXPECT_THAT(facet::testing::pixelsThatDiffer(fresh.image, rebuilt.image, whole), IsEmpty());
  EXPECT_THAT(damaged.render(scene, Backend::Gpu).warnings, IsEmpty());      // once
  EXPECT_THAT(loadPipelineCache(device_.adapterInfo()).warning, IsEmpty());  // written again
}

}  // namespace
}  // namespace facet::gpu_backend
