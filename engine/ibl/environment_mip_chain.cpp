#include "engine/ibl/environment_mip_chain.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "engine/ibl/environment_lookup.h"
#include "engine/ibl/prefilter_steps.h"

namespace facet::ibl {

std::vector<MipLevel> mipChain(const scene::EnvironmentMap& map) {
  std::vector<MipLevel> chain;
  for (const LevelSize& size : sourceChainSizes(map.width, map.height)) {
    MipLevel level{size.width, size.height, {}};
    if (chain.empty()) {
      level.rgb.assign(map.rgb.begin(), map.rgb.end());
    } else {
      const MipLevel& finer = chain.back();
      level.rgb.resize(3 * std::size_t(size.width) * std::size_t(size.height));
      for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
          const glm::dvec3 mean = coarserTexel(finer.rgb.data(), finer.width, finer.height, x, y);
          for (int channel = 0; channel < 3; ++channel)
            level.rgb[3 * (std::size_t(y) * size.width + x) + channel] = mean[channel];
        }
    }
    chain.push_back(std::move(level));
  }
  return chain;
}

glm::dvec3 mipChainRadiance(const std::vector<MipLevel>& chain, const glm::dvec2& uv, double lod) {
  const int coarsest = int(chain.size()) - 1;
  const double clamped = std::clamp(lod, 0.0, double(coarsest));
  const int l0 = std::min(int(std::floor(clamped)), coarsest);
  const int l1 = std::min(l0 + 1, coarsest);
  const auto at = [&](int l) { return bilinearLookup(chain[l].rgb.data(), chain[l].width, chain[l].height, uv); };
  return glm::mix(at(l0), at(l1), clamped - l0);
}

}  // namespace facet::ibl
