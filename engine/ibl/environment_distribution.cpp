#include "engine/ibl/environment_distribution.h"

#include <algorithm>

#include "rules/rules.h"

namespace facet::ibl {
namespace {

namespace m = rules::f64;

// Vose's construction: texels whose scaled probability n p is below 1 are
// topped up by one above 1, which becomes their alias; exact in expectation
// and O(n).
void buildAliasTable(const std::vector<double>& probability, EnvironmentDistribution& d) {
  const std::size_t n = probability.size();
  std::vector<double> scaled(n);
  std::vector<std::uint32_t> small, large;
  for (std::size_t i = 0; i < n; ++i) {
    scaled[i] = probability[i] * double(n);
    (scaled[i] < 1 ? small : large).push_back(std::uint32_t(i));
  }
  d.keep.assign(n, 1.0);
  d.alias.resize(n);
  for (std::size_t i = 0; i < n; ++i) d.alias[i] = std::uint32_t(i);
  while (!small.empty() && !large.empty()) {
    const std::uint32_t lo = small.back(), hi = large.back();
    small.pop_back();
    d.keep[lo] = scaled[lo];
    d.alias[lo] = hi;
    scaled[hi] -= 1 - scaled[lo];
    if (scaled[hi] < 1) {
      large.pop_back();
      small.push_back(hi);
    }
  }
  // What is left is 1 up to rounding: kept for sure.
}

}  // namespace

EnvironmentDistribution buildDistribution(const scene::EnvironmentMap& map) {
  const int w = map.width, h = map.height;
  bool black = true;
  for (float value : map.rgb) black = black && value == 0;
  // Radiance is looked up bilinearly, so inside a texel it mixes the texel
  // with its neighbours: weighing each texel by the brightest of its 3 x 3
  // neighbourhood keeps radiance / density bounded next to a bright sun,
  // where the texel's own luminance would leave the bleed to BRDF samples
  // alone (fireflies).
  std::vector<double> weight(std::size_t(w) * std::size_t(h));
  for (int y = 0; y < h; ++y) {
    const double solidAngle = m::environment_texel_solid_angle(y, w, h);
    for (int x = 0; x < w; ++x) {
      double brightest = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int ny = std::clamp(y + dy, 0, h - 1), nx = (x + dx + w) % w;
          brightest = std::max(brightest, m::luminance(glm::dvec3(map.texel(nx, ny))));
        }
      weight[std::size_t(y) * std::size_t(w) + std::size_t(x)] = solidAngle * (black ? 1.0 : brightest);
    }
  }

  double total = 0;
  for (double x : weight) total += x;
  EnvironmentDistribution d;
  d.width = w;
  d.height = h;
  d.texelPdf.resize(weight.size());
  std::vector<double> probability(weight.size());
  for (int y = 0; y < h; ++y) {
    const double solidAngle = m::environment_texel_solid_angle(y, w, h);
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
      probability[i] = weight[i] / total;
      d.texelPdf[i] = probability[i] / solidAngle;
    }
  }
  buildAliasTable(probability, d);
  return d;
}

EnvironmentSample sampleEnvironment(const EnvironmentDistribution& d, std::uint32_t texelBits, const glm::dvec3& u) {
  std::size_t texel = std::size_t((std::uint64_t(texelBits) * d.texelPdf.size()) >> 32);
  if (u.x >= d.keep[texel]) texel = d.alias[texel];
  const int x = int(texel % std::size_t(d.width)), y = int(texel / std::size_t(d.width));
  const double cosTop = m::environment_row_cos(y, d.height), cosBottom = m::environment_row_cos(y + 1, d.height);
  EnvironmentSample s;
  s.direction = m::environment_direction_cos((x + u.y) / d.width, cosTop + u.z * (cosBottom - cosTop));
  s.pdf = d.texelPdf[texel];
  return s;
}

double environmentPdf(const EnvironmentDistribution& d, const glm::dvec3& direction) {
  const glm::dvec2 uv = m::environment_uv(direction);
  const int x = std::clamp(int(uv.x * d.width), 0, d.width - 1);
  const int y = std::clamp(int(uv.y * d.height), 0, d.height - 1);
  return d.texelPdf[std::size_t(y) * std::size_t(d.width) + std::size_t(x)];
}

}  // namespace facet::ibl
