// Writing and reading images. Every writer goes through a temporary file in
// the destination's folder and renames it into place, so a failure never
// leaves a partial file behind.
//
// EXR channels (all 32-bit float unless noted):
//   R G B A                   beauty, linear; A = coverage (0 on misses)
//   Z                         depth: distance from the eye along the ray (+inf on misses)
//   P.X P.Y P.Z               world position
//   Ng.X Ng.Y Ng.Z            geometric normal
//   N.X N.Y N.Z               shading (limit-surface) normal
//   patchId faceId            32-bit unsigned (0xFFFFFFFF on misses)
//   uv.U uv.V                 parameter on the control-cage face
#pragma once

#include <filesystem>
#include <functional>

#include "engine/image/image.h"

namespace facet {

// Calls write(temporaryPath), then renames the temporary onto `path`.
void writeAtomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);

void writeExr(const std::filesystem::path& path, const Image& image);
Image readExr(const std::filesystem::path& path);

// 8-bit preview of the beauty through previewToneCurve (engine/image/color.h).
void writePng(const std::filesystem::path& path, const Image& image, float exposure = 0.0f);

}  // namespace facet
