#include <chrono>
#include <cmath>

#include "facet_kernels/spirv.h"
#include "tests/support/gpu_device.h"

namespace facet::gpu::testing {
namespace {

class Timestamps : public GpuTest {
 protected:
  // GPU time of a busy-loop dispatch, and the host's wall time around it: the
  // fastest of three runs, since another process can only ever add time.
  std::pair<double, double> timeBusyLoop(int iterations) {
    auto pipeline = derivedPipeline("busy", facet::spirv::fma_chain, {{"kIterations", double(iterations)}});
    auto layout = pipeline.getBindGroupLayout(0);
    Buffer values = upload(std::vector<float>(4 * 4096, 0.5f));
    auto group = device_.createBindGroup({"busy", &layout, {{0, &values}}});
    auto queries = device_.createQuerySet({"busy", 2});
    auto run = [&](const QuerySet* timed) {
      auto encoder = device_.createCommandEncoder();
      {
        auto pass = encoder.beginComputePass({"busy", {timed, 0, 1}});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.dispatchWorkgroups(4096 / 64);
      }
      device_.queue().submit(encoder.finish());
      device_.queue().waitIdle();
    };
    run(nullptr);  // lavapipe compiles the shader at its first dispatch
    std::pair<double, double> fastest{INFINITY, INFINITY};
    for (int repeat = 0; repeat < 3; ++repeat) {
      auto start = std::chrono::steady_clock::now();
      run(&queries);
      double hostNs = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
      auto ns = queries.readTimestampsNs(0, 2);
      if (ns[1] - ns[0] < fastest.first) fastest = {ns[1] - ns[0], hostNs};
    }
    return fastest;
  }
};

TEST_F(Timestamps, PassDurationsArePositiveAndPlausible) {
  ASSERT_GT(device_.limits().timestampPeriodNs, 0.0) << "this adapter's queue cannot write timestamps";
  // Only bounds that load cannot break: how much longer a longer loop takes
  // is a measurement, which belongs to benchmarks/.
  for (int iterations : {256, 4096}) {
    auto [gpu, host] = timeBusyLoop(iterations);
    EXPECT_GT(gpu, 0.0) << iterations << " iterations";
    // The device cannot take longer than the host waited for it.
    EXPECT_LE(gpu, host) << iterations << " iterations";
  }
}

TEST_F(Timestamps, ReadingUnwrittenQueriesIsAnError) {
  auto queries = device_.createQuerySet({"unused", 2});
  try {
    queries.readTimestampsNs(0, 2);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("never written"));
  }
}

}  // namespace
}  // namespace facet::gpu::testing
