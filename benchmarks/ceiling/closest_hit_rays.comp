// The closest hit of each ray of a given list (ray_list.glsl).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "benchmarks/ceiling/ray_list.glsl"
