#include "benchmarks/incoherent/ray_list.h"

#include <cstring>

namespace facet::benchmarks::incoherent {

gpu::Buffer uploadBuffer(gpu::Device& device, const char* label, gpu::BufferUsage usage, const void* data,
                         std::size_t bytes) {
  gpu::Buffer buffer = device.createBuffer({label, bytes, usage | gpu::BufferUsage::CopyDst});
  device.queue().writeBuffer(buffer, 0, data, bytes);
  return buffer;
}

std::vector<std::uint32_t> readBack(gpu::Device& device, const gpu::Buffer& source, std::size_t bytes) {
  gpu::Buffer host = device.createBuffer({"readback", bytes, gpu::BufferUsage::MapRead | gpu::BufferUsage::CopyDst});
  gpu::CommandEncoder encoder = device.createCommandEncoder({"readback"});
  encoder.copyBufferToBuffer(source, 0, host, 0, bytes);
  device.queue().submit(encoder.finish());
  device.queue().waitIdle();
  std::vector<std::uint32_t> words(bytes / 4);
  std::memcpy(words.data(), host.mappedRange().data(), bytes);
  return words;
}

Work submitAndReadWork(gpu::Device& device, gpu::CommandEncoder& encoder, const gpu::Buffer& counts, std::size_t rays) {
  device.queue().submit(encoder.finish());
  device.queue().waitIdle();
  const std::vector<std::uint32_t> words = readBack(device, counts, rays * 16);
  Work out(rays);
  for (std::size_t i = 0; i < rays; ++i) out[i] = {words[4 * i], words[4 * i + 1], words[4 * i + 2]};
  return out;
}

}  // namespace facet::benchmarks::incoherent
