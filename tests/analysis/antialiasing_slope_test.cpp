// The camera samples' curve of `facet ibl-chart` on a case with a known
// answer: a Lambert blob under a constant environment, flat grey inside
// (exact at any spp) against a brighter background, so only the silhouette
// pixels carry error, and it falls with spp. The slope itself is measured
// on the preview (BENCHMARKS.md): this few edge pixels make it noisy.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "analysis/antialiasing_slope.h"
#include "scenes/scene_file.h"
#include "tests/support/blob_scene.h"

namespace facet::analysis {
namespace {

scene::Scene greyBlobUnderWhite() {
  materials::Material m = scene::defaultMaterial();
  m.fresnel = rules::f64::F_DIELECTRIC;
  m.eta = glm::dvec3(1.0);  // no interface: no specular lobe
  m.diffuse = glm::dvec3(0.8);
  return testing::blobUnder(
      m, std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0))), 24);
}

TEST(AntialiasingSlope, SilhouettesConvergeAndFlatShadingIsExact) {
  Renderer renderer;
  const AntialiasingCurve curve = measureAntialiasing(renderer, greyBlobUnderWhite(), {1, 4, 16, 64}, Backend::Cpu);
  EXPECT_EQ(curve.referenceSamples, 1024);
  ASSERT_EQ(curve.points.size(), 4u);
  std::printf("silhouette relative RMSE at 1, 4, 16, 64 spp: %.3g %.3g %.3g %.3g, slope %.2f\n",
              curve.points[0].silhouetteRmse, curve.points[1].silhouetteRmse, curve.points[2].silhouetteRmse,
              curve.points[3].silhouetteRmse, curve.silhouetteSlope);
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    EXPECT_LT(curve.points[i].smoothRmse, 1e-6) << curve.points[i].samplesPerPixel << " spp";
    if (i > 0) {
      EXPECT_LT(curve.points[i].silhouetteRmse, curve.points[i - 1].silhouetteRmse);
    }
  }
  EXPECT_GT(curve.points.back().silhouetteRmse, 0.0);
  EXPECT_LT(curve.silhouetteSlope, 0.0);
}

}  // namespace
}  // namespace facet::analysis
