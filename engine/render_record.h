// What a render's outputs say about it, alike from the command line and the
// APIs: the digest of what decides its pixels, written into every tile so
// that `facet merge` joins only tiles of one render, and the digest and seed
// by which `facet compare` pairs stored renders; those settings as a
// line a person reads, for the EXR's facetRenderSettings attribute; and the
// EXR header that carries them with the camera and the scene's names. The
// picture digest is the settings digest without the backend and the seed:
// two renders with one picture digest estimate one picture.
#pragma once

#include <string>

#include "engine/image/exr_file.h"
#include "engine/image/pixel_rect.h"
#include "scenes/scene.h"

namespace facet {

// Hex FNV-1a of the scene file's bytes, the scene as the flags left it
// (image size, camera, sampling, method, subdivision, environment) and the
// backend. Files the scene names (cages, maps) count by path.
std::string settingsDigest(const scene::Scene& scene, const std::string& backend);

// "backend=gpu size=512x512 spp=4 method=exact pixelTolerance=0.5
// tessellationRate=auto ibl=prefiltered iblSamples=16 ...": the sampling,
// intersection and lighting settings; the camera is in worldToCamera.
std::string renderSettingsText(const scene::Scene& scene, const std::string& backend);

// The EXR options of a render of `scene` (its camera the frame's) on
// `backend` whose pixels are `window` of the full image, with `layers`.
ExrOptions describedExr(const scene::Scene& scene, const std::string& backend, const PixelRect& window,
                        const ExrLayers& layers, bool halfBeauty);

}  // namespace facet
