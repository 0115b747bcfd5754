// The render as a multi-layer EXR: the beauty and the AOV layers chosen,
// with the camera, settings and ID attributes of exr_metadata.h, written all
// or nothing like every output (image_io.h). Channels by layer (32-bit float
// unless noted; docs/outputs.md):
//   beauty    R G B A              linear, half with halfBeauty: RGB the mean radiance of the
//                                  pixel's samples, a miss counting what it sees; A = coverage,
//                                  the share of samples that hit (0 on misses). So
//                                  RGB = A C + (1 - A) E, C the surfaces' colour, E the
//                                  environment the misses saw: premultiplied by A only
//                                  without an environment (E = 0) (docs/preview.md)
//   depth     Z                    distance from the eye along the ray (+inf on misses)
//   position  P.X P.Y P.Z          world position
//   normals   Ng.X Ng.Y Ng.Z       geometric normal
//             N.X N.Y N.Z          shading (limit-surface) normal
//   ids       patchId faceId       32-bit unsigned (0xFFFFFFFF on misses)
//             objectId materialId  32-bit unsigned, with the scene's names
//   uv        uv.U uv.V            parameter on the control-cage face
//   texcoord  st.s st.t            texture coordinates (0 on misses and on surfaces without them)
//   crypto    CryptoObject00.R G B A, CryptoMaterial00.R G B A
//                                  Cryptomatte rank 0 and 1 (id, coverage), with the scene's names
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>

#include "engine/image/exr_metadata.h"
#include "engine/image/image.h"
#include "engine/image/image_io.h"
#include "engine/image/pixel_rect.h"

namespace facet {

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

// The layers above by name; the beauty is always written.
using ExrLayers = std::set<std::string>;
inline constexpr const char* kExrLayers[] = {"beauty", "depth", "position", "normals",
                                             "ids",    "uv",    "texcoord", "crypto"};
ExrLayers allExrLayers();
std::string exrLayerNames();  // "beauty, depth, ..."
// "all", "beauty" or a comma-separated list of layer names; throws
// std::invalid_argument "<flag> '<text>': <rule>" otherwise.
ExrLayers parseExrLayers(const std::string& text, const std::string& flag);

struct ExrOptions {
  std::optional<ExrPlacement> placement;  // none: the image is the whole display window
  ExrMetadata metadata;
  ExrLayers layers = allExrLayers();
  bool halfBeauty = false;  // R G B A as 16-bit half floats
};

OutputFile exrFile(const std::filesystem::path& path, const Image& image, const ExrOptions& options = {});
void writeExr(const std::filesystem::path& path, const Image& image, const ExrOptions& options = {});
// The image planes the file has; the others keep their miss values.
Image readExr(const std::filesystem::path& path);
// The provenance attributes the file has; the others are empty.
ExrProvenance readExrProvenance(const std::filesystem::path& path);

}  // namespace facet
