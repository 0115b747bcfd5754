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
//   st.s st.t                 texture coordinates (0 on misses and on surfaces without them)
#pragma once

#include <filesystem>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "engine/image/pixel_rect.h"

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

// Where an EXR's pixels lie in the full render (its data window inside the
// display window), and the digest of the settings that rendered them, kept
// in the header attribute kSettingsDigestAttribute so that a merge can tell
// tiles of one render from another's.
struct ExrPlacement {
  PixelRect dataWindow;
  int displayWidth = 0, displayHeight = 0;
  std::string digest;
};
inline constexpr const char* kSettingsDigestAttribute = "facetSettingsDigest";

// Without a placement, the image is the whole display window.
OutputFile exrFile(const std::filesystem::path& path, const Image& image,
                   const std::optional<ExrPlacement>& placement = {});
void writeExr(const std::filesystem::path& path, const Image& image);
Image readExr(const std::filesystem::path& path);

// 8-bit RGBA preview of `count` beauty pixels through previewToneCurve
// (engine/image/color.h), exposure in stops.
void previewPixels(const glm::vec4* beauty, std::size_t count, float exposure, std::uint8_t* rgba);

// A PNG of 8-bit RGBA pixels, row 0 at the top; `rgba` must outlive the write.
OutputFile rgbaPngFile(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba);

// 8-bit preview of the beauty through previewToneCurve (engine/image/color.h).
OutputFile pngFile(const std::filesystem::path& path, const Image& image, float exposure = 0.0f);
void writePng(const std::filesystem::path& path, const Image& image, float exposure = 0.0f);

}  // namespace facet
