// Objects given in code, validated as a scene file's are.
#pragma once

#include <string>

#include "facet/scene.h"
#include "scenes/scene.h"

namespace facet::api {

// `object` as the scene's object number `index`, its material counting in
// `materialCount`; errors name objects[index] and the field.
scene::Object engineObject(const v0::Object& object, int index, int materialCount);

// `x` in [lo, hi] and finite, or an InputError naming `field` and the rule.
double checkedRange(double x, double lo, double hi, const std::string& field);

}  // namespace facet::api
