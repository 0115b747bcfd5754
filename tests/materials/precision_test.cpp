// Outside the course's domain: alpha = 0, directions under the horizon,
// l = v, l = -v, grazing. Never NaN or Inf, in float or double; the float
// error stays bounded where the model is well conditioned.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "materials/material.h"
#include "materials/models.h"
#include "materials/precision.h"
#include "rules/rules.h"

namespace facet::materials {
namespace {

TEST(Stability, SweepIsFiniteAndFloatIsAccurateWhereWellConditioned) {
  PrecisionReport report = precisionSweep();
  std::printf("%s", toMarkdown(report).c_str());
  EXPECT_GT(report.evaluations, 1'000'000);
  EXPECT_EQ(report.nonfinite_float, 0);
  EXPECT_EQ(report.nonfinite_double, 0);
  // Under the horizon both precisions give exactly 0.
  for (const auto& row : report.by_alpha_and_cos) EXPECT_EQ(row.front().max_relative_error, 0.0);
  // alpha >= 0.01 and min(n.l, n.v) >= 0.01: float within 2e-3 relative for
  // every part. h = (l + v) / |l + v| carries an angular error of about
  // eps / |l + v|, and D's logarithm moves by 4/alpha per radian: at
  // grazing l and v on opposite sides |l + v| falls to n.l + n.v = 0.02,
  // so 4 eps / (alpha |l + v|) reaches 1.2e-3 (docs/shading.md, section 4
  // and the table of section 8).
  for (const PrecisionReport::Part& part : report.by_part)
    EXPECT_LT(part.benign.max_relative_error, 2e-3) << part.kind << " " << part.name << ": " << part.benign.worst_case;
}

TEST(Stability, SamplersAreFiniteAtTheEdgesOfTheUnitSquare) {
  // u at 0, 1 and just inside; alpha = 0; v normal, grazing and under the
  // horizon: directions and pdfs stay finite in float and double.
  const float kEdges[] = {0.0f, 1e-7f, 0.5f, 1 - 6e-8f, 1.0f};
  const float kThetaV[] = {0.0f, 1.0f, 1.5707f, 1.5708f, 2.0f, 3.1415926f};
  for (int technique : {rules::f64::SAMPLE_COSINE, rules::f64::SAMPLE_D, rules::f64::SAMPLE_GGX_VISIBLE})
    for (const ModelName& d : kDistributions)
      for (float alpha : {0.0f, 1e-3f, 0.5f, 1.0f})
        for (float theta : kThetaV)
          for (float u1 : kEdges)
            for (float u2 : kEdges) {
              Material material;
              material.distribution = d.id;
              material.geometry = rules::f64::G_SMITH_GGX;
              material.fresnel = rules::f64::F_NONE;
              material.alpha = alpha;
              material.f0 = material.eta = material.k = material.diffuse = glm::dvec3(0);
              const rules::f32::BrdfParams p32 = toParams32(material);
              glm::vec3 n(0, 0, 1), v(std::sin(theta), 0, std::cos(theta));
              glm::vec3 l = rules::f32::sample_direction(technique, p32, n, v, {u1, u2});
              float pdf = rules::f32::direction_pdf(technique, p32, n, l, v);
              EXPECT_TRUE(std::isfinite(l.x) && std::isfinite(l.y) && std::isfinite(l.z) && std::isfinite(pdf))
                  << "technique " << technique << " d=" << d.name << " alpha=" << alpha << " theta_v=" << theta
                  << " u=" << u1 << "," << u2;

              const rules::f64::BrdfParams p64 = toParams64(material);
              glm::dvec3 l64 =
                  rules::f64::sample_direction(technique, p64, glm::dvec3(n), glm::dvec3(v), {double(u1), double(u2)});
              double pdf64 = rules::f64::direction_pdf(technique, p64, glm::dvec3(n), l64, glm::dvec3(v));
              EXPECT_TRUE(std::isfinite(l64.x) && std::isfinite(l64.y) && std::isfinite(l64.z) && std::isfinite(pdf64));
            }
}

}  // namespace
}  // namespace facet::materials
