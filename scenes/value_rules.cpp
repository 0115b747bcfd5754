#include "scenes/value_rules.h"

#include <cmath>
#include <cstdio>

namespace facet::scene {

std::optional<std::string> rangeRule(double x, double lo, double hi) {
  if (x >= lo && x <= hi) return std::nullopt;
  return "must be in [" + formatNumber(lo) + ", " + formatNumber(hi) + "], is " + formatNumber(x);
}

bool hasNegativeComponent(const glm::dvec3& v) { return v.x < 0 || v.y < 0 || v.z < 0; }

std::optional<std::string> radianceRule(const glm::dvec3& color) {
  if (hasNegativeComponent(color)) return std::string(kNegativeColorRule);
  for (int c = 0; c < 3; ++c)
    if (!(color[c] <= kMaxRadiance))
      return "must be at most 1e30 per channel (light is summed in float), is " + formatNumber(color[c]);
  return std::nullopt;
}

std::string formatNumber(double x) {
  if (std::isinf(x)) return x < 0 ? "-inf" : "inf";
  if (std::abs(x) >= 1e15) {  // not hundreds of digits
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
  }
  std::string s = std::to_string(x);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace facet::scene
