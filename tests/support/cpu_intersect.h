#pragma once
// Shared by the CPU intersection tests: cages, rays aimed at known surface
// points, and an independent reference normal.

#include "engine/cpu/intersect.h"
#include "scenes/obj_cage.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace facet::cpu::testing {

struct Geometry {
  explicit Geometry(const std::string& cage, int isolationLevel = 3)
      : surface(scene::SubdivisionSurface::create(scene::loadObjCage(std::string(FACET_CAGE_DIR) + "/" + cage + ".obj"),
                                                  {isolationLevel})),
        bvh(scene::PatchBvh::build(surface)),
        diagonal(surface.bounds().diagonal()),
        centre(surface.bounds().centre()) {}

  scene::SubdivisionSurface surface;
  scene::PatchBvh bvh;
  double diagonal;
  glm::dvec3 centre;
};

// A surface point chosen by (patch, s, t) and a ray from outside the bounds
// that passes through it.
struct AimedRay {
  Ray ray;
  int patch;
  double u, v;     // face parameters of the target
  double targetT;  // the ray reaches the target at this t
};

inline glm::dvec3 randomDirection(std::mt19937& random) {
  std::normal_distribution<double> normal;
  glm::dvec3 d;
  do {
    // Drawn z first, in sequence: the order of a call's arguments is
    // unspecified, and gcc and clang differ.
    const double z = normal(random), y = normal(random), x = normal(random);
    d = glm::dvec3(x, y, z);
  } while (glm::length(d) < 1e-6);
  return glm::normalize(d);
}

// Targets include patch corners and edges (s or t in {0, 1}) one time in
// four: shared patch boundaries are where cracks would show.
inline std::vector<AimedRay> aimRays(const Geometry& geometry, int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> anyPatch(0, geometry.surface.patchCount() - 1);
  std::vector<AimedRay> rays;
  const glm::dvec3 centre = geometry.centre;
  for (int i = 0; i < count; ++i) {
    const int patch = anyPatch(random);
    const scene::PatchDomain& domain = geometry.surface.patch(patch).domain;
    double s = unit(random), t = unit(random);
    if (i % 4 == 1) s = std::round(s);
    if (i % 8 == 3) t = std::round(t);
    const double u = domain.u0 + s * domain.size, v = domain.v0 + t * domain.size;
    const glm::dvec3 target = geometry.surface.evaluatePatch(patch, u, v).position;
    const glm::dvec3 origin = centre + 1.5 * geometry.diagonal * randomDirection(random);
    AimedRay aimed;
    aimed.ray.origin = origin;
    aimed.ray.direction = glm::normalize(target - origin);
    aimed.patch = patch;
    aimed.u = u;
    aimed.v = v;
    aimed.targetT = glm::length(target - origin);
    rays.push_back(aimed);
  }
  return rays;
}

// The limit normal by central differences of OpenSubdiv positions: it does
// not use OpenSubdiv's derivatives, which for Gregory patches are an
// approximation.
inline glm::dvec3 finiteDifferenceNormal(const scene::SubdivisionSurface& surface, int patch, double u, double v) {
  const double h = 1e-6 * surface.patch(patch).domain.size;
  auto at = [&](double du, double dv) { return surface.evaluatePatch(patch, u + du, v + dv).position; };
  return glm::normalize(glm::cross(at(h, 0) - at(-h, 0), at(0, h) - at(0, -h)));
}

// An orthographic grid of rays from several directions: a miss with hits on
// both sides in its row and in its column lies inside the silhouette of a
// convex cage, so it is a crack.
template <typename Intersect>
void expectNoCracks(const Geometry& geometry, const std::string& name, Intersect&& intersect) {
  const glm::dvec3 directions[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {-1, 1, 1}, {1, -1, 1}, {0.3, 1, -0.7}};
  constexpr int kGrid = 32;
  const glm::dvec3 centre = geometry.centre;
  const double half = 0.5 * geometry.diagonal;
  int totalHits = 0;
  for (glm::dvec3 direction : directions) {
    direction = glm::normalize(direction);
    const glm::dvec3 side =
        glm::normalize(glm::cross(direction, std::abs(direction.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
    const glm::dvec3 up = glm::cross(side, direction);
    std::vector<int> covered(kGrid * kGrid);
    for (int j = 0; j < kGrid; ++j) {
      for (int i = 0; i < kGrid; ++i) {
        Ray ray;
        ray.origin = centre - 2.0 * half * direction +
                     half * ((2.0 * (i + 0.5) / kGrid - 1.0) * side + (2.0 * (j + 0.5) / kGrid - 1.0) * up);
        ray.direction = direction;
        covered[j * kGrid + i] = intersect(ray).has_value();
      }
    }
    int cracks = 0;
    for (int j = 0; j < kGrid; ++j) {
      for (int i = 0; i < kGrid; ++i) {
        totalHits += covered[j * kGrid + i];
        if (covered[j * kGrid + i]) continue;
        bool left = false, right = false, below = false, above = false;
        for (int k = 0; k < kGrid; ++k) {
          left = left || (k < i && covered[j * kGrid + k]);
          right = right || (k > i && covered[j * kGrid + k]);
          below = below || (k < j && covered[k * kGrid + i]);
          above = above || (k > j && covered[k * kGrid + i]);
        }
        cracks += left && right && below && above;
      }
    }
    EXPECT_EQ(cracks, 0) << name << " seen along " << direction.x << "," << direction.y << "," << direction.z;
  }
  // Only the thin slab seen edge-on may fall between the grid rays.
  EXPECT_GT(totalHits, kGrid * kGrid) << name;
}

inline double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace facet::cpu::testing
