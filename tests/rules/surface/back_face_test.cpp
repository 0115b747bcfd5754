// The back-face test of one-sided surfaces (rules/surface/back_face.h), in
// both precisions.
#include <gtest/gtest.h>

#include "rules/rules.h"

namespace facet {
namespace {

// is_back_face of one precision, its arguments given in double.
template <typename Vec3, typename IsBackFace>
void expectBackFaceRule(IsBackFace isBackFace) {
  const Vec3 up(0, 0, 1);
  EXPECT_FALSE(isBackFace(Vec3(0, 0, -1), up));         // met head on: the front
  EXPECT_TRUE(isBackFace(Vec3(0, 0, 1), up));           // from behind
  EXPECT_FALSE(isBackFace(Vec3(0.3, 0.2, -1e-6), up));  // grazing, from the front
  EXPECT_TRUE(isBackFace(Vec3(0.3, 0.2, 1e-6), up));
  EXPECT_FALSE(isBackFace(Vec3(1, 0, 0), up));  // in the surface's plane: kept
  // The normal's length does not matter (the GPU passes e1 x e2 or ds x dt).
  EXPECT_TRUE(isBackFace(Vec3(0, 0.5, 1), Vec3(0, 0, 1e-3)));
}

TEST(BackFace, IsWhereTheNormalFacesAlongTheRay) {
  expectBackFaceRule<rules::f64::vec3>(
      [](rules::f64::vec3 d, rules::f64::vec3 n) { return rules::f64::is_back_face(d, n); });
  expectBackFaceRule<rules::f32::vec3>(
      [](rules::f32::vec3 d, rules::f32::vec3 n) { return rules::f32::is_back_face(d, n); });
}

}  // namespace
}  // namespace facet
