#include "engine/gpu_backend/binding_table.h"

#include <utility>
#include <vector>

namespace facet::gpu_backend {

BindingTable bindingTable(const GeometryBuffers& g, const ShadingBuffers& s, const TextureBuffers& t,
                          const BandBuffers& b) {
  return {{0, &b.frame},
          {1, &g.nodes},
          {2, &g.patches},
          {3, &g.points},
          {4, &g.objects},
          {5, &g.gridVertices},
          {6, &g.edgeMidpoints},
          {7, &g.headers},
          {9, &b.hits},
          {10, &b.counters},
          {11, &s.materials},
          {12, &s.lights},
          {13, &b.aovs},
          {14, &b.shadowRays},
          {15, &b.contributions},
          {16, &g.cellBounds},
          {17, &s.compensationTables},
          {18, &b.beauty},
          {19, &s.environmentTexels},
          {20, &s.environmentLevels},
          {21, &s.environmentSampling},
          {22, &b.rayRadiance},
          {23, &s.environmentTables},
          {24, &b.cameraFallbacks},
          {25, &b.shadowFallbacks},
          {26, &g.refitOrder},
          {27, &g.normals},
          {28, &g.texcoords},
          {29, &t.texels},
          {30, &t.levels},
          {31, &t.table},
          {35, &s.sheenAlbedoRows},
          // Without paths no kernel that runs reads or writes these: they
          // name a buffer that is there, so that nothing is allocated.
          {32, b.pathStates ? &b.pathStates : &b.hits},
          {33, b.pathRays ? &b.pathRays : &b.hits},
          {34, b.livePaths ? &b.livePaths : &b.hits}};
}

gpu::BindGroup bindGroup(gpu::Device& d, const gpu::ComputePipeline& pipeline, const std::string& label,
                         const BindingTable& table) {
  gpu::BindGroupLayout groupLayout = pipeline.getBindGroupLayout(0);
  std::vector<gpu::BindGroupEntry> entries;
  for (const gpu::BindGroupLayoutEntry& entry : groupLayout.entries())
    entries.push_back({entry.binding, table.at(entry.binding)});
  return d.createBindGroup({label, &groupLayout, std::move(entries)});
}

}  // namespace facet::gpu_backend
