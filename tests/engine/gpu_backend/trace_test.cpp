// The GPU ray caster on its own, "rays in, hits out": scenes whose exact
// hits are known in closed form (or, for Catmull-Clark, checkable against
// the double-precision limit surface), rendered through the public API and
// checked pixel by pixel against rays computed in double with the same
// camera convention (engine/camera/camera.h, rules/camera/camera.h).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/translate_scene.h"
#include "engine/camera/camera.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "engine/image/image.h"
#include "scenes/scene.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/gpu_device.h"

namespace facet {
namespace {

constexpr int kWidth = 48;
constexpr int kHeight = 36;

const char* methodName(scene::IntersectionMethod method) {
  return method == scene::IntersectionMethod::Exact ? "exact" : "tess";
}

// The centre ray of pixel (x, y) (or a point offset from the centre by
// (dx, dy) pixels), in double, as both backends define it.
glm::dvec3 rayDirection(const rules::f64::CameraFrame& frame, int x, int y, double dx = 0.0, double dy = 0.0) {
  return rules::f64::camera_ray_direction(frame, x + 0.5 + dx, y + 0.5 + dy, double(kWidth), double(kHeight));
}

// Angle between two directions, robust near 0.
double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// A square of side 2 * halfSize, as an n x n grid of planar quads, centred
// at `centre` and spanned by the unit vectors `u`, `v` (counter-clockwise
// seen from u x v).
struct Square {
  glm::dvec3 centre{0.0};
  glm::dvec3 u{1.0, 0.0, 0.0};
  glm::dvec3 v{0.0, 1.0, 0.0};
  double halfSize = 1.0;

  glm::dvec3 normal() const { return glm::normalize(glm::cross(u, v)); }

  // Distance along the ray to the square's plane, and whether the hit lies
  // inside the square; nullopt when the ray is parallel or the plane is
  // behind the origin.
  struct PlaneHit {
    double t;
    bool inside;
  };
  std::optional<PlaneHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction) const {
    const glm::dvec3 n = normal();
    const double denominator = glm::dot(n, direction);
    if (denominator == 0.0) return std::nullopt;
    const double t = glm::dot(n, centre - origin) / denominator;
    if (!(t > 0.0)) return std::nullopt;
    const glm::dvec3 local = origin + t * direction - centre;
    const bool inside = std::abs(glm::dot(local, u)) < halfSize && std::abs(glm::dot(local, v)) < halfSize;
    return PlaneHit{t, inside};
  }
  bool hits(const glm::dvec3& origin, const glm::dvec3& direction) const {
    const auto hit = intersect(origin, direction);
    return hit && hit->inside;
  }

  scene::ControlCage cage(int n, const std::string& label) const {
    scene::ControlCage cage;
    cage.source = label;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double a = halfSize * (2.0 * i / n - 1.0), b = halfSize * (2.0 * j / n - 1.0);
        cage.positions.push_back(centre + a * u + b * v);
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int corner = j * (n + 1) + i;
        cage.faceVertexCounts.push_back(4);
        for (int k : {corner, corner + 1, corner + n + 2, corner + n + 1}) cage.faceVertexIndices.push_back(k);
      }
    return cage;
  }
};

scene::Object asAuthored(const Square& square, int n, const std::string& name) {
  scene::Object object;
  object.name = name;
  object.cage = square.cage(n, name);
  object.subdivision = scene::Subdivision::None;
  return object;
}

scene::Scene emptyScene(scene::IntersectionMethod method) {
  scene::Scene scene;
  scene.source = "trace_test";
  scene.materials.push_back(scene::defaultMaterial());
  scene.render.width = kWidth;
  scene.render.height = kHeight;
  scene.render.samplesPerPixel = 1;
  scene.render.method = method;
  return scene;
}

void record(const std::string& key, double value) {
  std::ostringstream text;
  text.precision(3);
  text << std::scientific << value;
  ::testing::Test::RecordProperty(key, text.str());
  std::cout << "  [measured] " << key << " = " << text.str() << "\n";
}

// ---------------------------------------------------------------------------
// 1. Planar squares as authored: every hit is the analytic ray-plane hit.

struct PlaneCase {
  double tiltDegrees;  // rotation of the square about the x axis
  scene::IntersectionMethod method;
};

void PrintTo(const PlaneCase& c, std::ostream* out) {
  *out << "tilt " << c.tiltDegrees << " deg, " << methodName(c.method);
}

class PlanarSquare : public gpu::testing::GpuTest, public ::testing::WithParamInterface<PlaneCase> {};

TEST_P(PlanarSquare, HitsAreTheAnalyticRayPlaneHits) {
  const double tilt = glm::radians(GetParam().tiltDegrees);
  Square square;
  square.centre = glm::dvec3(0.15, -0.1, 0.0);  // off the optical axis: no symmetry to hide behind
  square.u = glm::dvec3(1.0, 0.0, 0.0);
  square.v = glm::dvec3(0.0, std::cos(tilt), std::sin(tilt));  // (0, 1, 0) rotated about x
  square.halfSize = 1.0;

  scene::Scene scene = emptyScene(GetParam().method);
  scene.camera.eye = glm::dvec3(0.0, 0.0, 4.0);
  scene.camera.target = glm::dvec3(0.0);
  scene.camera.up = glm::dvec3(0.0, 1.0, 0.0);
  scene.camera.verticalFovDegrees = 40.0;
  scene.objects.push_back(asAuthored(square, 3, "square"));  // 3 x 3 quads: interior edges must not crack
  scene.lights.push_back(scene::defaultKeyLight(scene.camera));

  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  ASSERT_EQ(geometry.objects.size(), 1u);
  ASSERT_EQ(geometry.objects[0].surface.patchCount(), 9);
  const double sceneSize = geometry.bounds.diagonal();

  gpu_backend::GpuRenderer renderer(device_);
  const Image image = renderer.render(scene, geometry).image;
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);

  const rules::f64::CameraFrame frame = camera::cameraFrame(scene.camera, kWidth, kHeight);
  const glm::dvec3 eye = scene.camera.eye;
  const glm::dvec3 planeNormal = square.normal();

  double worstDepth = 0.0, worstPosition = 0.0, worstGeometric = 0.0, worstShading = 0.0;
  int covered = 0, ambiguous = 0, coverageMismatches = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t p = image.index(x, y);
      const glm::dvec3 d = rayDirection(frame, x, y);
      const bool expected = square.hits(eye, d);
      // A centre within 1e-4 pixel of an edge may go either way: the
      // corners of a 2e-4 pixel box around it disagree.
      bool edge = false;
      for (double dx : {-1e-4, 1e-4})
        for (double dy : {-1e-4, 1e-4}) edge |= square.hits(eye, rayDirection(frame, x, y, dx, dy)) != expected;
      const bool hit = image.patchId[p] != Image::kNoId;
      if (edge) {
        ++ambiguous;
        continue;
      }
      // Coverage: exactly the analytic footprint, on every coverage channel.
      if (hit != expected) ++coverageMismatches;
      EXPECT_EQ(hit, expected) << "pixel (" << x << ", " << y << ")";
      EXPECT_EQ(image.beauty[p].a, expected ? 1.0f : 0.0f) << "pixel (" << x << ", " << y << ")";
      EXPECT_EQ(std::isfinite(image.depth[p]), expected) << "pixel (" << x << ", " << y << ")";
      if (!hit || !expected) continue;
      ++covered;

      const auto analytic = square.intersect(eye, d);
      ASSERT_TRUE(analytic.has_value());
      const double t = analytic->t;
      const glm::dvec3 point = eye + t * d;
      const glm::dvec3 facing = glm::dot(planeNormal, d) > 0.0 ? -planeNormal : planeNormal;

      const double depthError = std::abs(double(image.depth[p]) - t) / t;
      const double positionError = glm::length(glm::dvec3(image.position[p]) - point) / sceneSize;
      const double geometricError = angleBetween(glm::normalize(glm::dvec3(image.geometricNormal[p])), facing);
      const double shadingError = angleBetween(glm::normalize(glm::dvec3(image.shadingNormal[p])), facing);
      worstDepth = std::max(worstDepth, depthError);
      worstPosition = std::max(worstPosition, positionError);
      worstGeometric = std::max(worstGeometric, geometricError);
      worstShading = std::max(worstShading, shadingError);
      // Depth: the analytic ray-plane distance, to 1e-6 relative.
      EXPECT_LE(depthError, 1e-6) << "depth at (" << x << ", " << y << "): " << image.depth[p] << " vs " << t;
      // Position AOV on the plane, to 1e-5 of the scene's size.
      EXPECT_LE(positionError, 1e-5) << "position at (" << x << ", " << y << ")";
      // Both normals are the plane's, facing the eye, to 1e-5 rad.
      EXPECT_LE(geometricError, 1e-5) << "geometric normal at (" << x << ", " << y << ")";
      EXPECT_LE(shadingError, 1e-5) << "shading normal at (" << x << ", " << y << ")";
    }
  // The square must fill a good part of the frame (a blank image would pass
  // the per-pixel checks), and few pixels may be excused as edge pixels.
  EXPECT_GT(covered, GetParam().tiltDegrees == 0.0 ? 600 : 250);
  EXPECT_LE(ambiguous, 4);
  record("covered_pixels", covered);
  record("edge_pixels_excused", ambiguous);
  record("coverage_mismatches", coverageMismatches);
  record("worst_depth_rel_error", worstDepth);
  record("worst_position_error_over_size", worstPosition);
  record("worst_geometric_normal_rad", worstGeometric);
  record("worst_shading_normal_rad", worstShading);
}

INSTANTIATE_TEST_SUITE_P(AsAuthored, PlanarSquare,
                         ::testing::Values(PlaneCase{0.0, scene::IntersectionMethod::Exact},
                                           PlaneCase{0.0, scene::IntersectionMethod::Tessellated},
                                           PlaneCase{60.0, scene::IntersectionMethod::Exact},
                                           PlaneCase{60.0, scene::IntersectionMethod::Tessellated}),
                         [](const ::testing::TestParamInfo<PlaneCase>& info) {
                           return std::string(info.param.tiltDegrees == 0.0 ? "flat_" : "tilted60_") +
                                  methodName(info.param.method);
                         });

// ---------------------------------------------------------------------------
// 2. Catmull-Clark cube, exact method: every hit lies on the limit surface at
// its own (patch, uv), and on the camera ray through the pixel centre, near
// the origin and 1e6 away from it.

class CubeLimitSurface : public gpu::testing::GpuTest, public ::testing::WithParamInterface<double> {};

TEST_P(CubeLimitSurface, ExactHitsLieOnTheLimitSurfaceAndOnTheirRay) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  scene.render.width = kWidth;
  scene.render.height = kHeight;
  scene.render.samplesPerPixel = 1;
  scene.render.method = scene::IntersectionMethod::Exact;
  // Closer than loadScene frames it, so that the cube fills more pixels.
  scene.camera.eye = scene.camera.target + 0.6 * (scene.camera.eye - scene.camera.target);
  const glm::dvec3 offset = GetParam() * glm::normalize(glm::dvec3(1.0, -0.5, 0.75));
  facet::testing::translateScene(scene, offset);

  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  ASSERT_EQ(geometry.objects.size(), 1u);
  const scene::SubdivisionSurface& surface = geometry.objects[0].surface;
  const double diagonal = geometry.bounds.diagonal();
  // The patches' control hulls of the [-1, 1]^3 cage, wherever it is.
  ASSERT_GT(diagonal, 2.0);
  ASSERT_LT(diagonal, 2.0 * std::sqrt(3.0));

  gpu_backend::GpuRenderer renderer(device_);
  const gpu_backend::GpuRenderResult result = renderer.render(scene, geometry);
  const Image& image = result.image;

  const rules::f64::CameraFrame frame = camera::cameraFrame(scene.camera, kWidth, kHeight);
  const glm::dvec3 eye = scene.camera.eye;

  double worstOnSurface = 0.0, worstOnRay = 0.0, worstEyeRelative = 0.0, worstUvOutside = 0.0;
  double rawOnSurface = 0.0, rawOnRay = 0.0, largestRounding = 0.0;
  int covered = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t p = image.index(x, y);
      if (image.patchId[p] == Image::kNoId) continue;
      ++covered;
      const int patch = int(image.patchId[p]);
      ASSERT_LT(patch, surface.patchCount()) << "pixel (" << x << ", " << y << ")";
      const double u = image.uv[p].x, v = image.uv[p].y;
      // The uv must belong to the patch (a root may only be accepted on it);
      // float rounding of the face uv allows 1e-6.
      const scene::PatchDomain& domain = surface.patch(patch).domain;
      const double outside = std::max({domain.u0 - u, u - (domain.u0 + domain.size), domain.v0 - v,
                                       v - (domain.v0 + domain.size), 0.0});
      worstUvOutside = std::max(worstUvOutside, outside);
      EXPECT_LE(outside, 1e-6) << "uv (" << u << ", " << v << ") off patch " << patch;

      const glm::dvec3 limit = surface.evaluatePatch(patch, u, v).position;
      const glm::dvec3 d = rayDirection(frame, x, y);
      // The position AOV is a float in world space: far from the origin it
      // is rounded to float's spacing there (0.0625 at 1e6), which the
      // tolerance must allow on top of the scene-relative 1e-5 x diagonal.
      const double largest = std::max({std::abs(limit.x), std::abs(limit.y), std::abs(limit.z)});
      const double rounding =
          std::sqrt(3.0) * 0.5 * (std::nextafter(float(largest), std::numeric_limits<float>::infinity()) - float(largest));
      const glm::dvec3 position(image.position[p]);
      const double onSurface = glm::length(position - limit);
      const glm::dvec3 fromEye = position - eye;
      const double onRay = glm::length(fromEye - glm::dot(fromEye, d) * d);
      // Relative to the eye, where the GPU works: depth along the double ray
      // lands on the limit point at the reported (patch, uv). No world-space
      // float rounding enters here, so 1e-5 x diagonal holds at 1e6 too.
      const double eyeRelative = glm::length(eye + double(image.depth[p]) * d - limit);
      rawOnSurface = std::max(rawOnSurface, onSurface / diagonal);
      rawOnRay = std::max(rawOnRay, onRay / diagonal);
      largestRounding = std::max(largestRounding, rounding / diagonal);
      worstOnSurface = std::max(worstOnSurface, std::max(onSurface - rounding, 0.0) / diagonal);
      worstOnRay = std::max(worstOnRay, std::max(onRay - rounding, 0.0) / diagonal);
      worstEyeRelative = std::max(worstEyeRelative, eyeRelative / diagonal);
      EXPECT_LE(onSurface, 1e-5 * diagonal + rounding) << "position off the limit surface at (" << x << ", " << y << ")";
      EXPECT_LE(onRay, 1e-5 * diagonal + rounding) << "position off the pixel's ray at (" << x << ", " << y << ")";
      EXPECT_LE(eyeRelative, 1e-5 * diagonal) << "eye + depth * ray off the limit surface at (" << x << ", " << y
                                              << ")";
    }
  // A blank frame would pass the per-pixel checks: the cube must fill a good
  // part of the image.
  EXPECT_GT(covered, 300);
  record("covered_pixels", covered);
  record("newton_fallbacks", double(result.newtonFallbacks));
  record("worst_position_to_limit_over_diagonal", rawOnSurface);
  record("worst_position_to_ray_over_diagonal", rawOnRay);
  record("float_rounding_allowance_over_diagonal", largestRounding);
  record("worst_position_to_limit_over_diagonal_beyond_float_rounding", worstOnSurface);
  record("worst_position_to_ray_over_diagonal_beyond_float_rounding", worstOnRay);
  record("worst_eye_plus_depth_to_limit_over_diagonal", worstEyeRelative);
  record("worst_uv_outside_patch", worstUvOutside);
}

INSTANTIATE_TEST_SUITE_P(Translated, CubeLimitSurface, ::testing::Values(0.0, 1e6),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return info.param == 0.0 ? std::string("at_origin") : std::string("at_1e6");
                         });

// ---------------------------------------------------------------------------
// 3. Any-hit shadow rays: a small occluder between a point light and a larger
// receiver; the receiver is black exactly inside the occluder's analytic
// shadow and lit outside it.

class ShadowRays : public gpu::testing::GpuTest, public ::testing::WithParamInterface<scene::IntersectionMethod> {};

TEST_P(ShadowRays, ReceiverIsDarkExactlyInsideTheAnalyticShadow) {
  Square receiver;
  receiver.centre = glm::dvec3(0.0);
  receiver.halfSize = 2.0;
  Square occluder;
  occluder.centre = glm::dvec3(-0.2, 0.3, 0.8);
  occluder.halfSize = 0.6;
  // Behind the occluder as the camera sees it, so that the shadow falls
  // towards the camera, mostly clear of the occluder's image.
  const glm::dvec3 lightPosition(0.4, 1.2, 3.0);

  scene::Scene scene = emptyScene(GetParam());
  scene.camera.eye = glm::dvec3(0.3, -2.0, 3.5);
  scene.camera.target = glm::dvec3(-0.2, 0.2, 0.0);
  scene.camera.up = glm::dvec3(0.0, 0.0, 1.0);
  scene.camera.verticalFovDegrees = 45.0;
  scene.objects.push_back(asAuthored(receiver, 4, "receiver"));
  scene.objects.push_back(asAuthored(occluder, 1, "occluder"));
  scene::Light light;
  light.type = scene::LightType::Point;
  light.position = lightPosition;
  light.color = glm::dvec3(10.0);
  scene.lights.push_back(light);
  ASSERT_FALSE(scene.environment.has_value());

  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  gpu_backend::GpuRenderer renderer(device_);
  const gpu_backend::GpuRenderResult result = renderer.render(scene, geometry);
  const Image& image = result.image;

  const rules::f64::CameraFrame frame = camera::cameraFrame(scene.camera, kWidth, kHeight);
  const glm::dvec3 eye = scene.camera.eye;

  // What each pixel's centre ray sees, analytically.
  enum Class { Miss, Occluder, Lit, Shadowed };
  std::vector<Class> classes(image.pixelCount());
  std::vector<double> receiverDepth(image.pixelCount(), 0.0);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const glm::dvec3 d = rayDirection(frame, x, y);
      const auto onOccluder = occluder.intersect(eye, d);
      const auto onReceiver = receiver.intersect(eye, d);
      Class c = Miss;
      if (onOccluder && onOccluder->inside) {
        c = Occluder;  // nearer the eye than the receiver everywhere in view
      } else if (onReceiver && onReceiver->inside) {
        const glm::dvec3 point = eye + onReceiver->t * d;
        const glm::dvec3 toLight = lightPosition - point;
        const auto blocker = occluder.intersect(point, toLight);  // t in (0, 1): between point and light
        c = blocker && blocker->inside && blocker->t < 1.0 ? Shadowed : Lit;
        receiverDepth[image.index(x, y)] = onReceiver->t;
      }
      classes[image.index(x, y)] = c;
    }

  int shadowedChecked = 0, litChecked = 0, band = 0;
  float darkestLit = std::numeric_limits<float>::infinity(), brightestShadowed = 0.0f;
  double worstReceiverDepth = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t p = image.index(x, y);
      const Class c = classes[p];
      if (c != Lit && c != Shadowed) continue;
      // The 1-pixel band: any neighbour that sees something else excuses
      // the pixel (shadow edge, receiver or occluder silhouette).
      bool edge = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && ny >= 0 && nx < kWidth && ny < kHeight) edge |= classes[image.index(nx, ny)] != c;
        }
      if (edge) {
        ++band;
        continue;
      }
      // It is the receiver the camera ray hit (not the occluder, not a miss).
      ASSERT_NE(image.patchId[p], Image::kNoId) << "pixel (" << x << ", " << y << ")";
      const double depthError = std::abs(double(image.depth[p]) - receiverDepth[p]) / receiverDepth[p];
      worstReceiverDepth = std::max(worstReceiverDepth, depthError);
      EXPECT_LE(depthError, 1e-5) << "not the receiver at (" << x << ", " << y << ")";
      const glm::vec4 beauty = image.beauty[p];
      if (c == Shadowed) {
        ++shadowedChecked;
        brightestShadowed = std::max({brightestShadowed, beauty.r, beauty.g, beauty.b});
        // The only light is blocked and there is no environment: exactly 0.
        EXPECT_EQ(beauty.r, 0.0f) << "lit inside the shadow at (" << x << ", " << y << ")";
        EXPECT_EQ(beauty.g, 0.0f) << "lit inside the shadow at (" << x << ", " << y << ")";
        EXPECT_EQ(beauty.b, 0.0f) << "lit inside the shadow at (" << x << ", " << y << ")";
      } else {
        ++litChecked;
        darkestLit = std::min({darkestLit, beauty.r, beauty.g, beauty.b});
        // Unblocked, n.l > 0 with the light and the eye on the same side: > 0.
        EXPECT_GT(beauty.r, 0.0f) << "dark outside the shadow at (" << x << ", " << y << ")";
        EXPECT_GT(beauty.g, 0.0f) << "dark outside the shadow at (" << x << ", " << y << ")";
        EXPECT_GT(beauty.b, 0.0f) << "dark outside the shadow at (" << x << ", " << y << ")";
      }
    }
  // Both sides of the shadow edge must be well represented.
  EXPECT_GT(shadowedChecked, 80);
  EXPECT_GT(litChecked, 500);
  record("shadowed_pixels_checked", shadowedChecked);
  record("lit_pixels_checked", litChecked);
  record("band_pixels_excused", band);
  record("shadow_rays", double(result.shadowRays));
  record("brightest_shadowed_beauty", brightestShadowed);
  record("darkest_lit_beauty", darkestLit);
  record("worst_receiver_depth_rel_error", worstReceiverDepth);
}

INSTANTIATE_TEST_SUITE_P(BothMethods, ShadowRays,
                         ::testing::Values(scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated),
                         [](const ::testing::TestParamInfo<scene::IntersectionMethod>& info) {
                           return std::string(methodName(info.param));
                         });

}  // namespace
}  // namespace facet
