// What the surface kernel reads of a scene besides its geometry, packed as
// compute/layout/raycast_layout.h lays it out: materials, lights (rebased on
// the eye) and the environment's tables (compute/raycast/shading/environment.glsl).
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

#include "engine/gpu_backend/raycast_layout.h"
#include "engine/ibl/compensation_tables.h"
#include "engine/ibl/environment_lighting.h"
#include "scenes/scene.h"

namespace facet::gpu_backend {

std::vector<gpu_layout::MaterialRecord> materialRecords(const scene::Scene& scene,
                                                        const ibl::EnvironmentLighting* environment,
                                                        const ibl::CompensationTables& compensation);

// Energy compensation's tables, one (scale, bias, 0, 0) texel per entry,
// with their size set in `frame`.
std::vector<glm::vec4> compensationTexels(const ibl::CompensationTables& compensation, gpu_layout::FrameParams& frame);

// The sheen's albedo rows (materials::sheenAlbedoRows), in float, where a
// material's sheen roughness is textured; none where no material's is.
std::vector<glm::vec4> sheenAlbedoRowTexels(const scene::Scene& scene);

std::vector<gpu_layout::LightRecord> lightRecords(const scene::Scene& scene, const glm::dvec3& origin);

// Everything the environment's lookups read, with its offsets and sizes set
// in `frame`.
struct EnvironmentData {
  std::vector<glm::vec4> texels;  // the map, RGB; filtered with environment samples: its density in w
  std::vector<Texel> sampling;    // sampled, filtered: per map texel (keep bits, density bits, alias, 0)
  std::vector<Texel> levels;      // prefiltered, filtered: (first texel, width, height, 0) per level
  std::vector<glm::vec4> tables;  // levels 1..n RGB (filtered: the density's chain in w); prefiltered: 9 SH RGB, DFG
};

EnvironmentData environmentData(const ibl::EnvironmentLighting& lighting, gpu_layout::FrameParams& frame);

// Slots per camera ray after the lights': none without an environment; one
// for what it adds without shadow rays; one per traced sample of a pair.
std::uint32_t environmentSlots(const ibl::EnvironmentLighting* lighting);

}  // namespace facet::gpu_backend
