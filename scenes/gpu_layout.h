#pragma once
// The C++ view of compute/shared/patch_bvh.h: the shared header is written in
// the common subset of GLSL and C++, and only needs GLSL's `uint` spelled out.
// It includes nothing itself, so including it inside a namespace is safe.

#include <cstddef>
#include <cstdint>

namespace facet::gpu_layout {
using uint = std::uint32_t;
#include "compute/shared/patch_bvh.h"
}  // namespace facet::gpu_layout

// The layout GLSL sees (std430 / scalar: 4-byte members, no padding).
static_assert(sizeof(facet::gpu_layout::PatchBvhNode) == 32);
static_assert(offsetof(facet::gpu_layout::PatchBvhNode, next) == 12);
static_assert(offsetof(facet::gpu_layout::PatchBvhNode, patchCount) == 28);
static_assert(sizeof(facet::gpu_layout::PatchRecord) == 48);
static_assert(offsetof(facet::gpu_layout::PatchRecord, faceU0) == 16);
static_assert(offsetof(facet::gpu_layout::PatchRecord, pointCount) == 40);
static_assert(offsetof(facet::gpu_layout::PatchRecord, transitionMask) == 44);
static_assert(sizeof(facet::gpu_layout::PatchPoint) == 12);
