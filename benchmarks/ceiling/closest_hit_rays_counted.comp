// closest_hit_rays.comp with the nodes visited and triangles tested per ray.
#version 460
#extension GL_GOOGLE_include_directive : require

#define CEILING_COUNT
#include "benchmarks/ceiling/ray_list.glsl"
