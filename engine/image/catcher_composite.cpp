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
                                    const std::vector<glm::vec4>& holdout, const std::vector<glm::vec4>& ground,
                                    int radius) {
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (width < 0 || height < 0 || radius < 0 || model.size() != pixels || holdout.size() != pixels ||
      ground.size() != pixels)
    throw std::invalid_argument("shadow catcher: the three renders must hold the same pixels");
  // Per pixel: the share of its samples that see the ground and not the
  // model (the holdout's coverage is the model's and the ground's union),
  // what is behind it, and the ground's radiance summed over that share,
  // shadowed (the black holdout adds nothing) and unshadowed.
  std::vector<float> share(pixels, 0.0f);
  std::vector<glm::vec3> behind(pixels), shadowed(pixels), open(pixels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      const glm::vec4 m = model[i], a = holdout[i], b = ground[i];
      if (a.a - m.a <= 0.0f || b.a <= 0.0f) continue;
      const std::optional<glm::vec3> e = background(width, height, model, x, y);
      if (!e) continue;
      share[i] = a.a - m.a;
      behind[i] = *e;
      shadowed[i] = glm::vec3(a) - (1.0f - a.a) * *e;
      open[i] = (glm::vec3(b) - (1.0f - b.a) * *e) * (share[i] / b.a);
    }
  std::vector<glm::vec4> out = model;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      if (share[i] <= 0.0f) continue;
      // The ratio of the sums over the window's ground pixels: the share of
      // the light that reaches the ground past the model.
      glm::vec3 numerator(0.0f), denominator(0.0f);
      float weight = 0.0f;
      for (int j = std::max(y - radius, 0); j <= std::min(y + radius, height - 1); ++j)
        for (int k = std::max(x - radius, 0); k <= std::min(x + radius, width - 1); ++k) {
          const std::size_t n = std::size_t(j) * std::size_t(width) + std::size_t(k);
          numerator += shadowed[n];
          denominator += open[n];
          weight += share[n];
        }
      glm::vec3 s(1.0f);
      for (int c = 0; c < 3; ++c)
        if (denominator[c] > kCatcherRadianceFloor * weight)
          s[c] = glm::clamp(numerator[c] / denominator[c], 0.0f, 1.0f);
      const glm::vec3 rgb =
          glm::max(glm::vec3(model[i]) - share[i] * behind[i] * (glm::vec3(1.0f) - s), glm::vec3(0.0f));
      out[i] = glm::vec4(rgb, model[i].a);
    }
  return out;
}

}  // namespace facet
