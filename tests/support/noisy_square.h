#pragma once
// Images for the statistical parity tests: a 20x20 image whose centre 10x10
// square is covered, each channel of each covered pixel drawn from `beauty`,
// and the beauty AOV of a parity report.

#include <functional>

#include "analysis/parity.h"
#include "engine/image/image.h"

namespace facet::testing {

inline Image noisySquare(const std::function<float()>& beauty) {
  Image image(20, 20);
  for (int y = 5; y < 15; ++y)
    for (int x = 5; x < 15; ++x) {
      const std::size_t p = image.index(x, y);
      image.beauty[p] = {beauty(), beauty(), beauty(), 1.0f};
      image.depth[p] = 10.0f;
      image.shadingNormal[p] = {0.0f, 0.0f, 1.0f};
      image.patchId[p] = 0;
    }
  return image;
}

inline const analysis::AovParity& beautyOf(const analysis::ParityReport& report) { return report.aovs[2]; }

}  // namespace facet::testing
