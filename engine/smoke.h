// The compute smoke job: a SAXPY on the device, checked element by element
// against the same float arithmetic on the host.
#pragma once

#include <cstddef>

#include "engine/gpu/gpu.h"

namespace facet {

struct SmokeResult {
  std::size_t elements = 0;
  std::size_t mismatches = 0;
  double gpuMilliseconds = 0;  // from timestamps; 0 when the queue has none
};

SmokeResult runSmokeJob(gpu::Device& device, std::size_t elements = std::size_t(1) << 20);

}  // namespace facet
