// The C++ view of the GPU buffer layouts of compute/layout/: they are written
// in the subset of rules/language.h, need only its `uint`, and include
// nothing themselves, so including them inside a namespace is safe.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "rules/rules.h"

namespace facet::gpu_backend {
// One RGBA32UI texel of a texel buffer.
using Texel = std::array<std::uint32_t, 4>;
}  // namespace facet::gpu_backend

namespace facet::gpu_layout {
using rules::f32::uint;
#include "compute/layout/patch_records.h"
#include "compute/layout/raycast_layout.h"
#include "compute/layout/path_layout.h"
#include "compute/layout/surface_features.h"
#include "compute/layout/wide_bvh.h"
}  // namespace facet::gpu_layout

// The layout GLSL sees: 4-byte members, no padding.
static_assert(sizeof(facet::gpu_layout::PatchRecord) == 16 * facet::gpu_layout::FACET_PATCH_RECORD_TEXELS);
static_assert(offsetof(facet::gpu_layout::PatchRecord, faceU0) == 16);
static_assert(offsetof(facet::gpu_layout::PatchRecord, ptexFace) == 28);
static_assert(sizeof(facet::gpu_layout::ObjectRange) == 100);
static_assert(sizeof(facet::gpu_layout::RayRecord) == 32);
static_assert(sizeof(facet::gpu_layout::ShadowRayRecord) == 36);
static_assert(sizeof(facet::gpu_layout::RenderCounters) == 84);
static_assert(offsetof(facet::gpu_layout::RenderCounters, shadowX) == 4);
static_assert(offsetof(facet::gpu_layout::RenderCounters, cameraFallbackX) == 20);
static_assert(offsetof(facet::gpu_layout::RenderCounters, shadowFallbackX) == 36);
static_assert(offsetof(facet::gpu_layout::RenderCounters, pathX) == 52);
static_assert(offsetof(facet::gpu_layout::RenderCounters, liveX) == 72);
static_assert(sizeof(facet::gpu_layout::FallbackRecord) == 28);
static_assert(sizeof(facet::gpu_layout::PathRayRecord) == 48);
static_assert(sizeof(facet::gpu_layout::PathState) == 276);
static_assert(sizeof(facet::gpu_layout::HitRecord) == 32);
static_assert(sizeof(facet::gpu_layout::LightRecord) == 48);
static_assert(sizeof(facet::gpu_layout::TextureSlotRecord) == 32);
static_assert(sizeof(facet::gpu_layout::MaterialRecord) == 776);
static_assert(sizeof(facet::gpu_layout::FrameParams) == 216);
static_assert(sizeof(facet::gpu_layout::PixelAovs) == 64);
