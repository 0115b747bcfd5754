// The split sum's precomputed half (docs/rendering.md, "Image-based
// lighting"): an environment prefiltered by GGX at a ladder of roughnesses,
// its irradiance as spherical harmonics and as a cosine-convolved map, and
// the DFG tables of the BRDF models a scene uses. Built in double on the CPU (the reference) or by
// compute kernels on the GPU (engine/gpu_backend/prefilter_gpu.h), both into
// this struct; kept in a disk cache keyed by the map and the settings.
//
// Everything here lives in the map's own frame: rotation and intensity are
// applied by whoever looks it up, so they never invalidate the cache.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "materials/material.h"
#include "rules/rules.h"
#include "scenes/environment_map.h"

namespace facet::ibl {

struct PrefilterSettings {
  int levels = 6;             // level i: alpha = (i / (levels - 1))^2; level 0 is the map itself
  int firstLevelWidth = 256;  // level 1's width (at most the map's); each further level halves, down to 16
  int samples = 256;          // GGX samples per prefiltered texel
  int dfgSize = 64;           // DFG table: dfgSize x dfgSize over (n.v, sqrt(alpha))
  int dfgSamples = 4096;      // samples per DFG entry
  int irradianceWidth = 64;   // the irradiance map: irradianceWidth x (irradianceWidth / 2 + 1) nodes (even)
};

struct RadianceLevel {
  int width = 0;
  int height = 0;
  double alpha = 0;        // the GGX roughness this level was filtered at
  std::vector<float> rgb;  // row-major, 3 floats per texel, the map's layout
};

// For one (D, G) pair: entry (i, j) at n.v = (i + 1) / size and
// sqrt(alpha) = j / (size - 1) (dfg_grid_nv, dfg_grid_alpha in
// rules/shading/dfg.h) holds (scale, bias), so that for Schlick's
// F the directional albedo of the specular lobe is F(0) scale + bias.
struct DfgTable {
  int distribution = 0;
  int geometry = 0;
  int size = 0;
  std::vector<float> scaleBias;  // 2 floats per entry, index 2 (j size + i)
};

struct PrefilteredEnvironment {
  std::vector<RadianceLevel> levels;
  std::array<glm::dvec3, 9> irradianceSh{};  // radiance projected on SH bands 0-2
  RadianceLevel irradianceMap;               // E / pi at irradiance_node_direction (alpha unused)
  bool irradianceFromMap = false;            // the rule's choice (usesIrradianceMap)
  std::vector<DfgTable> dfg;                 // one per requested (D, G) pair, in request order
};

using ModelPairs = std::vector<std::pair<int, int>>;  // (distribution, geometry) ids of rules/shading/microfacet.h

// The index of `material`'s (D, G) pair in `pairs`, appended if new.
int modelPairIndex(ModelPairs& pairs, const materials::Material& material);

PrefilteredEnvironment prefilterOnCpu(const scene::EnvironmentMap& map, const ModelPairs& models,
                                      const PrefilterSettings& settings = {});

// Lookups, in double, with the same bilinear/level interpolation the GPU
// kernels use. `direction` is in the map's frame.
glm::dvec3 prefilteredRadiance(const PrefilteredEnvironment& env, const glm::dvec3& direction, double alpha);
glm::dvec2 dfgLookup(const DfgTable& table, double nv, double alpha);
// The (D, G) pair's table at settings.dfgSize^2 entries of settings.dfgSamples
// samples each, built in double and stored in float.
DfgTable dfgTable(int distribution, int geometry, const PrefilterSettings& settings = {});
// The glass albedo table of a clear interface of `eta` (glass_albedo_entry in
// rules/shading/dfg.h) over the same grid, E in the scale and 0 in the bias,
// for GGX with the correlated Smith G, the only pair a transmissive material
// takes.
DfgTable glassAlbedoTable(double eta, bool thinWalled, const PrefilterSettings& settings = {});
// What dfgLookup returns from the (D, G) table `settings` would build,
// computing only the four entries it reads, in double (the tables store
// float), for one-off queries.
glm::dvec2 dfgLookupOnDemand(int distribution, int geometry, double nv, double alpha,
                             const PrefilterSettings& settings = {});
// The multiple-scattering factor on the specular lobe at n.v = nv
// (energy_compensation in rules/shading/dfg.h), from that table for the
// material's D and G; with compensationTableSettings()
// (engine/ibl/compensation_tables.h), the factor the renderers apply.
glm::dvec3 energyCompensationOnDemand(const rules::f64::BrdfParams& params, double nv,
                                      const PrefilterSettings& settings = {});
// Irradiance / pi at normal n (c_diff times this is the Lambertian
// radiance): from the irradiance map where the rule chose it, else from the
// SH coefficients, clamped at 0 (bands 0-2 ring below 0 around very bright
// sources).
glm::dvec3 irradianceOverPi(const PrefilteredEnvironment& env, const glm::dvec3& n);
// The SH irradiance's relative RMS difference from the irradiance map over
// the sphere (solid-angle weighted, all channels): how far bands 0-2 miss it.
double shIrradianceError(const std::array<glm::dvec3, 9>& sh, const RadianceLevel& irradianceMap);
// The rule: the map where the SH misses it by more than 1%, else the SH
// (exact for maps of bands 0-2 alone, with no interpolation between texels).
bool usesIrradianceMap(const std::array<glm::dvec3, 9>& sh, const RadianceLevel& irradianceMap);
// The irradiance table the GPU reads (layout in rules/environment/irradiance_map.h).
std::vector<glm::vec4> irradianceTable(const PrefilteredEnvironment& env);

// The cache: returns the stored result for (map, models, settings, builder)
// when present and intact, else runs `build` and stores its result (written
// to a temporary file and renamed). The directory is FACET_CACHE_DIR, else
// $XDG_CACHE_HOME/facet, else ~/.cache/facet; an unwritable directory only
// costs the rebuild.
PrefilteredEnvironment cachedPrefilter(const scene::EnvironmentMap& map, const ModelPairs& models,
                                       const PrefilterSettings& settings, const std::string& builder,
                                       const std::function<PrefilteredEnvironment()>& build);
// cachedPrefilter behind the last result this process got, kept in memory:
// the rounds, frames and cells of one scene read the file once.
PrefilteredEnvironment rememberedPrefilter(const scene::EnvironmentMap& map, const ModelPairs& models,
                                           const PrefilterSettings& settings, const std::string& builder,
                                           const std::function<PrefilteredEnvironment()>& build);
// dfgTable through the same cache, keyed by the pair and the table's settings.
DfgTable cachedDfgTable(int distribution, int geometry, const PrefilterSettings& settings = {});
// glassAlbedoTable through the same cache, keyed by eta, the wall and the settings.
DfgTable cachedGlassAlbedoTable(double eta, bool thinWalled, const PrefilterSettings& settings = {});

}  // namespace facet::ibl
