// The pinhole camera's primary rays, one convention for both backends. Pixel
// (i, j) is sampled at (i + sx, j + sy) with (sx, sy) = (0.5, 0.5) at its
// centre; row 0 is the top of the image.

#ifndef FACET_RULE_CAMERA_CAMERA
#define FACET_RULE_CAMERA_CAMERA

// The camera as both sides see it: an orthonormal frame and the image plane
// at distance 1 along `forward`, scaled by tan(fov / 2).
struct CameraFrame {
  vec3 eye;
  vec3 forward;
  vec3 right;
  vec3 up;
  real tanHalfFovY;
  real aspect;  // width / height
};

// Unit direction of the ray through image point (x, y), in pixels.
FACET_FN vec3 camera_ray_direction(CameraFrame c, real x, real y, real width, real height) {
  real sx = (real(2) * x / width - real(1)) * c.tanHalfFovY * c.aspect;
  real sy = (real(1) - real(2) * y / height) * c.tanHalfFovY;
  return normalize(c.forward + sx * c.right + sy * c.up);
}

#endif
