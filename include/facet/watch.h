// Watching a scene file as `facet render --watch` does (README.md,
// "Watching a scene"): a picture refined pass by pass, then a new one each
// time a file the scene reads changes (the scene, material files, cages,
// glTF files, images, environment maps), on one Renderer, which keeps the
// device, the compiled kernels and the diced geometry while it is the same.
#pragma once

#include <string>

#include "facet/image.h"
#include "facet/render.h"

namespace facet {
namespace v0 {

struct WatchSettings {
  RenderSettings render;  // over each load of the scene, as Renderer::render applies them
  int passes = 16;        // of each picture, in [1, 4096], each adding its samples (at least 4 after the first)
  int changes = 0;        // changes handled before watch returns, in [0, 1000000]; 0: until onPass stops it
  std::string variant;    // a glTF file's material variant, as loadScene(path, variant); "" its default
};

// A picture after one of its passes.
struct WatchPass {
  int picture = 0;  // 0: the first; then one more for each change that rendered
  int passes = 0;   // in the image
  int spp = 0;
  Image image;
};

}  // namespace v0
#ifndef FACET_IMPLEMENTATION
using namespace v0;
#endif
}  // namespace facet
