// The "ceiling" for facet's GPU ray caster (not a test): the same micro-grids
// facet traverses (k x k cells of each patch's limit surface, k the scene's
// own dicing rate) as plain triangles in a binned-SAH BVH4, cast by the
// simplest fast kernels on lavapipe (ceiling.glsl). No patches, no Newton:
// whatever facet spends beyond this is the price of its representation.
//
//   ceiling_bench [--csv out.csv] [--adapter NAME]
//
// Per scene at 512²: triangles, CPU build time (median of 3), BVH size,
// camera and shadow rays per second (GPU timestamps, median of 5 after an
// untimed warm-up, so lavapipe's JIT is excluded), and a check of every 97th
// pixel against brute force in double over the same float triangles.
// Shadow Mrays/s counts the rays traced: hits facing the light.

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "ceiling_kernels/spirv.h"
#include "engine/camera/camera.h"
#include "engine/gpu/gpu.h"
#include "engine/renderer.h"
#include "engine/gpu_backend/raycast_layout.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"

namespace {

namespace gpu = facet::gpu;
using facet::gpuAdapterFromEnvironment;
using facet::gpuInstanceFromEnvironment;
using glm::dvec3;
using glm::vec3;

constexpr int kSize = 512;
constexpr int kCheckStride = 97;
// facet's node layout (compute/layout/wide_bvh.h), which the kernels test
// with facet's own node code; leaves reference triangle ranges instead of cells.
namespace gpu_layout = facet::gpu_layout;
constexpr std::size_t kNodeTexels = gpu_layout::FACET_BVH4_TEXELS;
constexpr std::uint32_t kLeaf = 0x80000000u, kEmpty = gpu_layout::FACET_BVH4_EMPTY;
constexpr int kMaxLeaf = 4, kBins = 16, kStack = 64;  // kStack: ceiling.glsl's STACK
constexpr float kInf = std::numeric_limits<float>::infinity();

double nowMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Triangle {
  vec3 a, b, c;
};

// Each patch's (k+1)² limit points, two triangles per cell, relative to the eye.
std::vector<Triangle> dice(const facet::scene::SceneGeometry& geometry, dvec3 eye) {
  std::vector<Triangle> out;
  std::vector<vec3> grid;
  for (const facet::scene::ObjectGeometry& object : geometry.objects) {
    const int k = object.refinement.tessellationRate;
    for (int patch = 0; patch < object.surface.patchCount(); ++patch) {
      const facet::scene::PatchDomain& domain = object.surface.patch(patch).domain;
      grid.clear();
      for (int j = 0; j <= k; ++j)
        for (int i = 0; i <= k; ++i)
          grid.push_back(vec3(object.surface.evaluatePatch(patch, domain.u0 + domain.size * i / k,
                                                           domain.v0 + domain.size * j / k).position - eye));
      for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
          const vec3 &c00 = grid[j * (k + 1) + i], &c10 = grid[j * (k + 1) + i + 1];
          const vec3 &c01 = grid[(j + 1) * (k + 1) + i], &c11 = grid[(j + 1) * (k + 1) + i + 1];
          out.push_back({c00, c10, c11});
          out.push_back({c00, c11, c01});
        }
    }
  }
  return out;
}

// ---------------------------------------------------------------- BVH

struct Box {
  vec3 lo{kInf}, hi{-kInf};
  void extend(vec3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
  void extend(const Box& b) { lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi); }
  float area() const {
    const vec3 e = glm::max(hi - lo, vec3(0.0f));
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
};

struct BinaryNode {
  Box box;
  int left = -1, right = -1;  // -1: a leaf of triangles [first, first + count) of the order
  int first = 0, count = 0;
};

// Binned SAH over centroids, every axis, a traversal step costing as much as
// one triangle test. Leaves of up to 4 triangles: 8 gave the same trees here.
struct BinaryBuilder {
  std::vector<Box> boxes;
  std::vector<vec3> centroids;
  std::vector<int> order;
  std::vector<BinaryNode> nodes;

  explicit BinaryBuilder(const std::vector<Triangle>& t) : boxes(t.size()), centroids(t.size()), order(t.size()) {
    for (std::size_t i = 0; i < t.size(); ++i) {
      boxes[i].extend(t[i].a), boxes[i].extend(t[i].b), boxes[i].extend(t[i].c);
      centroids[i] = 0.5f * (boxes[i].lo + boxes[i].hi);
      order[i] = int(i);
    }
    nodes.reserve(2 * t.size());
    build(0, int(t.size()));
  }

  int build(int first, int count) {
    const int index = int(nodes.size());
    nodes.push_back({});
    Box box, centres;
    for (int i = first; i < first + count; ++i) box.extend(boxes[order[i]]), centres.extend(centroids[order[i]]);
    nodes[index].box = box;
    float bestCost = std::numeric_limits<float>::max();
    int bestAxis = -1, bestBin = 0;
    for (int axis = 0; axis < 3 && count > 1; ++axis) {
      const float lo = centres.lo[axis], extent = centres.hi[axis] - lo;
      if (!(extent > 0)) continue;
      std::array<Box, kBins> bins;
      std::array<int, kBins> counts{};
      for (int i = first; i < first + count; ++i) {
        const int b = std::min(kBins - 1, int(kBins * (centroids[order[i]][axis] - lo) / extent));
        bins[b].extend(boxes[order[i]]), ++counts[b];
      }
      std::array<float, kBins> rightCost{};
      Box acc;
      for (int b = kBins - 1, n = 0; b > 0; --b) acc.extend(bins[b]), n += counts[b], rightCost[b] = n * acc.area();
      acc = Box{};
      for (int b = 0, n = 0; b < kBins - 1; ++b) {
        acc.extend(bins[b]), n += counts[b];
        const float cost = n * acc.area() + rightCost[b + 1];
        if (n > 0 && n < count && cost < bestCost) bestCost = cost, bestAxis = axis, bestBin = b;
      }
    }
    const float leafCost = float(count) * box.area(), splitCost = box.area() + bestCost;
    if (count == 1 || (count <= kMaxLeaf && leafCost <= splitCost) || (bestAxis < 0 && count <= kMaxLeaf)) {
      nodes[index].first = first, nodes[index].count = count;
      return index;
    }
    int middle = first + count / 2;  // all centroids equal: split the list
    if (bestAxis >= 0) {
      const float lo = centres.lo[bestAxis], extent = centres.hi[bestAxis] - lo;
      middle = int(std::partition(order.begin() + first, order.begin() + first + count, [&](int t) {
                     return std::min(kBins - 1, int(kBins * (centroids[t][bestAxis] - lo) / extent)) <= bestBin;
                   }) - order.begin());
    }
    const int left = build(first, middle - first);
    const int right = build(middle, first + count - middle);
    nodes[index].left = left, nodes[index].right = right;
    return index;
  }
};

struct Bvh4 {
  std::vector<std::array<std::uint32_t, 4>> nodeTexels;  // kNodeTexels per node
  std::vector<glm::vec4> triTexels;                      // 3 per triangle, in leaf order
  std::vector<Triangle> tris;                            // the same, for the CPU check
  int depth = 0;
  std::size_t nodeCount() const { return nodeTexels.size() / kNodeTexels; }
};

// The binary tree collapsed to 4-wide: a node adopts its children, then
// keeps opening the largest inner one until it has four.
struct Collapser {
  const BinaryBuilder& binary;
  Bvh4& out;

  std::uint32_t reference(int b, int depth) {
    const BinaryNode& n = binary.nodes[b];
    if (n.left < 0) return kLeaf | std::uint32_t(n.count - 1) << 27 | std::uint32_t(n.first);
    return wide({n.left, n.right}, depth);
  }

  std::uint32_t wide(std::vector<int> children, int depth) {
    out.depth = std::max(out.depth, depth);
    while (children.size() < 4) {
      int open = -1;
      for (int c = 0; c < int(children.size()); ++c) {
        const BinaryNode& n = binary.nodes[children[c]];
        if (n.left >= 0 && (open < 0 || n.box.area() > binary.nodes[children[open]].box.area())) open = c;
      }
      if (open < 0) break;
      const BinaryNode& n = binary.nodes[children[open]];
      children[open] = n.left;
      children.push_back(n.right);
    }
    const std::size_t index = out.nodeCount();
    out.nodeTexels.resize(out.nodeTexels.size() + kNodeTexels, {0, 0, 0, 0});
    std::array<std::uint32_t, 4> refs{kEmpty, kEmpty, kEmpty, kEmpty};
    for (std::size_t c = 0; c < children.size(); ++c) {
      const Box& box = binary.nodes[children[c]].box;
      for (int axis = 0; axis < 3; ++axis) {
        out.nodeTexels[index * kNodeTexels + 2 * axis][c] = std::bit_cast<std::uint32_t>(box.lo[axis]);
        out.nodeTexels[index * kNodeTexels + 2 * axis + 1][c] = std::bit_cast<std::uint32_t>(box.hi[axis]);
      }
      refs[c] = reference(children[c], depth + 1);
    }
    out.nodeTexels[index * kNodeTexels + gpu_layout::FACET_BVH4_REFERENCES] = refs;
    return std::uint32_t(index);
  }
};

Bvh4 buildBvh4(const std::vector<Triangle>& tris) {
  const BinaryBuilder binary(tris);
  Bvh4 out;
  const BinaryNode& root = binary.nodes[0];
  Collapser{binary, out}.wide(root.left < 0 ? std::vector<int>{0} : std::vector<int>{root.left, root.right}, 1);
  for (int t : binary.order) {
    const Triangle& tri = tris[t];
    out.tris.push_back(tri);
    out.triTexels.insert(out.triTexels.end(), {glm::vec4(tri.a, 0), glm::vec4(tri.b - tri.a, 0), glm::vec4(tri.c - tri.a, 0)});
  }
  return out;
}

// ---------------------------------------------------------------- CPU reference

// Möller-Trumbore in double over the float vertices: t in (0, tMax), else inf.
double intersect(const Triangle& tri, dvec3 o, dvec3 d, double tMax) {
  const dvec3 v0(tri.a), e1 = dvec3(tri.b) - v0, e2 = dvec3(tri.c) - v0;
  const dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (det == 0) return kInf;
  const dvec3 s = o - v0, q = glm::cross(s, e1);
  const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det, t = glm::dot(e2, q) / det;
  return (u >= 0 && v >= 0 && u + v <= 1 && t > 0 && t < tMax) ? t : kInf;
}

double bruteForce(const std::vector<Triangle>& tris, dvec3 o, dvec3 d, double tMax, bool anyHit) {
  double best = kInf;
  for (const Triangle& tri : tris) {
    best = std::min(best, intersect(tri, o, d, std::min(best, tMax)));
    if (anyHit && best < kInf) break;
  }
  return best;
}

// ---------------------------------------------------------------- GPU

struct FrameBlock {  // ceiling.glsl's Frame, std140
  glm::vec4 forward, right, up, light, screen;
};

double dispatchNs(gpu::Device& device, const gpu::ComputePipeline& pipeline, const gpu::BindGroup& group,
                  const gpu::QuerySet& queries) {
  gpu::CommandEncoder encoder = device.createCommandEncoder();
  {
    gpu::ComputePassEncoder pass = encoder.beginComputePass({"ceiling", {&queries, 0, 1}});
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups(kSize * kSize / 64);
  }
  device.queue().submit(encoder.finish());
  device.queue().waitIdle();
  const std::vector<double> ns = queries.readTimestampsNs(0, 2);
  return ns[1] - ns[0];
}

// The median of 5 timed dispatches after one untimed (the JIT compiles the pipeline there).
double medianNs(gpu::Device& device, const gpu::ComputePipeline& pipeline, const gpu::BindGroup& group,
                const gpu::QuerySet& queries) {
  dispatchNs(device, pipeline, group, queries);
  std::vector<double> ns;
  for (int i = 0; i < 5; ++i) ns.push_back(dispatchNs(device, pipeline, group, queries));
  return median(ns);
}

gpu::Buffer upload(gpu::Device& device, const char* label, gpu::BufferUsage usage, const void* data, std::size_t bytes) {
  gpu::Buffer buffer = device.createBuffer({label, bytes, usage | gpu::BufferUsage::CopyDst});
  device.queue().writeBuffer(buffer, 0, data, bytes);
  return buffer;
}

struct Row {
  std::string scene, dicing;
  std::size_t triangles = 0, nodes = 0, nodeBytes = 0, triBytes = 0, hits = 0, shadowRays = 0, occluded = 0;
  int depth = 0;
  double diceMs = 0, buildMs = 0, primaryMs = 0, primaryMrays = 0, shadowMs = 0, shadowMrays = 0;
  std::size_t checked = 0, hitMismatch = 0, shadowChecked = 0, shadowMismatch = 0;
  double maxRelDepth = 0;
};

Row run(gpu::Device& device, const std::string& path) {
  Row row;
  row.scene = path;
  facet::scene::Scene scene = facet::scene::loadScene(std::string(FACET_SOURCE_DIR) + "/" + path);
  scene.render.width = scene.render.height = kSize;  // dicing rates as facet chooses them at 512²
  const facet::scene::SceneGeometry geometry = facet::scene::buildGeometry(scene);
  int kMin = 64, kMax = 1;
  for (const auto& o : geometry.objects)
    kMin = std::min(kMin, o.refinement.tessellationRate), kMax = std::max(kMax, o.refinement.tessellationRate);
  row.dicing = kMin == kMax ? std::to_string(kMin) : std::to_string(kMin) + "-" + std::to_string(kMax);

  const dvec3 eye = scene.camera.eye;
  double start = nowMs();
  const std::vector<Triangle> tris = dice(geometry, eye);
  row.diceMs = nowMs() - start;
  std::vector<double> buildMs;
  Bvh4 bvh;
  for (int i = 0; i < 3; ++i) {
    start = nowMs();
    bvh = buildBvh4(tris);
    buildMs.push_back(nowMs() - start);
  }
  if (3 * bvh.depth > kStack) throw std::runtime_error(path + ": BVH4 too deep for the kernels' stack");
  row.triangles = tris.size(), row.buildMs = median(buildMs), row.nodes = bvh.nodeCount(), row.depth = bvh.depth;
  row.nodeBytes = bvh.nodeTexels.size() * 16, row.triBytes = bvh.triTexels.size() * 16;

  // A point light: the scene's own, else one along its first light's direction, two diagonals out.
  const double diagonal = geometry.bounds.diagonal();
  dvec3 light = geometry.bounds.centre() + dvec3(0, 2 * diagonal, 0);
  if (!scene.lights.empty()) {
    const facet::scene::Light& l = scene.lights[0];
    light = l.type == facet::scene::LightType::Directional
                ? geometry.bounds.centre() - 2 * diagonal * glm::normalize(l.direction)
                : l.position;
  }
  const facet::rules::f64::CameraFrame camera = facet::camera::cameraFrame(scene.camera, kSize, kSize);
  const float shadowOffset = float(1e-4 * diagonal);
  const FrameBlock frame{glm::vec4(vec3(camera.forward), 0), glm::vec4(vec3(camera.right), 0),
                         glm::vec4(vec3(camera.up), 0), glm::vec4(vec3(light - eye), shadowOffset),
                         glm::vec4(kSize, kSize, camera.tanHalfFovY * camera.aspect, camera.tanHalfFovY)};

  using U = gpu::BufferUsage;
  const std::size_t pixels = std::size_t(kSize) * kSize;
  gpu::Buffer frameBuffer = upload(device, "frame", U::Uniform, &frame, sizeof frame);
  gpu::Buffer nodes = upload(device, "nodes", U::Texel, bvh.nodeTexels.data(), row.nodeBytes);
  gpu::Buffer triBuffer = upload(device, "tris", U::Texel, bvh.triTexels.data(), row.triBytes);
  gpu::Buffer hits = device.createBuffer({"hits", pixels * 8, U::Storage | U::CopySrc});
  gpu::Buffer shadow = device.createBuffer({"shadow", pixels * 4, U::Storage | U::CopySrc});
  gpu::Buffer readback = device.createBuffer({"readback", pixels * 12, U::MapRead | U::CopyDst});
  gpu::QuerySet queries = device.createQuerySet({"ceiling", 2});

  gpu::ShaderModule closestModule = device.createShaderModule({"closest_hit", facet::ceiling_spirv::closest_hit});
  gpu::ShaderModule anyModule = device.createShaderModule({"any_hit", facet::ceiling_spirv::any_hit});
  gpu::ComputePipeline closest = device.createComputePipeline({"closest_hit", nullptr, &closestModule});
  gpu::ComputePipeline any = device.createComputePipeline({"any_hit", nullptr, &anyModule});
  gpu::BindGroupLayout closestLayout = closest.getBindGroupLayout(0), anyLayout = any.getBindGroupLayout(0);
  gpu::BindGroup closestGroup = device.createBindGroup(
      {"closest_hit", &closestLayout, {{0, &frameBuffer}, {1, &nodes}, {2, &triBuffer}, {3, &hits}}});
  gpu::BindGroup anyGroup = device.createBindGroup(
      {"any_hit", &anyLayout, {{0, &frameBuffer}, {1, &nodes}, {2, &triBuffer}, {3, &hits}, {4, &shadow}}});

  const double primaryNs = medianNs(device, closest, closestGroup, queries);
  const double shadowNs = medianNs(device, any, anyGroup, queries);
  gpu::CommandEncoder encoder = device.createCommandEncoder();
  encoder.copyBufferToBuffer(hits, 0, readback, 0, pixels * 8);
  encoder.copyBufferToBuffer(shadow, 0, readback, pixels * 8, pixels * 4);
  device.queue().submit(encoder.finish());
  device.queue().waitIdle();
  const std::span<const std::uint32_t> out = readback.mapped<const std::uint32_t>();
  auto hitT = [&](std::size_t p) { return std::bit_cast<float>(out[2 * p]); };
  auto hitTri = [&](std::size_t p) { return out[2 * p + 1]; };
  auto shadowCode = [&](std::size_t p) { return out[2 * pixels + p]; };
  for (std::size_t p = 0; p < pixels; ++p) {
    row.hits += hitTri(p) != kEmpty;
    row.shadowRays += shadowCode(p) >= 2;
    row.occluded += shadowCode(p) == 3;
  }
  row.primaryMs = primaryNs * 1e-6, row.shadowMs = shadowNs * 1e-6;
  row.primaryMrays = double(pixels) / primaryNs * 1e3;
  row.shadowMrays = double(row.shadowRays) / shadowNs * 1e3;

  // Camera rays in double; shadow rays start where the kernel's do (same
  // float arithmetic), so a mismatch there is the traversal's, not the offset's.
  facet::rules::f64::CameraFrame relative = camera;
  relative.eye = dvec3(0);
  const vec3 lightF = vec3(light - eye);
  for (std::size_t p = 0; p < pixels; p += kCheckStride) {
    const dvec3 d = facet::rules::f64::camera_ray_direction(relative, double(p % kSize) + 0.5, double(p / kSize) + 0.5,
                                                        kSize, kSize);
    const double reference = bruteForce(bvh.tris, dvec3(0), d, kInf, false);
    ++row.checked;
    if ((reference < kInf) != (hitTri(p) != kEmpty)) ++row.hitMismatch;
    else if (reference < kInf) row.maxRelDepth = std::max(row.maxRelDepth, std::abs(hitT(p) - reference) / reference);
    if (shadowCode(p) < 2) continue;
    const float w = frame.screen.x, h = frame.screen.y;
    const float sx = (2.0f * (float(p % kSize) + 0.5f) / w - 1.0f) * frame.screen.z;
    const float sy = (1.0f - 2.0f * (float(p / kSize) + 0.5f) / h) * frame.screen.w;
    const vec3 df = glm::normalize(vec3(frame.forward) + sx * vec3(frame.right) + sy * vec3(frame.up));
    const Triangle& tri = bvh.tris[hitTri(p)];
    vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
    if (glm::dot(n, df) > 0) n = -n;
    const vec3 o = df * hitT(p) + n * shadowOffset;
    const dvec3 toLight = dvec3(lightF - o);
    const double distance = glm::length(toLight);
    const bool occluded = bruteForce(bvh.tris, dvec3(o), toLight / distance, distance, true) < kInf;
    ++row.shadowChecked;
    row.shadowMismatch += occluded != (shadowCode(p) == 3);
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  std::string csvPath, adapter;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--csv" && i + 1 < argc) csvPath = argv[++i];
    else if (arg == "--adapter" && i + 1 < argc) adapter = argv[++i];
    else {
      std::fprintf(stderr, "usage: ceiling_bench [--csv FILE] [--adapter NAME]\n");
      return 2;
    }
  }
  try {
    gpu::Instance instance = gpu::Instance::create(gpuInstanceFromEnvironment());
    gpu::Device device = instance.requestAdapter(gpuAdapterFromEnvironment(adapter)).requestDevice();
    if (device.limits().timestampPeriodNs == 0) throw std::runtime_error("the adapter cannot write timestamps");
    std::printf("ceiling: triangle BVH4 on %s, %dx%d, 1 ray per pixel\n", device.adapterInfo().name.c_str(), kSize,
                kSize);
    std::printf("%-28s %3s %7s %7s %8s %6s %5s %7s %6s %7s %9s %6s %8s %7s %9s %13s %10s\n", "scene", "k", "tris",
                "dice ms", "build ms", "nodes", "depth", "node MB", "hits", "prim ms", "prim Mr/s", "shadow", "occluded",
                "shad ms", "shad Mr/s", "max rel depth", "mismatches");
    std::vector<Row> rows;
    for (const char* path : {"scenes/examples/preview.json", "scenes/cages/suzanne.obj", "scenes/cages/cube.obj"}) {
      const Row r = run(device, path);
      std::printf("%-28s %3s %7zu %7.1f %8.1f %6zu %5d %7.2f %6zu %7.2f %9.2f %6zu %8zu %7.2f %9.2f %13.2e %4zu/%-5zu\n",
                  r.scene.c_str(), r.dicing.c_str(), r.triangles, r.diceMs, r.buildMs, r.nodes, r.depth,
                  r.nodeBytes / 1048576.0, r.hits, r.primaryMs, r.primaryMrays, r.shadowRays, r.occluded, r.shadowMs,
                  r.shadowMrays, r.maxRelDepth, r.hitMismatch, r.shadowMismatch);
      std::printf("  checked %zu camera rays (hit/miss mismatches %zu), %zu shadow rays (mismatches %zu)\n", r.checked,
                  r.hitMismatch, r.shadowChecked, r.shadowMismatch);
      std::fflush(stdout);
      rows.push_back(r);
    }
    if (!csvPath.empty()) {
      std::ofstream csv(csvPath);
      csv << "scene,dicing,triangles,dice_ms,build_ms,nodes,depth,node_bytes,tri_bytes,hits,primary_ms,primary_mrays,"
             "shadow_rays,occluded,shadow_ms,shadow_mrays,checked,hit_mismatches,max_rel_depth,shadow_checked,shadow_mismatches\n";
      for (const Row& r : rows)
        csv << r.scene << ',' << r.dicing << ',' << r.triangles << ',' << r.diceMs << ',' << r.buildMs << ',' << r.nodes
            << ',' << r.depth << ',' << r.nodeBytes << ',' << r.triBytes << ',' << r.hits << ',' << r.primaryMs << ',' << r.primaryMrays
            << ',' << r.shadowRays << ',' << r.occluded << ',' << r.shadowMs << ',' << r.shadowMrays << ',' << r.checked << ','
            << r.hitMismatch << ',' << r.maxRelDepth << ',' << r.shadowChecked << ',' << r.shadowMismatch << '\n';
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ceiling_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
