#include "engine/image/catcher_composite.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace facet {
namespace {

// What the camera sees behind the pixel's uncovered share: the model's
// render itself where the model covers none of it, else the mean of its
// uncovered 3 x 3 neighbours (the environment is smooth at a pixel's scale,
// as docs/preview.md assumes for --alpha); none where it has none.
std::optional<glm::vec3> background(int width, int height, const std::vector<glm::vec4>& model, int x, int y) {
  const glm::vec4& own = model[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  if (own.a <= 0.0f) return glm::vec3(own);
  glm::vec3 sum(0.0f);
  int count = 0;
  for (int j = std::max(y - 1, 0); j <= std::min(y + 1, height - 1); ++j)
    for (int i = std::max(x - 1, 0); i <= std::min(x + 1, width - 1); ++i) {
      const glm::vec4& p = model[std::size_t(j) * std::size_t(width) + std::size_t(i)];
      if (p.a > 0.0f) continue;
      sum += glm::vec3(p);
      ++count;
    }
  if (count == 0) return std::nullopt;
  return sum / float(count);
}

}  // namespace

std::vector<glm::vec4> catchShadows(int width, int height, const std::vector<glm::vec4>& model,
                                    const std::vector<glm::vec4>& holdout, const std::vector<glm::vec4>& ground) {
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (width < 0 || height < 0 || model.size() != pixels || holdout.size() != pixels || ground.size() != pixels)
    throw std::invalid_argument("shadow catcher: the three renders must hold the same pixels");
  std::vector<glm::vec4> out = model;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      const glm::vec4 m = model[i], a = holdout[i], b = ground[i];
      // The share of the pixel's samples that see the ground and not the
      // model: the holdout's coverage is the model's and the ground's union.
      const float share = a.a - m.a;
      if (share <= 0.0f || b.a <= 0.0f) continue;
      const std::optional<glm::vec3> e = background(width, height, model, x, y);
      if (!e) continue;
      // The ground's mean radiance over its samples, shadowed (the black
      // holdout adds nothing) and unshadowed; their ratio is the share of
      // the light that reaches the ground past the model.
      const glm::vec3 shadowed = (glm::vec3(a) - (1.0f - a.a) * *e) / share;
      const glm::vec3 open = (glm::vec3(b) - (1.0f - b.a) * *e) / b.a;
      glm::vec3 s(1.0f);
      for (int c = 0; c < 3; ++c)
        if (open[c] > kCatcherRadianceFloor) s[c] = glm::clamp(shadowed[c] / open[c], 0.0f, 1.0f);
      const glm::vec3 rgb = glm::max(glm::vec3(m) - share * *e * (glm::vec3(1.0f) - s), glm::vec3(0.0f));
      out[i] = glm::vec4(rgb, m.a);
    }
  return out;
}

}  // namespace facet
