// Writing and reading images. Every writer goes through a temporary file in
// the destination's folder and renames it into place, so a failure never
// leaves a partial file behind; a set of outputs is renamed into place only
// once every one of them is written (docs/reliability.md#outputs).
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
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/image/image.h"

namespace facet {

// An output that could not be written, or a path no output can be written to.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file to write: its destination, and how to write it to a given path.
struct OutputFile {
  std::filesystem::path path;
  std::function<void(const std::filesystem::path&)> write;
};

// Throws OutputError "<flag> '<path>': <rule>" unless `path` names a file
// that can be created or replaced: not empty, not a folder, in an existing
// writable folder. Checked before the work that produces the file.
void checkOutputPath(const std::string& flag, const std::filesystem::path& path);

// Writes every file to a temporary in its destination's folder, then renames
// them all into place. When a write fails, removes the temporaries and leaves
// every existing destination untouched.
void writeAllOrNothing(const std::vector<OutputFile>& files);

// Calls write(temporaryPath), then renames the temporary onto `path`.
void writeAtomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);

OutputFile exrFile(const std::filesystem::path& path, const Image& image);
void writeExr(const std::filesystem::path& path, const Image& image);
Image readExr(const std::filesystem::path& path);

// 8-bit preview of the beauty through previewToneCurve (engine/image/color.h).
OutputFile pngFile(const std::filesystem::path& path, const Image& image, float exposure = 0.0f);
void writePng(const std::filesystem::path& path, const Image& image, float exposure = 0.0f);

}  // namespace facet
