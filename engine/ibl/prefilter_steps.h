// The pieces of the prefiltered environment's build that the CPU reference
// (prefiltered_environment.cpp) and the GPU build
// (engine/gpu_backend/prefilter_gpu.cpp) must do alike.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <vector>

#include "engine/ibl/environment_lookup.h"
#include "engine/ibl/prefiltered_environment.h"

namespace facet::ibl {

struct LevelSize {
  int width = 0;
  int height = 0;
};

// Level i >= 1 of the ladder: max(16, min(map width, firstLevelWidth) >> (i - 1)) wide, 2:1.
LevelSize prefilteredLevelSize(const scene::EnvironmentMap& map, const PrefilterSettings& settings, int level);

// The irradiance map: irradianceWidth x (irradianceWidth / 2 + 1) nodes,
// its rows from pole to pole (irradiance_node_direction).
LevelSize irradianceMapSize(const PrefilterSettings& settings);

// The 2x2-box mip chain of a map: levels while both sides halve evenly,
// down to a single row.
std::vector<LevelSize> sourceChainSizes(int width, int height);

// Texel (x, y) of the next coarser level of a mip chain: the solid-angle-
// weighted mean of the 2 x 2 texels it covers (environment_upper_row_share),
// as downsample.comp computes it.
template <class Real>
glm::dvec3 coarserTexel(const Real* finer, int finerWidth, int finerHeight, int x, int y) {
  const double upper = rules::f64::environment_upper_row_share(y, finerHeight);
  return 0.5 * (upper * (texelAt(finer, finerWidth, 2 * x, 2 * y) + texelAt(finer, finerWidth, 2 * x + 1, 2 * y)) +
                (1 - upper) *
                    (texelAt(finer, finerWidth, 2 * x, 2 * y + 1) + texelAt(finer, finerWidth, 2 * x + 1, 2 * y + 1)));
}

// Per row y, the radiance summed over the row weighted by each of the five
// azimuthal integrals of sh_column_integrals (one, sin, cos, cos^2, sin cos).
using ShRowSums = std::array<glm::dvec3, 5>;

// The SH coefficients (bands 0-2) of a piecewise-constant map from its row
// sums: each row's polar integrals, taken exactly in double, times its sums.
std::array<glm::dvec3, 9> shFromRowSums(const std::vector<ShRowSums>& rows);

}  // namespace facet::ibl
