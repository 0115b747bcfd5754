// The device check `facet info` runs (engine/smoke.h): a kernel against the
// host, element by element.
#include "engine/smoke.h"
#include "tests/support/gpu_device.h"

namespace facet::gpu::testing {
namespace {

TEST_F(GpuTest, SmokeJobFindsNoMismatch) {
  SmokeResult result = runSmokeJob(device_, 12345);
  EXPECT_EQ(result.elements, 12345u);
  EXPECT_EQ(result.mismatches, 0u);
}

}  // namespace
}  // namespace facet::gpu::testing
