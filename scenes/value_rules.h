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

// The largest radiance (per channel) a light, an emission or an environment
// may have: the renderers sum and filter light in float on the GPU, and a
// sum of such values stays finite (docs/reliability.md, "Limits").
inline constexpr double kMaxRadiance = 1e30;

// A light's or an environment's colour: "must not be negative", or "must be
// at most 1e30 per channel, is x" (NaN included); nothing when it is fine.
std::optional<std::string> radianceRule(const glm::dvec3& color);

// Shortest decimal text of `x`: no trailing zeros, "inf" and "-inf".
std::string formatNumber(double x);

}  // namespace facet::scene
