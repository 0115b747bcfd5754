// A render's image: beauty and every AOV, each a plane of width x height
// pixels, row 0 at the top, channels interleaved. A pixel no ray hit has
// beauty alpha 0, depth +inf, ids 0xFFFFFFFF and zero elsewhere.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace facet {
namespace v0 {

struct Aov {
  int channels = 1;
  std::vector<float> values;  // width x height x channels
};

// Names: beauty (RGBA, linear radiance, alpha = coverage), depth, position,
// geometric_normal, shading_normal, uv, texcoord; ids: patch_id, face_id.
struct Image {
  int width = 0, height = 0;
  std::map<std::string, Aov> aovs;
  std::map<std::string, std::vector<std::uint32_t>> ids;

  // Throws Error (BadInput) for a name the image does not have.
  const Aov& aov(const std::string& name) const;
};

}  // namespace v0
#ifndef FACET_IMPLEMENTATION  // inside libfacet, facet:: is also the engine's
using namespace v0;
#endif
}  // namespace facet
