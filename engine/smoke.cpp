#include "engine/smoke.h"

#include <random>
#include <vector>

#include "facet_kernels/spirv.h"

namespace facet {

SmokeResult runSmokeJob(gpu::Device& device, std::size_t elements) {
  using gpu::BufferUsage;
  const float a = 1.5f;
  std::mt19937 rng(std::random_device{}());
  std::uniform_real_distribution<float> uniform(-1000.0f, 1000.0f);
  std::vector<float> x(elements), y(elements);
  for (std::size_t i = 0; i < elements; ++i) {
    x[i] = uniform(rng);
    y[i] = uniform(rng);
  }
  const std::uint64_t bytes = elements * sizeof(float);
  auto xBuffer = device.createBuffer({"smoke x", bytes, BufferUsage::Storage | BufferUsage::CopyDst});
  auto yBuffer =
      device.createBuffer({"smoke y", bytes, BufferUsage::Storage | BufferUsage::CopyDst | BufferUsage::CopySrc});
  auto readback = device.createBuffer({"smoke readback", bytes, BufferUsage::MapRead | BufferUsage::CopyDst});
  device.queue().writeBuffer(xBuffer, 0, std::span<const float>(x));
  device.queue().writeBuffer(yBuffer, 0, std::span<const float>(y));

  auto module = device.createShaderModule({"smoke_saxpy", spirv::smoke_saxpy});
  auto pipeline = device.createComputePipeline({"smoke saxpy", nullptr, &module, "main", {{"kA", a}}});
  auto layout = pipeline.getBindGroupLayout(0);
  auto group = device.createBindGroup({"smoke", &layout, {{0, &xBuffer}, {1, &yBuffer}}});
  const bool timed = device.limits().timestampPeriodNs > 0;
  gpu::QuerySet timestamps;
  if (timed) timestamps = device.createQuerySet({"smoke timestamps", 2});

  auto encoder = device.createCommandEncoder({"smoke"});
  {
    auto pass = encoder.beginComputePass({"saxpy", {timed ? &timestamps : nullptr, 0, 1}});
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups(std::uint32_t((elements + 63) / 64));
  }
  encoder.copyBufferToBuffer(yBuffer, 0, readback, 0, bytes);
  device.queue().submit(encoder.finish());
  device.queue().waitIdle();

  SmokeResult result;
  result.elements = elements;
  auto out = readback.mapped<const float>();
  for (std::size_t i = 0; i < elements; ++i) result.mismatches += out[i] != a * x[i] + y[i];
  if (timed) {
    auto ns = timestamps.readTimestampsNs(0, 2);
    result.gpuMilliseconds = (ns[1] - ns[0]) * 1e-6;
  }
  return result;
}

}  // namespace facet
