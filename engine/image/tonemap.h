// Tone curves of the PNG preview: display-referred RGB in [0, 1] from
// scene-linear RGB (Rec.709 primaries), before the sRGB encoding
// (docs/preview.md compares them).
#pragma once

#include <glm/vec3.hpp>

#include <optional>
#include <string_view>

namespace facet {

enum class ToneCurve { Clamp, Aces, PbrNeutral };

// The curve as --tonemap spells it, nothing for any other name;
// kToneCurveNames lists the spellings for error messages.
std::optional<ToneCurve> toneCurveNamed(std::string_view name);
inline constexpr const char* kToneCurveNames = "clamp, aces, pbr-neutral";

// Each channel clipped to [0, 1].
glm::dvec3 clampCurve(glm::dvec3 linear);

// Narkowicz's fit of the ACES RRT + ODT, per channel
// (K. Narkowicz, "ACES Filmic Tone Mapping Curve", 2015).
glm::dvec3 acesCurve(glm::dvec3 linear);

// Khronos PBR Neutral: an offset toe, identity up to the compression start,
// then a hue-preserving shoulder desaturating towards white
// (Khronos PBR Neutral Tone Mapper specification, 2024).
glm::dvec3 pbrNeutralCurve(glm::dvec3 linear);

glm::dvec3 toneMap(ToneCurve curve, glm::dvec3 linear);

}  // namespace facet
