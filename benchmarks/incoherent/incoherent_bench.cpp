#include "benchmarks/incoherent/incoherent_bench.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <random>
#include <stdexcept>

#include "benchmarks/ceiling/micro_grid_triangles.h"
#include "benchmarks/ceiling/triangle_bvh4.h"
#include "benchmarks/incoherent/ceiling_rays.h"
#include "benchmarks/incoherent/facet_rays.h"
#include "benchmarks/incoherent/incoherent_report.h"
#include "benchmarks/wall_clock.h"
#include "engine/camera/camera.h"
#include "engine/gpu/gpu.h"
#include "engine/renderer.h"
#include "rules/rules.h"
#include "scenes/obj_cage.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"

#if FACET_HAVE_EMBREE
#include "benchmarks/incoherent/embree_triangles.h"
#endif

namespace facet::benchmarks::incoherent {
namespace {

namespace f32 = facet::rules::f32;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// One ray per pixel centre from the eye (the origin of the GPU's coordinates).
std::vector<Ray> cameraRays(const scene::Scene& scene, int size) {
  rules::f64::CameraFrame camera = facet::camera::cameraFrame(scene.camera, size, size);
  camera.eye = glm::dvec3(0);
  std::vector<Ray> rays;
  rays.reserve(std::size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec3 d(rules::f64::camera_ray_direction(camera, x + 0.5, y + 0.5, size, size));
      rays.push_back({0, 0, 0, 0, d.x, d.y, d.z, kMiss});
    }
  return rays;
}

// From each camera ray's hit (the ceiling's), a cosine-distributed ray about
// the micro-triangle's normal facing the eye, offset as facet's paths are.
std::vector<Ray> continuationRays(const std::vector<Ray>& camera, const Traced& hits,
                                  const std::vector<ceiling::Triangle>& tris, float offset) {
  std::mt19937 random(24);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<Ray> rays;
  for (std::size_t i = 0; i < camera.size(); ++i) {
    if (!(hits.t[i] < kMiss)) continue;
    const glm::vec3 d(camera[i].directionX, camera[i].directionY, camera[i].directionZ);
    const ceiling::Triangle& tri = tris[hits.triangle[i]];
    glm::vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
    if (glm::dot(n, d) > 0) n = -n;
    const glm::vec3 origin = f32::shadow_ray_origin(d * hits.t[i], n, offset);
    const float u0 = uniform(random), u1 = uniform(random);
    const glm::vec3 l =
        glm::normalize(f32::from_local(f32::frame_from_normal(n), f32::sample_cosine_hemisphere({u0, u1})));
    rays.push_back({origin.x, origin.y, origin.z, offset, l.x, l.y, l.z, kMiss});
  }
  return rays;
}

// Rays on which `a` and `b` disagree about hit or miss, or whose distances differ by more than `relative`.
std::size_t disagreements(const Traced& a, const Traced& b, double relative) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.t.size(); ++i) {
    const bool hitA = a.t[i] < kMiss, hitB = b.t[i] < kMiss;
    n += hitA != hitB || (hitA && std::abs(a.t[i] - b.t[i]) > relative * b.t[i]);
  }
  return n;
}

WorkStats workStats(const Work& work) {
  WorkStats s;
  for (std::size_t first = 0; first < work.size(); first += kLanes) {
    std::uint32_t longest = 0;
    for (std::size_t i = first; i < std::min(work.size(), first + kLanes); ++i) {
      s.nodes += work[i][0], s.leaves += work[i][1], s.items += work[i][2];
      longest = std::max(longest, work[i][0] + work[i][1]);
    }
    s.groupSteps += double(longest) * double(std::min<std::size_t>(kLanes, work.size() - first));
  }
  s.steps = s.nodes + s.leaves;
  for (double* v : {&s.nodes, &s.leaves, &s.items, &s.steps, &s.groupSteps}) *v /= double(work.size());
  return s;
}

}  // namespace

bool runIncoherent(const Options& options) {
  const double runStart = nowMs();
  gpu::Instance instance = gpu::Instance::create(gpuInstanceFromEnvironment());
  gpu::Device device = instance.requestAdapter(gpuAdapterFromEnvironment(options.adapter)).requestDevice();
  if (device.limits().timestampPeriodNs == 0) throw std::runtime_error("the adapter cannot write timestamps");
  Report report;
  report.adapter = device.adapterInfo().name;
  report.size = options.size;
  report.repeats = options.repeats;
  report.threads = options.threads;
  bool agreed = true;
  for (const std::string& path : options.cages) {
    std::fprintf(stderr, "[%6.1f s] %s\n", (nowMs() - runStart) / 1e3, path.c_str());
    scene::Scene scene = scene::sceneFromCage(scene::loadObjCage(std::filesystem::path(FACET_SOURCE_DIR) / path));
    scene.render.width = scene.render.height = options.size;
    scene.render.method = scene::IntersectionMethod::Tessellated;
    const scene::SceneGeometry geometry = scene::buildGeometry(scene);
    const std::vector<ceiling::Triangle> tris = ceiling::dice(geometry, scene.camera.eye);
    const ceiling::Bvh4 bvh = ceiling::buildBvh4(tris);
    if (3 * bvh.depth > 64) throw std::runtime_error(path + ": the ceiling's BVH4 is too deep for its stack");
    FacetRays facet(device, scene, geometry);
    CeilingRays ceilingRays(device, bvh);
#if FACET_HAVE_EMBREE
    EmbreeTriangles embree(bvh.tris, options.threads);
#endif
    const std::vector<Ray> camera = cameraRays(scene, options.size);
    ceilingRays.setRays(camera);
    const Traced cameraHits = ceilingRays.trace();
    const std::vector<Ray> continuation = continuationRays(camera, cameraHits, bvh.tris, facet.shadowOffset());
    // The camera rays of the same paths: those that hit, in pixel order.
    const std::vector<Ray> hitting = [&] {
      std::vector<Ray> rays;
      for (std::size_t i = 0; i < camera.size(); ++i)
        if (cameraHits.t[i] < kMiss) rays.push_back(camera[i]);
      return rays;
    }();
    const int k = geometry.objects[0].refinement.tessellationRate;
    for (const auto& [name, rays] :
         {std::pair{"camera", &camera}, std::pair{"camera hits", &hitting}, std::pair{"continuation", &continuation}}) {
      std::fprintf(stderr, "[%6.1f s]   %s rays: %zu\n", (nowMs() - runStart) / 1e3, name, rays->size());
      facet.setRays(*rays);
      ceilingRays.setRays(*rays);
      Row row;
      row.scene = std::filesystem::path(path).stem().string();
      row.k = k;
      row.triangles = tris.size();
      row.rays = name;
      row.count = rays->size();
      std::vector<double> facetMs, ceilingMs, embreeMs, overCeiling, overEmbree;
      Traced f = facet.trace(), c = ceilingRays.trace();  // untimed: the JIT compiles each pipeline here
#if FACET_HAVE_EMBREE
      Traced e = embree.trace(*rays);
#endif
      for (int rep = 0; rep < options.repeats; ++rep) {
        f = facet.trace(), c = ceilingRays.trace();
        facetMs.push_back(f.ms), ceilingMs.push_back(c.ms), overCeiling.push_back(c.ms / f.ms);
#if FACET_HAVE_EMBREE
        e = embree.trace(*rays);
        embreeMs.push_back(e.ms), overEmbree.push_back(e.ms / f.ms);
#endif
      }
      std::size_t hits = 0;
      for (float t : c.t) hits += t < kMiss;
      row.hitFraction = double(hits) / double(rays->size());
      row.facetMs = median(facetMs), row.ceilingMs = median(ceilingMs);
      row.facetOverCeiling = median(overCeiling);
      row.facetVsCeiling = disagreements(f, c, 1e-2);
#if FACET_HAVE_EMBREE
      row.embreeMs = median(embreeMs), row.facetOverEmbree = median(overEmbree);
      row.embreeVsCeiling = disagreements(e, c, 1e-4);
#else
      row.embreeMs = row.facetOverEmbree = kNaN;
#endif
      row.facetWork = workStats(facet.work());
      row.ceilingWork = workStats(ceilingRays.work());
      // A few rays differ (facet fans its cells on split patch edges and
      // evaluates the grid in float on the GPU; the ceiling's triangles are
      // the plain grid from double): over 5 % is a wrong comparison.
      agreed = agreed && row.facetVsCeiling * 20 <= row.count && row.embreeVsCeiling * 20 <= row.count;
      report.rows.push_back(row);
    }
  }
  report.seconds = (nowMs() - runStart) / 1e3;
  printReport(report);
  if (!options.csvPath.empty()) writeReportCsv(options.csvPath, report);
  return agreed;
}

}  // namespace facet::benchmarks::incoherent
