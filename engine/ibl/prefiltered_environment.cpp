#include "engine/ibl/prefiltered_environment.h"

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <thread>

#include "engine/ibl/environment_lookup.h"
#include "rules/rules.h"
#include "engine/ibl/environment_mip_chain.h"
#include "engine/ibl/prefilter_steps.h"

namespace facet::ibl {

namespace m = rules::f64;

LevelSize prefilteredLevelSize(const scene::EnvironmentMap& map, const PrefilterSettings& settings, int level) {
  const int width = std::max(16, std::min(map.width, settings.firstLevelWidth) >> (level - 1));
  return {width, width / 2};
}

LevelSize irradianceMapSize(const PrefilterSettings& settings) {
  return {settings.irradianceWidth, settings.irradianceWidth / 2 + 1};
}

std::vector<LevelSize> sourceChainSizes(int width, int height) {
  std::vector<LevelSize> sizes{{width, height}};
  while (sizes.back().height > 1 && sizes.back().width % 2 == 0 && sizes.back().height % 2 == 0)
    sizes.push_back({sizes.back().width / 2, sizes.back().height / 2});
  return sizes;
}

std::array<glm::dvec3, 9> shFromRowSums(const std::vector<ShRowSums>& rows) {
  // The basis' normalizations, read off the shared basis itself.
  const double k0 = m::sh_basis(0, glm::dvec3(0.0));
  const double k1 = m::sh_basis(1, glm::dvec3(0, 1, 0));
  const double k2 = m::sh_basis(4, glm::dvec3(1, 1, 0));
  const double k6 = -m::sh_basis(6, glm::dvec3(0.0));
  const double k8 = m::sh_basis(8, glm::dvec3(1, 0, 0));
  const int height = int(rows.size());
  std::array<glm::dvec3, 9> sh{};
  for (int y = 0; y < height; ++y) {
    const double theta0 = m::PI * y / height, theta1 = m::PI * (y + 1) / height;
    const double c0 = std::cos(theta0), c1 = std::cos(theta1);
    const double s0 = std::sin(theta0), s1 = std::sin(theta1);
    // Integrals over cos theta in [c1, c0] (d omega = d cos theta d phi).
    const double one = c0 - c1;
    const double c = 0.5 * (c0 * c0 - c1 * c1);
    const double cc = (c0 * c0 * c0 - c1 * c1 * c1) / 3;
    const double ss = one - cc;
    const double s = 0.5 * (c0 * s0 - c1 * s1 + theta1 - theta0);
    const double cs = (s1 * s1 * s1 - s0 * s0 * s0) / 3;
    const auto& [rowOne, rowSin, rowCos, rowCos2, rowSinCos] = rows[y];
    sh[0] += k0 * one * rowOne;
    sh[1] += k1 * c * rowOne;
    sh[2] -= k1 * s * rowCos;
    sh[3] += k1 * s * rowSin;
    sh[4] += k2 * cs * rowSin;
    sh[5] -= k2 * cs * rowCos;
    sh[6] += k6 * (3 * ss * rowCos2 - one * rowOne);
    sh[7] -= k2 * ss * rowSinCos;
    sh[8] += k8 * (ss * (rowOne - rowCos2) - cc * rowOne);
  }
  return sh;
}

namespace {

// Runs rowTask(y) for every row, rows interleaved over the machine's cores.
void forEachRow(int rows, const std::function<void(int)>& rowTask) {
  const int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, std::max(1, rows));
  std::vector<std::jthread> workers;
  for (int t = 1; t < threads; ++t)
    workers.emplace_back([&, t] {
      for (int y = t; y < rows; y += threads) rowTask(y);
    });
  for (int y = 0; y < rows; y += threads) rowTask(y);
}

struct PrefilterSample {
  glm::dvec3 localNormal;
  double weight = 0;
  double lod = 0;
};

RadianceLevel prefilterLevel(const std::vector<MipLevel>& chain, LevelSize size, double alpha, int samples) {
  const MipLevel& source = chain.front();
  std::vector<PrefilterSample> lobe;
  for (int k = 0; k < samples; ++k) {
    const glm::dvec3 normal = m::prefilter_sample_normal(k, samples, alpha);
    const double weight = m::prefilter_sample_weight(alpha, normal);
    if (weight <= 0) continue;
    lobe.push_back({normal, weight,
                    m::prefilter_source_lod(alpha, normal, samples, source.width, source.height, int(chain.size()))});
  }
  RadianceLevel level{size.width, size.height, alpha, {}};
  level.rgb.resize(3 * std::size_t(size.width) * std::size_t(size.height));
  forEachRow(size.height, [&](int y) {
    for (int x = 0; x < size.width; ++x) {
      const glm::dvec3 r = m::environment_direction(glm::dvec2((x + 0.5) / size.width, (y + 0.5) / size.height));
      const m::Frame frame = m::frame_from_normal(r);
      glm::dvec3 sum(0.0);
      double weight = 0;
      for (const PrefilterSample& s : lobe) {
        const glm::dvec3 l = glm::reflect(-r, m::from_local(frame, s.localNormal));
        sum += s.weight * mipChainRadiance(chain, m::environment_uv(l), s.lod);
        weight += s.weight;
      }
      const glm::dvec3 radiance = weight > 0 ? sum / weight : glm::dvec3(0.0);
      for (int channel = 0; channel < 3; ++channel)
        level.rgb[3 * (std::size_t(y) * size.width + x) + channel] = float(radiance[channel]);
    }
  });
  return level;
}

// Per node of the irradiance map, the cosine-weighted mean radiance around
// its direction over every texel of the chain level irradiance_source_level picks.
RadianceLevel convolveIrradiance(const std::vector<MipLevel>& chain, LevelSize size) {
  const MipLevel& source = chain[m::irradiance_source_level(chain.front().width, int(chain.size()))];
  struct SourceTexel {
    glm::dvec3 direction;
    double solidAngle;
    glm::dvec3 radiance;
  };
  std::vector<SourceTexel> texels;
  for (int j = 0; j < source.height; ++j)
    for (int i = 0; i < source.width; ++i)
      texels.push_back({m::irradiance_texel_direction(i, j, source.width, source.height),
                        m::environment_texel_solid_angle(j, source.width, source.height),
                        texelAt(source.rgb.data(), source.width, i, j)});
  RadianceLevel map{size.width, size.height, 0.0, {}};
  map.rgb.resize(3 * std::size_t(size.width) * std::size_t(size.height));
  forEachRow(size.height, [&](int y) {
    for (int x = 0; x < size.width; ++x) {
      const glm::dvec3 n = m::irradiance_node_direction(x, y, size.width, size.height);
      glm::dvec3 sum(0.0);
      double weight = 0;
      for (const SourceTexel& t : texels) {
        const double w = m::irradiance_texel_weight(n, t.direction, t.solidAngle);
        sum += w * t.radiance;
        weight += w;
      }
      const glm::dvec3 mean = sum / weight;
      for (int channel = 0; channel < 3; ++channel)
        map.rgb[3 * (std::size_t(y) * size.width + x) + channel] = float(mean[channel]);
    }
  });
  return map;
}

std::array<glm::dvec3, 9> projectOnSh(const scene::EnvironmentMap& map) {
  std::vector<m::ShColumnIntegrals> columns;
  for (int x = 0; x < map.width; ++x) columns.push_back(m::sh_column_integrals(x, map.width));
  std::vector<ShRowSums> rows(map.height);
  for (int y = 0; y < map.height; ++y) {
    ShRowSums& row = rows[y];
    row.fill(glm::dvec3(0.0));
    for (int x = 0; x < map.width; ++x) {
      const glm::dvec3 radiance = map.texel(x, y);
      const m::ShColumnIntegrals& c = columns[x];
      row[0] += c.one * radiance;
      row[1] += c.sin_phi * radiance;
      row[2] += c.cos_phi * radiance;
      row[3] += c.cos2_phi * radiance;
      row[4] += c.sin_cos_phi * radiance;
    }
  }
  return shFromRowSums(rows);
}

}  // namespace

namespace {

// A size x size table over dfg_grid_nv and dfg_grid_alpha of what `entry`
// gives at (n.v, alpha), built a row per task.
DfgTable gridTable(int distribution, int geometry, int size,
                   const std::function<glm::dvec2(double nv, double alpha)>& entry) {
  DfgTable table{distribution, geometry, size, std::vector<float>(2 * std::size_t(size) * std::size_t(size))};
  forEachRow(size, [&](int j) {
    const double alpha = m::dfg_grid_alpha(j, size);
    for (int i = 0; i < size; ++i) {
      const glm::dvec2 value = entry(m::dfg_grid_nv(i, size), alpha);
      table.scaleBias[2 * (std::size_t(j) * size + i)] = float(value.x);
      table.scaleBias[2 * (std::size_t(j) * size + i) + 1] = float(value.y);
    }
  });
  return table;
}

}  // namespace

DfgTable dfgTable(int distribution, int geometry, const PrefilterSettings& settings) {
  return gridTable(distribution, geometry, settings.dfgSize, [&](double nv, double alpha) {
    return m::dfg_integrals(distribution, geometry, nv, alpha, settings.dfgSamples);
  });
}

DfgTable glassAlbedoTable(double eta, bool thinWalled, const PrefilterSettings& settings) {
  return gridTable(m::D_GGX, m::G_SMITH_GGX_CORRELATED, settings.dfgSize, [&](double nv, double alpha) {
    return m::glass_albedo_entry(nv, alpha, eta, thinWalled, settings.dfgSamples);
  });
}

int modelPairIndex(ModelPairs& pairs, const materials::Material& material) {
  const std::pair<int, int> pair{material.distribution, material.geometry};
  const auto found = std::find(pairs.begin(), pairs.end(), pair);
  if (found != pairs.end()) return int(found - pairs.begin());
  pairs.push_back(pair);
  return int(pairs.size()) - 1;
}

PrefilteredEnvironment prefilterOnCpu(const scene::EnvironmentMap& map, const ModelPairs& models,
                                      const PrefilterSettings& settings) {
  PrefilteredEnvironment env;
  env.levels.push_back({map.width, map.height, 0.0, map.rgb});
  const std::vector<MipLevel> chain = mipChain(map);
  for (int i = 1; i < settings.levels; ++i)
    env.levels.push_back(prefilterLevel(chain, prefilteredLevelSize(map, settings, i),
                                        m::prefiltered_level_alpha(i, settings.levels), settings.samples));
  env.irradianceSh = projectOnSh(map);
  env.irradianceMap = convolveIrradiance(chain, irradianceMapSize(settings));
  env.irradianceFromMap = usesIrradianceMap(env.irradianceSh, env.irradianceMap);
  for (const auto& [distribution, geometry] : models) env.dfg.push_back(dfgTable(distribution, geometry, settings));
  return env;
}

glm::dvec3 prefilteredRadiance(const PrefilteredEnvironment& env, const glm::dvec3& direction, double alpha) {
  if (env.levels.empty()) return glm::dvec3(0.0);
  const int last = int(env.levels.size()) - 1;
  const double level = m::prefiltered_level(alpha, last + 1);
  const int l0 = std::min(int(std::floor(level)), last);
  const int l1 = std::min(l0 + 1, last);
  const glm::dvec2 uv = m::environment_uv(direction);
  const auto at = [&](int l) {
    const RadianceLevel& r = env.levels[l];
    return bilinearLookup(r.rgb.data(), r.width, r.height, uv);
  };
  return glm::mix(at(l0), at(l1), level - l0);
}

namespace {

// dfg_grid_position's bilinear interpolation over entry(i, j) of a size x size grid.
glm::dvec2 dfgBilinear(int size, double nv, double alpha, const std::function<glm::dvec2(int, int)>& entry) {
  const glm::dvec2 position = m::dfg_grid_position(nv, alpha, size);
  const double i = position.x, j = position.y;
  const int i0 = int(std::floor(i)), j0 = int(std::floor(j));
  const int i1 = std::min(i0 + 1, size - 1), j1 = std::min(j0 + 1, size - 1);
  return glm::mix(glm::mix(entry(i0, j0), entry(i1, j0), i - i0), glm::mix(entry(i0, j1), entry(i1, j1), i - i0),
                  j - j0);
}

}  // namespace

glm::dvec2 dfgLookup(const DfgTable& table, double nv, double alpha) {
  return dfgBilinear(table.size, nv, alpha, [&](int i, int j) {
    const std::size_t index = 2 * (std::size_t(j) * table.size + i);
    return glm::dvec2(table.scaleBias[index], table.scaleBias[index + 1]);
  });
}

glm::dvec2 dfgLookupOnDemand(int distribution, int geometry, double nv, double alpha,
                             const PrefilterSettings& settings) {
  const int size = settings.dfgSize;
  return dfgBilinear(size, nv, alpha, [&](int i, int j) {
    return m::dfg_integrals(distribution, geometry, m::dfg_grid_nv(i, size), m::dfg_grid_alpha(j, size),
                            settings.dfgSamples);
  });
}

glm::dvec3 energyCompensationOnDemand(const m::BrdfParams& params, double nv, const PrefilterSettings& settings) {
  return m::specular_compensation(
      params, dfgLookupOnDemand(params.d_model, params.g_model, nv, m::isotropic_equivalent_alpha(params), settings));
}

namespace {

glm::dvec3 shIrradianceOverPi(const std::array<glm::dvec3, 9>& sh, const glm::dvec3& n) {
  glm::dvec3 sum(0.0);
  for (int i = 0; i < 9; ++i) sum += sh[i] * (m::sh_cosine_band(i) * m::sh_basis(i, n));
  return glm::max(sum, glm::dvec3(0.0));
}

}  // namespace

glm::dvec3 irradianceOverPi(const PrefilteredEnvironment& env, const glm::dvec3& n) {
  if (!env.irradianceFromMap) return shIrradianceOverPi(env.irradianceSh, n);
  const RadianceLevel& map = env.irradianceMap;
  const m::IrradianceTaps t = m::irradiance_map_taps(m::environment_uv(n), map.width, map.height);
  const auto at = [&](int texel) { return texelAt(map.rgb.data(), map.width, texel % map.width, texel / map.width); };
  return glm::mix(glm::mix(at(t.t00), at(t.t10), t.fx), glm::mix(at(t.t01), at(t.t11), t.fx), t.fy);
}

double shIrradianceError(const std::array<glm::dvec3, 9>& sh, const RadianceLevel& irradianceMap) {
  double difference = 0, total = 0;
  for (int y = 0; y < irradianceMap.height; ++y) {
    const double solidAngle = m::irradiance_node_solid_angle(y, irradianceMap.width, irradianceMap.height);
    for (int x = 0; x < irradianceMap.width; ++x) {
      const glm::dvec3 n = m::irradiance_node_direction(x, y, irradianceMap.width, irradianceMap.height);
      const glm::dvec3 convolved = texelAt(irradianceMap.rgb.data(), irradianceMap.width, x, y);
      const glm::dvec3 error = shIrradianceOverPi(sh, n) - convolved;
      difference += solidAngle * glm::dot(error, error);
      total += solidAngle * glm::dot(convolved, convolved);
    }
  }
  return total > 0 ? std::sqrt(difference / total) : 0.0;
}

bool usesIrradianceMap(const std::array<glm::dvec3, 9>& sh, const RadianceLevel& irradianceMap) {
  return shIrradianceError(sh, irradianceMap) > 0.01;
}

std::vector<glm::vec4> irradianceTable(const PrefilteredEnvironment& env) {
  const RadianceLevel& map = env.irradianceMap;
  std::vector<glm::vec4> table{{float(env.irradianceFromMap ? m::IRRADIANCE_FROM_MAP : m::IRRADIANCE_FROM_SH),
                                float(map.width), float(map.height), 0.0f}};
  for (const glm::dvec3& c : env.irradianceSh) table.emplace_back(float(c.r), float(c.g), float(c.b), 0.0f);
  for (std::size_t i = 0; i + 2 < map.rgb.size(); i += 3)
    table.emplace_back(map.rgb[i], map.rgb[i + 1], map.rgb[i + 2], 0.0f);
  return table;
}

}  // namespace facet::ibl
