// What an EXR says about the render besides its pixels: the camera as
// OpenEXR's standard worldToCamera and worldToNDC attributes, the software,
// its settings and what they decide, and the scene's object and material names that the ID
// layers refer to (docs/outputs.md).
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace facet {

// A 4x4 matrix in OpenEXR's (Imath's) convention: row vectors, p' = p M, so
// the translation is the last row; m[i][j] is Imath's x[i][j].
using RowMatrix = std::array<std::array<double, 4>, 4>;

// The pinhole camera of rules/camera/camera.h: an orthonormal frame, the
// image plane at distance 1 along `forward`, scaled by tan(fov / 2).
struct ExrCamera {
  glm::dvec3 eye{0.0}, right{1.0, 0.0, 0.0}, up{0.0, 1.0, 0.0}, forward{0.0, 0.0, -1.0};
  double tanHalfFovY = 1.0;
  double aspect = 1.0;  // display width / height
};

// World to OpenEXR's (RenderMan's) left-handed camera space: origin at the
// eye, +x right and +y up in the image, +z the viewing direction.
RowMatrix worldToCamera(const ExrCamera& camera);

// World to NDC, homogeneous: after the divide by w, (x, y) = (0, 0) at the
// display window's top-left corner and (1, 1) at its bottom-right, so pixel
// (i, j)'s centre is ((i + 0.5) / width, (j + 0.5) / height); z = 1 / camera
// depth, which keeps the matrix invertible.
RowMatrix worldToNdc(const ExrCamera& camera);

// The scene's names, and which pixels they cover: object k owns the faceIds
// firstFace[k] .. firstFace[k + 1] - 1 (the renderers number faces object by
// object) and uses material materialOf[k].
struct ExrNames {
  std::vector<std::string> objects;
  std::vector<std::uint32_t> firstFace;  // ascending, one per object
  std::vector<std::uint32_t> materialOf;
  std::vector<std::string> materials;
};

// The object a faceId belongs to; Image::kNoId for a miss.
std::uint32_t objectOfFace(const ExrNames& names, std::uint32_t faceId);

// How the render was made: what `facet compare` reads back to tell whether
// two stored renders estimate the same picture, and to pair them by seed.
struct ExrProvenance {
  std::string software;                       // "software": "facet <version>"
  std::string renderSettings;                 // kRenderSettingsAttribute
  std::string pictureDigest;                  // kPictureDigestAttribute (engine/render_record.h)
  std::optional<std::uint32_t> estimateSeed;  // kEstimateSeedAttribute: only where the beauty is an estimate
};
inline constexpr const char* kRenderSettingsAttribute = "facetRenderSettings";
inline constexpr const char* kPictureDigestAttribute = "facetPictureDigest";
inline constexpr const char* kEstimateSeedAttribute = "facetEstimateSeed";

struct ExrMetadata {
  std::optional<ExrCamera> camera;  // worldToCamera, worldToNDC
  ExrProvenance provenance;
  std::optional<ExrNames> names;  // objectId, materialId and the Cryptomatte layers
};

}  // namespace facet
