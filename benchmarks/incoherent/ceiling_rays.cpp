#include "benchmarks/incoherent/ceiling_rays.h"

#include <glm/vec4.hpp>

#include <bit>
#include <map>

#include "ceiling_kernels/spirv.h"

namespace facet::benchmarks::incoherent {

using U = gpu::BufferUsage;

struct CeilingRays::State {
  gpu::Device& d;
  gpu::Buffer frame, nodes, tris, rays, hits;
  std::size_t rayCount = 0;
  gpu::ShaderModule module, countedModule;
  gpu::ComputePipeline pipeline, counted;
  gpu::QuerySet queries;
  explicit State(gpu::Device& device) : d(device) {}

  gpu::BindGroup group(const gpu::ComputePipeline& p, const std::map<std::uint32_t, const gpu::Buffer*>& buffers) {
    gpu::BindGroupLayout groupLayout = p.getBindGroupLayout(0);
    std::vector<gpu::BindGroupEntry> entries;
    for (const gpu::BindGroupLayoutEntry& entry : groupLayout.entries())
      entries.push_back({entry.binding, buffers.at(entry.binding)});
    return d.createBindGroup({"ceiling rays", &groupLayout, std::move(entries)});
  }
};

CeilingRays::CeilingRays(gpu::Device& device, const ceiling::Bvh4& bvh) : s_(std::make_unique<State>(device)) {
  State& s = *s_;
  s.nodes = uploadBuffer(s.d, "nodes", U::Texel, bvh.nodeTexels.data(), bvh.nodeTexels.size() * 16);
  s.tris = uploadBuffer(s.d, "tris", U::Texel, bvh.triTexels.data(), bvh.triTexels.size() * 16);
  s.module = s.d.createShaderModule({"closest_hit_rays", facet::ceiling_spirv::closest_hit_rays});
  s.countedModule =
      s.d.createShaderModule({"closest_hit_rays_counted", facet::ceiling_spirv::closest_hit_rays_counted});
  s.pipeline = s.d.createComputePipeline({"closest_hit_rays", nullptr, &s.module});
  s.counted = s.d.createComputePipeline({"closest_hit_rays_counted", nullptr, &s.countedModule});
  s.queries = s.d.createQuerySet({"ceiling rays", 2});
}

CeilingRays::~CeilingRays() = default;

void CeilingRays::setRays(const std::vector<Ray>& rays) {
  State& s = *s_;
  s.rayCount = rays.size();
  // ceiling.glsl's Frame: only screen.x, the list's length, is read.
  const glm::vec4 frame[5] = {{}, {}, {}, {}, {float(rays.size()), 1, 0, 0}};
  s.frame = uploadBuffer(s.d, "frame", U::Uniform, frame, sizeof frame);
  s.rays = uploadBuffer(s.d, "rays", U::Storage, rays.data(), rays.size() * sizeof(Ray));
  s.hits = s.d.createBuffer({"hits", rays.size() * 8, U::Storage | U::CopySrc});
}

Traced CeilingRays::trace() {
  State& s = *s_;
  gpu::CommandEncoder encoder = s.d.createCommandEncoder({"ceiling rays"});
  {
    gpu::ComputePassEncoder pass = encoder.beginComputePass({"ceiling rays", {&s.queries, 0, 1}});
    pass.setPipeline(s.pipeline);
    pass.setBindGroup(0, s.group(s.pipeline, {{0, &s.frame}, {1, &s.nodes}, {2, &s.tris}, {3, &s.rays}, {4, &s.hits}}));
    pass.dispatchWorkgroups(std::uint32_t((s.rayCount + 63) / 64));
  }
  s.d.queue().submit(encoder.finish());
  s.d.queue().waitIdle();
  const std::vector<double> ns = s.queries.readTimestampsNs(0, 2);
  Traced out;
  out.ms = (ns[1] - ns[0]) * 1e-6;
  const std::vector<std::uint32_t> words = readBack(s.d, s.hits, s.rayCount * 8);
  out.t.resize(s.rayCount);
  out.triangle.resize(s.rayCount);
  for (std::size_t i = 0; i < s.rayCount; ++i) {
    out.triangle[i] = words[2 * i + 1];
    out.t[i] = out.triangle[i] == ceiling::kEmpty ? kMiss : std::bit_cast<float>(words[2 * i]);
  }
  return out;
}

Work CeilingRays::work() {
  State& s = *s_;
  gpu::Buffer counts = s.d.createBuffer({"work", s.rayCount * 16, U::Storage | U::CopySrc});
  gpu::CommandEncoder encoder = s.d.createCommandEncoder({"ceiling work"});
  {
    gpu::ComputePassEncoder pass = encoder.beginComputePass({"ceiling counted"});
    pass.setPipeline(s.counted);
    pass.setBindGroup(
        0, s.group(s.counted, {{0, &s.frame}, {1, &s.nodes}, {2, &s.tris}, {3, &s.rays}, {4, &s.hits}, {5, &counts}}));
    pass.dispatchWorkgroups(std::uint32_t((s.rayCount + 63) / 64));
  }
  return submitAndReadWork(s.d, encoder, counts, s.rayCount);
}

}  // namespace facet::benchmarks::incoherent
