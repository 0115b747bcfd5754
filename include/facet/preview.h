// The preview stage as a library call (docs/preview-stage.md): materials on
// a model, each rendered by adaptive sampling to a noise threshold over a
// ground that catches the model's shadow, laid out as a labelled contact
// sheet; a turntable's frames; and the sheet or movie written as
// `facet preview` writes them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facet/image.h"
#include "facet/output.h"
#include "facet/render.h"
#include "facet/scene.h"

namespace facet {
namespace v0 {

// What a turntable turns before the fixed camera: the model (lights and
// environment fixed), or the environment.
enum class Turn { Model, Environment };

// `facet preview`'s flags, under the same rules.
struct PreviewSettings {
  std::vector<std::string> materials;  // presets or material files (.json), one picture each
  int width = 256, height = 256;       // of each picture
  int columns = 0;                     // of the sheet; 0: a grid about as wide as tall
  bool ground = true;                  // a ground that catches the model's shadow and is otherwise unseen
  // The light: the model's own lights go; none: the studio environment.
  std::optional<Environment> environment;
  double noiseThreshold = 0.02;            // a tile's relative standard error, in (0, 1]
  int maxSpp = 256;                        // in [8, 65536]
  std::optional<double> timeLimit;         // seconds per picture, in (0, 86400]; none: no limit
  std::optional<int> turntable;            // frames of a full turn, in [2, 3600]
  Turn turn = Turn::Model;
  Backend backend = Backend::Gpu;
  double exposure = 0;  // the pictures' 8-bit encoding, as PngSettings'
  ToneCurve toneCurve = ToneCurve::PbrNeutral;
};

struct PreviewPicture {
  std::string label;               // the material's name
  Image image;                     // the render, beauty and AOVs
  std::vector<std::uint8_t> rgba;  // width x height, through the exposure and tone curve, row 0 at the top
  SamplingReport sampling;         // its rounds, samples and the noise they left
};

struct PreviewSheet {
  int frame = 0;
  std::vector<PreviewPicture> pictures;  // one per material, in order
  int width = 0, height = 0;             // of the sheet
  std::vector<std::uint8_t> rgba;        // the labelled contact sheet, row 0 at the top
};

}  // namespace v0
#ifndef FACET_IMPLEMENTATION
using namespace v0;
#endif
}  // namespace facet
