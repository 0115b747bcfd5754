// The camera ray of each invocation of a band, computed where it is needed
// rather than stored: sample `index % raysPerPixel` of its pixel
// (rules/camera/sample_plan.h, camera_samples.h, camera.h). Rays start at
// the eye, the origin of the GPU's coordinates. Needs ray.glsl,
// rules/sampling/random.h, low_discrepancy.h, scrambled_net.h and `frame`.
#ifndef FACET_RAYCAST_CAMERA_RAYS_GLSL
#define FACET_RAYCAST_CAMERA_RAYS_GLSL

#include "rules/language.glsl"
#include "compute/raycast/common/band_pixels.glsl"
#include "rules/camera/camera.h"
#include "rules/camera/camera_samples.h"

Ray camera_ray(uint index) {
  uint pixel = image_pixel(index / frame.raysPerPixel), sampleIndex = index % frame.raysPerPixel;
  // Camera rays are cast only while the frame holds the scene's own seed
  // (band_passes.cpp gives each bounce a vertex seed after them).
  vec2 offset = sample_offset(pixel, sampleIndex, frame.strata, frame.environmentSeed);
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
