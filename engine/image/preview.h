// The 8-bit PNG preview of a linear beauty (docs/preview.md).
//
// Both renderers store a pixel's beauty as the mean radiance of its shaded
// samples with A their coverage, so RGB = A C + (1 - A) E, where C is the
// surfaces' colour and E what the missed samples saw: the environment, or
// black without one. The preview is opaque by default and shows RGB as
// rendered; a background colour replaces E, and straight alpha writes C.
// E at a pixel the surface partly covers is estimated by its fully missed
// neighbours (3 x 3), 0 where there are none.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/image/tonemap.h"

namespace facet {

// The rules of a preview's options, for the command line and the APIs alike.
// 2^64 times the largest radiance a render keeps (1e30) is still a float.
inline constexpr const char* kExposureRule = "expected a finite number of stops in [-64, 64]";
inline constexpr const char* kBackgroundRule = "expected three finite, non-negative linear values R,G,B";
inline bool validExposure(double stops) { return stops >= -64.0 && stops <= 64.0; }
inline bool validBackground(const glm::dvec3& c) {
  return std::isfinite(c.r + c.g + c.b) && c.r >= 0 && c.g >= 0 && c.b >= 0;
}

struct PreviewOptions {
  float exposure = 0.0f;  // stops: the radiance is scaled by 2^exposure before the tone curve
  ToneCurve curve = ToneCurve::PbrNeutral;
  std::optional<glm::vec3> background;  // linear RGB behind the surfaces; none: as rendered
  bool straightAlpha = false;           // RGBA, colour not premultiplied; else opaque
};

// Encodes the rows of a width-wide beauty, top first, into 8-bit RGBA
// (A = 255 unless straight alpha), sRGB-encoded after the tone curve. A row
// is encoded once the row below it has arrived, or at finish().
class PreviewEncoder {
 public:
  PreviewEncoder(int width, const PreviewOptions& options, std::uint8_t* rgba);
  void push(const glm::vec4* row);
  void finish();

 private:
  void encode(int row);  // the middle of rows_, whose neighbours are rows_[0] and rows_[2]

  int width_;
  PreviewOptions options_;
  std::uint8_t* rgba_;
  std::array<std::vector<glm::vec4>, 3> rows_;  // rows y - 1, y, y + 1 of the next row to encode, y
  int pushed_ = 0;
};

// The whole beauty at once.
std::vector<std::uint8_t> previewPixels(const std::vector<glm::vec4>& beauty, int width, int height,
                                        const PreviewOptions& options);

}  // namespace facet
