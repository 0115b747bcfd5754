#include "benchmarks/incoherent/facet_rays.h"

#include <cstddef>
#include <cstring>

#include "engine/gpu_backend/binding_table.h"
#include "engine/gpu_backend/frame_params.h"
#include "engine/gpu_backend/gpu_scene.h"
#include "engine/gpu_backend/pipeline_cache.h"
#include "engine/gpu_backend/render_buffers.h"
#include "engine/gpu_backend/shading_records.h"
#include "engine/gpu_backend/stage_clock.h"
#include "ceiling_kernels/spirv.h"
#include "engine/ibl/compensation_tables.h"
#include "rules/rules.h"

namespace facet::benchmarks::incoherent {

namespace gb = facet::gpu_backend;
namespace layout = facet::gpu_layout;
using gb::Pass;
using U = gpu::BufferUsage;

struct FacetRays::State {
  gpu::Device& d;
  gb::PipelineCache pipelines;
  layout::FrameParams frame{};
  gb::GeometryBuffers geometry;
  gb::ShadingBuffers shading;
  gb::TextureBuffers textures;
  gb::BandBuffers band;
  gb::BindingTable table;
  gpu::Buffer rays, hits, counts;
  std::size_t rayCount = 0;
  gpu::ComputePipeline* intersect = nullptr;
  gpu::ShaderModule countedModule;
  gpu::ComputePipeline counted;
  explicit State(gpu::Device& device) : d(device), pipelines(device) {}
};

FacetRays::FacetRays(gpu::Device& device, const scene::Scene& scene, const scene::SceneGeometry& geometry)
    : s_(std::make_unique<State>(device)) {
  State& s = *s_;
  if (scene.render.method != scene::IntersectionMethod::Tessellated)
    throw gpu::Error("raycast_bench --incoherent: facet's rays are traced by the tessellated method only");
  // As GpuRenderer::render: packed relative to the eye, the frame, the
  // shading tables (bound, not read by the intersect kernel), one small band.
  const gb::GpuScene packed =
      gb::packScene(scene, geometry, scene.camera.eye, gb::rootTolerance(scene, geometry), true);
  s.frame =
      gb::frameParams(scene, geometry, rules::f64::sample_strata(std::uint32_t(scene.render.samplesPerPixel)), packed);
  const ibl::CompensationTables compensation = ibl::compensationTables(scene);
  const std::vector<glm::vec4> compensationTexels = gb::compensationTexels(compensation, s.frame);
  s.geometry = gb::uploadGeometry(s.d, packed);
  s.shading =
      gb::uploadShading(s.d, scene, nullptr, gb::EnvironmentData{}, compensation, compensationTexels, scene.camera.eye);
  s.textures = gb::uploadTextures(s.d, scene.textures);
  s.band = gb::allocateBands(s.d, 1, 1, 1, 0, true);
  s.table = gb::bindingTable(s.geometry, s.shading, s.textures, s.band);
  s.d.queue().writeBuffer(s.band.frame, 0, &s.frame, sizeof(s.frame));

  // GpuRenderer's dicing stage: the micro-grid, the quadtrees, the top levels refitted.
  gb::StageClock clock(s.d);
  gpu::CommandEncoder encoder = s.d.createCommandEncoder({"dice"});
  gpu::ComputePipeline& grid = s.pipelines.get("dice_grid", {});
  clock.dispatch(encoder, Pass::DiceGrid, grid, gb::bindGroup(s.d, grid, "dice grid", s.table),
                 packed.gridVertices + packed.edgeMidpoints);
  gpu::ComputePipeline& cells = s.pipelines.get("dice_cells", {{"METHOD", 1.0}});
  clock.dispatch(encoder, Pass::DiceCells, cells, gb::bindGroup(s.d, cells, "dice cells", s.table), packed.blocks);
  gpu::ComputePipeline& quadtrees = s.pipelines.get("build_quadtrees", {});
  clock.dispatch(encoder, Pass::Quadtrees, quadtrees, gb::bindGroup(s.d, quadtrees, "quadtrees", s.table),
                 packed.patches.size());
  gpu::ComputePipeline& refit = s.pipelines.get("refit_top_levels", {});
  clock.begin(encoder, Pass::Refit, refit, gb::bindGroup(s.d, refit, "refit", s.table)).dispatchWorkgroups(1);
  s.d.queue().submit(encoder.finish());
  s.d.queue().waitIdle();

  s.intersect = &s.pipelines.get("intersect", {{"METHOD", 1.0}, {"PATHS", 1}});
  s.countedModule = s.d.createShaderModule({"facet_counted", facet::ceiling_spirv::facet_counted});
  s.counted = s.d.createComputePipeline({"facet_counted", nullptr, &s.countedModule, "main", {{"METHOD", 1.0}}});
}

FacetRays::~FacetRays() = default;

float FacetRays::shadowOffset() const { return s_->frame.shadowOffset; }

void FacetRays::setRays(const std::vector<Ray>& rays) {
  State& s = *s_;
  std::vector<layout::PathRayRecord> records(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) records[i] = {rays[i], std::uint32_t(i)};
  s.rayCount = rays.size();
  s.rays = uploadBuffer(s.d, "continuation rays", U::Storage, records.data(), records.size() * sizeof(records[0]));
  s.hits = s.d.createBuffer({"hits", rays.size() * sizeof(layout::HitRecord), U::Storage | U::CopySrc});
  // The list's length and grid, as the path loop's dispatch_args pass leaves them.
  layout::RenderCounters counters{};
  const rules::f32::uvec3 grid = rules::f32::workgroup_grid(std::uint32_t(rays.size()));
  counters.pathRays = std::uint32_t(rays.size());
  counters.pathX = grid.x, counters.pathY = grid.y, counters.pathZ = grid.z;
  s.d.queue().writeBuffer(s.band.counters, 0, &counters, sizeof counters);
  s.table[33] = &s.rays;
  s.table[9] = &s.hits;
}

Traced FacetRays::trace() {
  State& s = *s_;
  gb::StageClock clock(s.d);
  gpu::CommandEncoder encoder = s.d.createCommandEncoder({"trace list"});
  clock.begin(encoder, Pass::BounceIntersect, *s.intersect, gb::bindGroup(s.d, *s.intersect, "intersect", s.table))
      .dispatchWorkgroupsIndirect(s.band.counters, offsetof(layout::RenderCounters, pathX));
  s.d.queue().submit(encoder.finish());
  s.d.queue().waitIdle();
  Traced out;
  out.ms = clock.read(Pass::BounceIntersect, Pass::BounceIntersect);
  const std::vector<std::uint32_t> words = readBack(s.d, s.hits, s.rayCount * sizeof(layout::HitRecord));
  out.t.resize(s.rayCount);
  for (std::size_t i = 0; i < s.rayCount; ++i) {
    layout::HitRecord h;
    std::memcpy(&h, words.data() + i * (sizeof h / 4), sizeof h);
    out.t[i] = h.patchIndex == layout::FACET_NO_HIT ? kMiss : h.t;
  }
  return out;
}

Work FacetRays::work() {
  State& s = *s_;
  gpu::Buffer counts = s.d.createBuffer({"work", s.rayCount * 16, U::Storage | U::CopySrc});
  gb::BindingTable table = s.table;
  table[9] = &counts;
  gpu::CommandEncoder encoder = s.d.createCommandEncoder({"count work"});
  {
    gpu::ComputePassEncoder pass = encoder.beginComputePass({"facet counted"});
    pass.setPipeline(s.counted);
    pass.setBindGroup(0, gb::bindGroup(s.d, s.counted, "facet counted", table));
    pass.dispatchWorkgroupsIndirect(s.band.counters, offsetof(layout::RenderCounters, pathX));
  }
  return submitAndReadWork(s.d, encoder, counts, s.rayCount);
}

}  // namespace facet::benchmarks::incoherent
