// The C++ view of compute/shared/raycast_layout.h (see scenes/gpu_layout.h
// for why including it inside a namespace is safe).
#pragma once

#include <cstddef>
#include <cstdint>

namespace facet::gpu_layout {
using uint = std::uint32_t;
#include "compute/shared/raycast_layout.h"
}  // namespace facet::gpu_layout

// The layout GLSL sees: 4-byte members, no padding.
static_assert(sizeof(facet::gpu_layout::ObjectRange) == 40);
static_assert(sizeof(facet::gpu_layout::RayRecord) == 32);
static_assert(sizeof(facet::gpu_layout::HitRecord) == 32);
static_assert(sizeof(facet::gpu_layout::LightRecord) == 48);
static_assert(sizeof(facet::gpu_layout::MaterialRecord) == 68);
static_assert(sizeof(facet::gpu_layout::FrameParams) == 152);
static_assert(sizeof(facet::gpu_layout::PixelAovs) == 56);
static_assert(sizeof(facet::gpu_layout::EnvironmentLevel) == 12);
