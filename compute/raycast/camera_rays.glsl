// The camera ray of each invocation of a band, computed where it is needed
// rather than stored: per pixel the centre ray (AOVs, and the beauty at
// 1 spp), then strata^2 stratified rays when spp > 1 (docs/rendering.md,
// compute/shared/camera.h). Rays start at the eye, the origin of the GPU's
// coordinates. Needs ray.glsl and `frame`.
#ifndef FACET_RAYCAST_CAMERA_RAYS_GLSL
#define FACET_RAYCAST_CAMERA_RAYS_GLSL

#define real float
#define FACET_FN
#include "compute/shared/camera.h"

Ray camera_ray(uint index) {
  uint pixel = frame.firstPixel + index / frame.raysPerPixel, sampleIndex = index % frame.raysPerPixel;
  vec2 offset = vec2(0.5);
  if (sampleIndex > 0u) {
    uint stratum = sampleIndex - 1u;
    offset = (vec2(stratum % frame.strata, stratum / frame.strata) + 0.5) / float(frame.strata);
  }
  uint width = uint(frame.width);
  CameraFrame camera;
  camera.eye = vec3(0.0);
  camera.forward = vec3(frame.forwardX, frame.forwardY, frame.forwardZ);
  camera.right = vec3(frame.rightX, frame.rightY, frame.rightZ);
  camera.up = vec3(frame.upX, frame.upY, frame.upZ);
  camera.tanHalfFovY = frame.tanHalfFovY;
  camera.aspect = frame.aspect;
  vec3 direction = camera_ray_direction(camera, float(pixel % width) + offset.x, float(pixel / width) + offset.y,
                                        frame.width, frame.height);
  return Ray(vec3(0.0), direction, 0.0, INFINITE_DISTANCE);
}

#endif
