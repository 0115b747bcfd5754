// Comparing a crop of a render with the same pixels of the whole render:
// every plane, bit for bit.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "engine/image/pixel_rect.h"

namespace facet::testing {

// "(x, y)"; built with snprintf, since GCC 12 warns (-Wrestrict, falsely) on
// a literal + std::string chain here.
inline std::string pixelName(int x, int y) {
  char name[32];
  std::snprintf(name, sizeof name, "(%d, %d)", x, y);
  return name;
}

// The pixels of `crop` that differ from pixel (x0 + x, y0 + y) of `whole`
// in any plane, as "(x, y)" of the whole image; at most `most` of them.
inline std::vector<std::string> pixelsThatDiffer(const Image& whole, const Image& crop, const PixelRect& window,
                                                 std::size_t most = 8) {
  std::vector<std::string> differ;
  EXPECT_EQ(crop.width, window.width());
  EXPECT_EQ(crop.height, window.height());
  const auto same = [](const auto& a, const auto& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (int y = 0; y < crop.height && differ.size() < most; ++y)
    for (int x = 0; x < crop.width && differ.size() < most; ++x) {
      const std::size_t c = crop.index(x, y), w = whole.index(window.x0 + x, window.y0 + y);
      if (!same(crop.beauty[c], whole.beauty[w]) || !same(crop.depth[c], whole.depth[w]) ||
          !same(crop.position[c], whole.position[w]) || !same(crop.geometricNormal[c], whole.geometricNormal[w]) ||
          !same(crop.shadingNormal[c], whole.shadingNormal[w]) || !same(crop.patchId[c], whole.patchId[w]) ||
          !same(crop.faceId[c], whole.faceId[w]) || !same(crop.uv[c], whole.uv[w]) ||
          !same(crop.texcoord[c], whole.texcoord[w]))
        differ.push_back(pixelName(window.x0 + x, window.y0 + y));
    }
  return differ;
}

}  // namespace facet::testing
