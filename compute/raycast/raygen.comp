// Camera rays of a band of pixels: per pixel the centre ray (AOVs, and the
// beauty at 1 spp), then strata^2 stratified rays when spp > 1
// (docs/rendering.md, compute/shared/camera.h).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/shared/raycast_layout.h"

#define real float
#define FACET_FN
#include "compute/shared/camera.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 8, std430) writeonly buffer Rays { RayRecord rays[]; };

void main() {
  uint index = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u;
  if (index >= frame.pixelCount * frame.raysPerPixel) return;
  uint pixel = frame.firstPixel + index / frame.raysPerPixel, sampleIndex = index % frame.raysPerPixel;
  vec2 offset = vec2(0.5);
  if (sampleIndex > 0u) {
    uint stratum = sampleIndex - 1u;
    offset = (vec2(stratum % frame.strata, stratum / frame.strata) + 0.5) / float(frame.strata);
  }
  uint width = uint(frame.width);
  CameraFrame camera;
  camera.eye = vec3(frame.eyeX, frame.eyeY, frame.eyeZ);
  camera.forward = vec3(frame.forwardX, frame.forwardY, frame.forwardZ);
  camera.right = vec3(frame.rightX, frame.rightY, frame.rightZ);
  camera.up = vec3(frame.upX, frame.upY, frame.upZ);
  camera.tanHalfFovY = frame.tanHalfFovY;
  camera.aspect = frame.aspect;
  vec3 direction = camera_ray_direction(camera, float(pixel % width) + offset.x, float(pixel / width) + offset.y,
                                        frame.width, frame.height);
  rays[index] = RayRecord(camera.eye.x, camera.eye.y, camera.eye.z, 0.0, direction.x, direction.y, direction.z,
                          uintBitsToFloat(0x7f800000u));
}
