// The shading model both backends share (docs/shading.md), evaluated in
// double precision for one material and pairs of directions.
#pragma once

#include <vector>

#include "facet/scene.h"

namespace facet {
namespace v0 {

// f(l, v) = F G D / (4 (n.l)(n.v)) + c_diff / pi, with its factors.
struct BrdfValue {
  Vec3 f, specular, diffuse, F;
  double D = 0, G = 0;
};

// In the local frame n = +z; l and v point away from the surface and need
// not be unit length. Throws Error (BadInput) for an invalid material or a
// zero direction.
BrdfValue evaluateBrdf(const Material& material, const Vec3& l, const Vec3& v);
std::vector<BrdfValue> evaluateBrdf(const Material& material, const std::vector<Vec3>& l, const std::vector<Vec3>& v);

}  // namespace v0
#ifndef FACET_IMPLEMENTATION  // inside libfacet, facet:: is also the engine's
using namespace v0;
#endif
}  // namespace facet
