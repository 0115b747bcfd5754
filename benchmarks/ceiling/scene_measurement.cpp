#include "benchmarks/ceiling/scene_measurement.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "benchmarks/ceiling/brute_force.h"
#include "benchmarks/ceiling/micro_grid_triangles.h"
#include "benchmarks/ceiling/triangle_bvh4.h"
#include "benchmarks/wall_clock.h"
#include "ceiling_kernels/spirv.h"
#include "engine/camera/camera.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"

namespace facet::benchmarks::ceiling {
namespace {

namespace gpu = facet::gpu;
using glm::dvec3;
using glm::vec3;

constexpr int kCheckStride = 97;
constexpr int kStack = 64;  // ceiling.glsl's STACK

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

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

gpu::Buffer upload(gpu::Device& device, const char* label, gpu::BufferUsage usage, const void* data,
                   std::size_t bytes) {
  gpu::Buffer buffer = device.createBuffer({label, bytes, usage | gpu::BufferUsage::CopyDst});
  device.queue().writeBuffer(buffer, 0, data, bytes);
  return buffer;
}

// A point light: the scene's own, else one along its first light's direction, two diagonals out.
dvec3 pointLight(const facet::scene::Scene& scene, const facet::scene::SceneGeometry& geometry) {
  const double diagonal = geometry.bounds.diagonal();
  dvec3 light = geometry.bounds.centre() + dvec3(0, 2 * diagonal, 0);
  if (!scene.lights.empty()) {
    const facet::scene::Light& l = scene.lights[0];
    light = l.type == facet::scene::LightType::Directional
                ? geometry.bounds.centre() - 2 * diagonal * glm::normalize(l.direction)
                : l.position;
  }
  return light;
}

// What the kernels wrote: per pixel the closest hit's (t, triangle), then
// per pixel the shadow ray's code.
struct KernelResults {
  std::span<const std::uint32_t> out;
  std::size_t pixels;
  float hitT(std::size_t p) const { return std::bit_cast<float>(out[2 * p]); }
  std::uint32_t hitTri(std::size_t p) const { return out[2 * p + 1]; }
  std::uint32_t shadowCode(std::size_t p) const { return out[2 * pixels + p]; }
};

// Every kCheckStride-th pixel's hit and shadow ray against brute force over
// `tris`, counted in row; `lightF` is the light relative to the eye.
void checkAgainstBruteForce(Row& row, const KernelResults& results, const std::vector<Triangle>& tris,
                            const facet::rules::f64::CameraFrame& camera, const FrameBlock& frame, const vec3& lightF,
                            float shadowOffset) {
  // Camera rays in double; shadow rays start where the kernel's do (same
  // float arithmetic), so a mismatch there is the traversal's, not the offset's.
  facet::rules::f64::CameraFrame relative = camera;
  relative.eye = dvec3(0);
  for (std::size_t p = 0; p < results.pixels; p += kCheckStride) {
    const dvec3 d = facet::rules::f64::camera_ray_direction(relative, double(p % kSize) + 0.5, double(p / kSize) + 0.5,
                                                            kSize, kSize);
    const double reference = bruteForce(tris, dvec3(0), d, kInf, false);
    ++row.checked;
    if ((reference < kInf) != (results.hitTri(p) != kEmpty))
      ++row.hitMismatch;
    else if (reference < kInf)
      row.maxRelDepth = std::max(row.maxRelDepth, std::abs(results.hitT(p) - reference) / reference);
    if (results.shadowCode(p) < 2) continue;
    const float w = frame.screen.x, h = frame.screen.y;
    const float sx = (2.0f * (float(p % kSize) + 0.5f) / w - 1.0f) * frame.screen.z;
    const float sy = (1.0f - 2.0f * (float(p / kSize) + 0.5f) / h) * frame.screen.w;
    const vec3 df = glm::normalize(vec3(frame.forward) + sx * vec3(frame.right) + sy * vec3(frame.up));
    const Triangle& tri = tris[results.hitTri(p)];
    vec3 n = glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a));
    if (glm::dot(n, df) > 0) n = -n;
    const vec3 o = df * results.hitT(p) + n * shadowOffset;
    const dvec3 toLight = dvec3(lightF - o);
    const double distance = glm::length(toLight);
    const bool occluded = bruteForce(tris, dvec3(o), toLight / distance, distance, true) < kInf;
    ++row.shadowChecked;
    row.shadowMismatch += occluded != (results.shadowCode(p) == 3);
  }
}

}  // namespace

Row measureScene(gpu::Device& device, const std::string& path) {
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

  const double diagonal = geometry.bounds.diagonal();
  const dvec3 light = pointLight(scene, geometry);
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
  const KernelResults results{readback.mapped<const std::uint32_t>(), pixels};
  for (std::size_t p = 0; p < pixels; ++p) {
    row.hits += results.hitTri(p) != kEmpty;
    row.shadowRays += results.shadowCode(p) >= 2;
    row.occluded += results.shadowCode(p) == 3;
  }
  row.primaryMs = primaryNs * 1e-6, row.shadowMs = shadowNs * 1e-6;
  row.primaryMrays = double(pixels) / primaryNs * 1e3;
  row.shadowMrays = double(row.shadowRays) / shadowNs * 1e3;

  checkAgainstBruteForce(row, results, bvh.tris, camera, frame, vec3(light - eye), shadowOffset);
  return row;
}

}  // namespace facet::benchmarks::ceiling
