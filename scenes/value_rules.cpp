#include "scenes/value_rules.h"

#include <cmath>

namespace facet::scene {

std::optional<std::string> rangeRule(double x, double lo, double hi) {
  if (x >= lo && x <= hi) return std::nullopt;
  return "must be in [" + formatNumber(lo) + ", " + formatNumber(hi) + "], is " + formatNumber(x);
}

bool hasNegativeComponent(const glm::dvec3& v) { return v.x < 0 || v.y < 0 || v.z < 0; }

std::string formatNumber(double x) {
  if (std::isinf(x)) return x < 0 ? "-inf" : "inf";
  std::string s = std::to_string(x);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace facet::scene
