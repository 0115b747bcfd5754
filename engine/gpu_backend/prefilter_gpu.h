// The prefiltered environment (engine/ibl/prefiltered_environment.h) built by
// the compute kernels of compute/ibl/ — the same math as the CPU reference,
// in float — and read back into the same struct.
#pragma once

#include "engine/gpu/gpu.h"
#include "engine/ibl/prefiltered_environment.h"
#include "scenes/environment_map.h"

namespace facet::gpu_backend {

// Kernels: downsample (the map's 2x2-box mip chain), prefilter (one level
// each), sh_project (per-row sums, added up in double on the host),
// irradiance (the cosine-convolved map; the rule runs on the host) and dfg
// (one table per pair, a pipeline variant per pair). A map whose mip chain
// exceeds one storage binding is box-halved on the host first (see the .cpp).
ibl::PrefilteredEnvironment prefilterOnGpu(gpu::Device& device, const scene::EnvironmentMap& map,
                                           const ibl::ModelPairs& models, const ibl::PrefilterSettings& settings);

}  // namespace facet::gpu_backend
