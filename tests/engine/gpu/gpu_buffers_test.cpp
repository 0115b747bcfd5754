#include <numeric>
#include <random>

#include "tests/support/gpu_device.h"

namespace facet::gpu::testing {
namespace {

class BufferRoundTrip : public GpuTest, public ::testing::WithParamInterface<std::uint64_t> {};

std::vector<std::uint32_t> randomWords(std::size_t count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::uint32_t> words(count);
  for (auto& w : words) w = rng();
  return words;
}

// Host → writeBuffer → storage buffer → copy → MapRead buffer → host.
TEST_P(BufferRoundTrip, WriteBufferThenCopyToMapRead) {
  const std::uint64_t bytes = GetParam();
  auto data = randomWords(bytes / 4, std::uint32_t(bytes));
  Buffer storage = upload(data, BufferUsage::Storage | BufferUsage::CopySrc);
  EXPECT_EQ(readBack<std::uint32_t>(storage), data);
}

// Host → MapWrite buffer → copy → storage → copy → MapRead → host, at an offset.
TEST_P(BufferRoundTrip, MappedWriteThroughCopiesAtAnOffset) {
  const std::uint64_t bytes = GetParam();
  const std::uint64_t offset = 256;
  auto data = randomWords(bytes / 4, std::uint32_t(bytes) + 1);
  Buffer source = device_.createBuffer({"source", bytes, BufferUsage::MapWrite | BufferUsage::CopySrc});
  std::memcpy(source.mappedRange().data(), data.data(), bytes);
  Buffer middle = device_.createBuffer(
      {"middle", bytes + offset, BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst});
  Buffer sink = device_.createBuffer({"sink", bytes, BufferUsage::MapRead | BufferUsage::CopyDst});
  auto encoder = device_.createCommandEncoder({"round trip"});
  encoder.copyBufferToBuffer(source, 0, middle, offset, bytes);
  encoder.copyBufferToBuffer(middle, offset, sink, 0, bytes);
  device_.queue().submit(encoder.finish());
  device_.queue().waitIdle();
  auto out = sink.mapped<const std::uint32_t>();
  EXPECT_TRUE(std::equal(out.begin(), out.end(), data.begin(), data.end()));
}

INSTANTIATE_TEST_SUITE_P(Sizes, BufferRoundTrip,
                         ::testing::Values(4, 4100, std::uint64_t(1) << 20, std::uint64_t(64) << 20),
                         [](const auto& info) { return std::to_string(info.param) + "_bytes"; });

TEST_F(GpuTest, LaterWriteToTheSameRangeWins) {
  Buffer buffer =
      device_.createBuffer({"twice", 64, BufferUsage::Storage | BufferUsage::CopyDst | BufferUsage::CopySrc});
  std::vector<std::uint32_t> first(16, 1), second(16, 2);
  device_.queue().writeBuffer(buffer, 0, std::span<const std::uint32_t>(first));
  device_.queue().writeBuffer(buffer, 0, std::span<const std::uint32_t>(second));
  EXPECT_EQ(readBack<std::uint32_t>(buffer), second);
}

TEST_F(GpuTest, ClearBufferZeroesOnlyItsRange) {
  std::vector<std::uint32_t> ones(64, 1);
  Buffer buffer = upload(ones, BufferUsage::Storage | BufferUsage::CopySrc);
  auto encoder = device_.createCommandEncoder();
  encoder.clearBuffer(buffer, 64, 128);
  device_.queue().submit(encoder.finish());
  auto out = readBack<std::uint32_t>(buffer);
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], (i >= 16 && i < 48) ? 0u : 1u) << "word " << i;
}

TEST_F(GpuTest, ResourcesDroppedBeforeTheWorkEndsStayAliveUntilItDoes) {
  Buffer sink = device_.createBuffer({"sink", 1 << 20, BufferUsage::MapRead | BufferUsage::CopyDst});
  {
    std::vector<std::uint32_t> data(1 << 18);
    std::iota(data.begin(), data.end(), 0u);
    Buffer source = upload(data, BufferUsage::CopySrc);
    auto encoder = device_.createCommandEncoder();
    encoder.copyBufferToBuffer(source, 0, sink, 0, 1 << 20);
    device_.queue().submit(encoder.finish());
  }  // `source` is gone here; the queue still holds it
  device_.queue().waitIdle();
  auto out = sink.mapped<const std::uint32_t>();
  for (std::uint32_t i = 0; i < out.size(); i += 4099) ASSERT_EQ(out[i], i);
}

}  // namespace
}  // namespace facet::gpu::testing
