// Presets against the course's two F(0) tables, retyped here from the
// slides "Normal-Incidence Fresnel for Metals / for Non-Metals".
#include <gtest/gtest.h>

#include <cmath>

#include "engine/image/color.h"
#include "materials/presets.h"

namespace facet::materials {
namespace {

struct PrintedRow {
  const char* label;
  glm::dvec3 linear;
  glm::dvec3 srgb;
};

const PrintedRow kPrinted[] = {
    {"Gold", {1.00, 0.71, 0.29}, {1.00, 0.86, 0.57}},
    {"Silver", {0.95, 0.93, 0.88}, {0.98, 0.97, 0.95}},
    {"Copper", {0.95, 0.64, 0.54}, {0.98, 0.82, 0.76}},
    {"Iron", {0.56, 0.57, 0.58}, {0.77, 0.78, 0.78}},
    {"Aluminum", {0.91, 0.92, 0.92}, {0.96, 0.96, 0.97}},
    {"Water", {0.02, 0.02, 0.02}, {0.15, 0.15, 0.15}},
    {"Plastic / Glass (Low)", {0.03, 0.03, 0.03}, {0.21, 0.21, 0.21}},
    {"Plastic High", {0.05, 0.05, 0.05}, {0.24, 0.24, 0.24}},
    {"Glass (High) / Ruby", {0.08, 0.08, 0.08}, {0.31, 0.31, 0.31}},
    {"Diamond", {0.17, 0.17, 0.17}, {0.45, 0.45, 0.45}},
};

TEST(Presets, EveryRowWithItsLinearValuesAsPrinted) {
  ASSERT_EQ(presets().size(), std::size(kPrinted));
  for (size_t i = 0; i < std::size(kPrinted); ++i) {
    const Preset& preset = presets()[i];
    EXPECT_EQ(preset.label, kPrinted[i].label);
    EXPECT_EQ(preset.f0_linear, kPrinted[i].linear) << preset.label;  // exact
    EXPECT_EQ(preset.f0_srgb, kPrinted[i].srgb) << preset.label;
    EXPECT_EQ(preset.metal, i < 5) << preset.label;
    EXPECT_EQ(findPreset(preset.name), &preset);
  }
  EXPECT_EQ(findPreset("unobtainium"), nullptr);
}

TEST(Presets, SrgbConversionReproducesThePrintedColumn) {
  // Tolerance +-0.01 on each printed sRGB value. One printed value is not
  // the sRGB encoding of its own linear value: Plastic / Glass (Low) prints
  // 0.03 -> 0.21, but 0.03 encodes to 0.1897 (0.21 would need linear 0.035 to
  // 0.038; a 2.2 power curve, which fits that row, misses Water by 0.019).
  // That row is checked against the exact encoding and reported in
  // docs/shading.md instead of bending the conversion to fit it.
  double worst = 0;
  for (size_t i = 0; i < std::size(kPrinted); ++i) {
    glm::dvec3 srgb = linearToSrgb(kPrinted[i].linear);
    for (int c = 0; c < 3; ++c) {
      double error = std::abs(srgb[c] - kPrinted[i].srgb[c]);
      if (std::string(kPrinted[i].label) == "Plastic / Glass (Low)") {
        EXPECT_NEAR(srgb[c], 0.1897, 1e-4);
        EXPECT_NEAR(error, 0.0203, 1e-4);
        continue;
      }
      EXPECT_LE(error, 0.01) << kPrinted[i].label << " channel " << c;
      worst = std::max(worst, error);
    }
  }
  std::printf("worst |sRGB(linear) - printed| over the 29 consistent values: %.4f\n", worst);
}

TEST(Presets, IorFromF0InvertsTheNormalIncidenceFresnel) {
  // Water's 0.02 gives 1.33, Diamond's 0.17 gives 2.42 (to the printed
  // precision of F0).
  EXPECT_NEAR(iorFromF0(0.02), 1.33, 0.005);
  EXPECT_NEAR(iorFromF0(0.17), 2.42, 0.02);
  for (double eta : {1.2, 1.5, 2.0}) EXPECT_NEAR(iorFromF0(std::pow((eta - 1) / (eta + 1), 2)), eta, 1e-12);
}

}  // namespace
}  // namespace facet::materials
