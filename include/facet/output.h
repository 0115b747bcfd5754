// Writing a render as `facet render` writes it (docs/outputs.md): the EXR
// with its layers and the header that describes the render (camera, the
// scene's names and Cryptomatte, settings and their digest), and the 8-bit
// PNG preview through the same tone curves (docs/preview.md). Each file is
// written whole or not at all, and an existing one is replaced only then.
#pragma once

#include <optional>
#include <string>

#include "facet/image.h"
#include "facet/render.h"
#include "facet/scene.h"

namespace facet {
namespace v0 {

struct ExrSettings {
  std::string layers = "all";  // as --aovs: all, beauty, or a comma-separated list of layers
  bool halfBeauty = false;     // as --half: R, G, B, A as 16-bit half floats
};

enum class ToneCurve { PbrNeutral, Aces, Clamp };

struct PngSettings {
  double exposure = 0;                          // as --exposure, in stops
  ToneCurve toneCurve = ToneCurve::PbrNeutral;  // as --tonemap
  std::optional<Vec3> background;               // as --background: linear RGB in place of the environment
  bool straightAlpha = false;                   // as --alpha: coverage, colour not premultiplied
};

// `result` as rendered from `scene` with `settings` (the arguments that
// Renderer::render took). Throws Error: BadInput for an image without a
// layer or with planes of the wrong size, or bad settings; OutputFailed for
// a path that is not a .exr (.png) file facet may write: a symlink, a
// device, a folder, or one that cannot be written.
void writeExr(const std::string& path, const RenderResult& result, const Scene& scene,
              const RenderSettings& settings = {}, const ExrSettings& exr = {});
void writePng(const std::string& path, const Image& image, const PngSettings& png = {});
// As writePng, refusing (OutputFailed) a path that `scene` was read from:
// its file, a material file, cage, texture or environment map it reads.
// writeExr and writeExrAndPng refuse those too.
void writePng(const std::string& path, const Image& image, const Scene& scene, const PngSettings& png = {});

// Both files of one render, as `facet render -o a.exr --png b.png` writes
// them: every path and setting checked first, then the two replaced
// together, or neither where either cannot be written (OutputFailed, with
// both files as they were).
void writeExrAndPng(const std::string& exrPath, const std::string& pngPath, const RenderResult& result,
                    const Scene& scene, const RenderSettings& settings = {}, const ExrSettings& exr = {},
                    const PngSettings& png = {});

}  // namespace v0

#ifndef FACET_IMPLEMENTATION
using namespace v0;
#endif

}  // namespace facet
