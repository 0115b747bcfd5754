#include "engine/image/tonemap.h"

#include <glm/common.hpp>

#include <algorithm>

namespace facet {

std::optional<ToneCurve> toneCurveNamed(std::string_view name) {
  if (name == "clamp") return ToneCurve::Clamp;
  if (name == "aces") return ToneCurve::Aces;
  if (name == "pbr-neutral") return ToneCurve::PbrNeutral;
  return std::nullopt;
}

glm::dvec3 clampCurve(glm::dvec3 linear) { return glm::clamp(linear, 0.0, 1.0); }

glm::dvec3 acesCurve(glm::dvec3 linear) {
  const glm::dvec3 x = glm::max(linear, 0.0);
  return glm::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

glm::dvec3 pbrNeutralCurve(glm::dvec3 linear) {
  constexpr double kStartCompression = 0.8 - 0.04, kDesaturation = 0.15;
  glm::dvec3 color = glm::max(linear, 0.0);
  const double lowest = std::min({color.r, color.g, color.b});
  color -= lowest < 0.08 ? lowest - 6.25 * lowest * lowest : 0.04;
  const double peak = std::max({color.r, color.g, color.b});
  if (peak < kStartCompression) return color;
  const double d = 1.0 - kStartCompression;
  const double newPeak = 1.0 - d * d / (peak + d - kStartCompression);
  color *= newPeak / peak;
  const double towardsWhite = 1.0 - 1.0 / (kDesaturation * (peak - newPeak) + 1.0);
  return glm::mix(color, glm::dvec3(newPeak), towardsWhite);
}

glm::dvec3 toneMap(ToneCurve curve, glm::dvec3 linear) {
  switch (curve) {
    case ToneCurve::Clamp:
      return clampCurve(linear);
    case ToneCurve::Aces:
      return acesCurve(linear);
    case ToneCurve::PbrNeutral:
      return pbrNeutralCurve(linear);
  }
  return clampCurve(linear);
}

}  // namespace facet
