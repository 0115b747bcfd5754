// Tiles of one render (EXRs whose data windows lie in one display window,
// each carrying the render's settings digest) merged into the whole image.
#pragma once

#include <filesystem>
#include <vector>

#include "engine/image/preview.h"

namespace facet {

struct MergeOutputs {
  std::filesystem::path exr;
  std::filesystem::path png;  // empty: none
  PreviewOptions preview;     // of the PNG
};

// Checks that the tiles share one settings digest, display window and
// channel list, and cover the display window exactly once; throws
// std::invalid_argument "<tile>: <what>: <rule>" otherwise, before anything
// is written. Then streams the tiles into the outputs a band of rows at a
// time, so memory grows with the width, not the image (the PNG preview
// holds its 8-bit pixels); outputs are written all or nothing. Pixel data
// that does not decode is found only then, and is the tile's
// std::invalid_argument too, with no output left.
void mergeTiles(const std::vector<std::filesystem::path>& tiles, const MergeOutputs& outputs);

}  // namespace facet
