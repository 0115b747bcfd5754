// The digest of what decides a render's pixels, written into every tile so
// that `facet merge` joins only tiles of one render; and those settings as
// a line a person reads, for the EXR's facetRenderSettings attribute.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace facet::cli {

// Hex FNV-1a of the scene file's bytes, the scene as the flags left it
// (image size, camera, sampling, method, subdivision, environment) and the
// backend. Files the scene names (cages, maps) count by path.
std::string settingsDigest(const scene::Scene& scene, const std::string& backend);

// "backend=gpu size=512x512 spp=4 method=exact pixelTolerance=0.5
// tessellationRate=auto ibl=prefiltered iblSamples=16 ...": the sampling,
// intersection and lighting settings; the camera is in worldToCamera.
std::string renderSettingsText(const scene::Scene& scene, const std::string& backend);

}  // namespace facet::cli
