// engine/gpu micro-benchmarks: the fixed costs and the throughputs that bound
// every kernel facet runs. Run: build/benchmarks/gpu_bench
#include <benchmark/benchmark.h>

#include <cstring>
#include <thread>
#include <vector>

#include "engine/gpu/gpu.h"
#include "engine/renderer.h"
#include "facet_kernels/spirv.h"

namespace {

using namespace facet::gpu;
using facet::gpuAdapterFromEnvironment;
using facet::gpuInstanceFromEnvironment;

Device& device() {
  static Device d = Instance::create(gpuInstanceFromEnvironment()).requestAdapter(gpuAdapterFromEnvironment({})).requestDevice({"bench"});
  return d;
}

struct FmaChain {
  explicit FmaChain(std::uint32_t elements, int iterations = 256)
      : shader(device().createShaderModule({"fma_chain", facet::spirv::fma_chain})),
        pipeline(
            device().createComputePipeline({"fma", nullptr, &shader, "main", {{"kIterations", double(iterations)}}})),
        layout(pipeline.getBindGroupLayout(0)),
        values(device().createBuffer({"values", elements * 16ull, BufferUsage::Storage | BufferUsage::CopyDst})),
        group(device().createBindGroup({"fma", &layout, {{0, &values}}})),
        workgroups(elements / 64) {
    device().queue().writeBuffer(values, 0, std::span<const float>(std::vector<float>(elements * 4, 0.5f)));
  }
  void record(ComputePassEncoder& pass) const {
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups(workgroups);
  }
  ShaderModule shader;
  ComputePipeline pipeline;
  BindGroupLayout layout;
  Buffer values;
  BindGroup group;
  std::uint32_t workgroups;
};

// One tiny dispatch per submit, waited for: the floor under every stage.
void BM_SubmitAndWaitOneDispatch(benchmark::State& state) {
  FmaChain job(64, 1);
  for (auto _ : state) {
    auto encoder = device().createCommandEncoder();
    {
      auto pass = encoder.beginComputePass();
      job.record(pass);
    }
    device().queue().submit(encoder.finish());
    device().queue().waitIdle();
  }
}
BENCHMARK(BM_SubmitAndWaitOneDispatch)->Unit(benchmark::kMicrosecond)->UseRealTime();

// Many dependent dispatches in one command buffer: the marginal cost of a stage.
void BM_DispatchesPerSubmit(benchmark::State& state) {
  FmaChain job(64, 1);
  const auto dispatches = state.range(0);
  for (auto _ : state) {
    auto encoder = device().createCommandEncoder();
    {
      auto pass = encoder.beginComputePass();
      for (int i = 0; i < dispatches; ++i) job.record(pass);
    }
    device().queue().submit(encoder.finish());
    device().queue().waitIdle();
  }
  state.SetItemsProcessed(state.iterations() * dispatches);  // dispatches per second
}
BENCHMARK(BM_DispatchesPerSubmit)->Arg(100)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_Upload(benchmark::State& state) {
  const std::size_t bytes = std::size_t(state.range(0)) << 20;
  Buffer target = device().createBuffer({"target", bytes, BufferUsage::Storage | BufferUsage::CopyDst});
  std::vector<std::byte> data(bytes, std::byte{1});
  for (auto _ : state) {
    device().queue().writeBuffer(target, 0, data.data(), bytes);
    device().queue().waitIdle();
  }
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(bytes));
}
BENCHMARK(BM_Upload)->Arg(1)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Readback(benchmark::State& state) {
  const std::size_t bytes = std::size_t(state.range(0)) << 20;
  Buffer source = device().createBuffer({"source", bytes, BufferUsage::Storage | BufferUsage::CopySrc});
  Buffer staging = device().createBuffer({"staging", bytes, BufferUsage::MapRead | BufferUsage::CopyDst});
  std::vector<std::byte> host(bytes);
  for (auto _ : state) {
    auto encoder = device().createCommandEncoder();
    encoder.copyBufferToBuffer(source, 0, staging, 0, bytes);
    device().queue().submit(encoder.finish());
    device().queue().waitIdle();
    std::memcpy(host.data(), staging.mappedRange().data(), bytes);
  }
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(bytes));
}
BENCHMARK(BM_Readback)->Arg(1)->Arg(64)->Unit(benchmark::kMillisecond)->UseRealTime();

// GPU time from timestamps; 64 flops per element per loop iteration.
void BM_FmaThroughputGpu(benchmark::State& state) {
  const std::uint32_t elements = 1 << 16;
  const int iterations = 256;
  FmaChain job(elements, iterations);
  auto queries = device().createQuerySet({"fma", 2});
  auto run = [&](const QuerySet* timed) {
    auto encoder = device().createCommandEncoder();
    {
      auto pass = encoder.beginComputePass({"fma", {timed, 0, 1}});
      job.record(pass);
    }
    device().queue().submit(encoder.finish());
    device().queue().waitIdle();
  };
  run(nullptr);  // JIT at the first dispatch
  double gpuSeconds = 0;
  for (auto _ : state) {
    run(&queries);
    auto ns = queries.readTimestampsNs(0, 2);
    state.SetIterationTime((ns[1] - ns[0]) * 1e-9);
    gpuSeconds += (ns[1] - ns[0]) * 1e-9;
  }
  state.counters["GFLOP/s"] = 64.0 * elements * iterations * double(state.iterations()) * 1e-9 / gpuSeconds;
}
BENCHMARK(BM_FmaThroughputGpu)->UseManualTime()->Unit(benchmark::kMillisecond);

// The same chains in C++ on every core: the machine's native reference.
void BM_FmaThroughputNative(benchmark::State& state) {
  const std::size_t elements = 1 << 14;
  const int iterations = 1024;
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<float> values(elements * 4, 0.5f);
  for (auto _ : state) {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) {
      pool.emplace_back([&, t] {
        for (std::size_t i = t * 4 * (elements / threads); i < (t + 1) * 4 * (elements / threads); i += 16) {
          float a[16], b[16];
          for (int l = 0; l < 16; ++l) a[l] = values[i + l], b[l] = a[l] * 0.5f + 0.25f;
          for (int k = 0; k < iterations; ++k)
            for (int l = 0; l < 16; ++l) a[l] = a[l] * b[l] + 0.001f, b[l] = b[l] * a[l] - 0.001f;
          for (int l = 0; l < 16; ++l) values[i + l] = a[l] + b[l];
        }
      });
    }
    for (auto& th : pool) th.join();
    benchmark::DoNotOptimize(values.data());
  }
  state.counters["GFLOP/s"] =
      benchmark::Counter(16.0 * elements * iterations * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_FmaThroughputNative)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
