#pragma once
// The ranges a scene's values must lie in, whichever format the scene is
// written in, so that a JSON scene and a glTF file are held to one rule.

#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace facet::scene {

inline constexpr double kMinFovDegrees = 1e-3;
inline constexpr double kMaxFovDegrees = 179.0;
// Half-angle: a spot light lights at most a hemisphere.
inline constexpr double kMaxSpotConeDegrees = 90.0;
inline constexpr char kNegativeColorRule[] = "must not be negative";

// "must be in [lo, hi], is x" when `x` lies outside [lo, hi] (NaN does);
// nothing when it lies inside.
std::optional<std::string> rangeRule(double x, double lo, double hi);

bool hasNegativeComponent(const glm::dvec3& v);

// Shortest decimal text of `x`: no trailing zeros, "inf" and "-inf".
std::string formatNumber(double x);

}  // namespace facet::scene
