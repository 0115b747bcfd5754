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

#include <cstdio>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "benchmarks/ceiling/scene_measurement.h"
#include "engine/gpu/gpu.h"
#include "engine/renderer.h"

namespace {

namespace gpu = facet::gpu;
using facet::gpuAdapterFromEnvironment;
using facet::gpuInstanceFromEnvironment;
using facet::benchmarks::ceiling::kSize;
using facet::benchmarks::ceiling::measureScene;
using facet::benchmarks::ceiling::Row;

}  // namespace

int main(int argc, char** argv) {
  std::string csvPath, adapter;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--csv" && i + 1 < argc)
      csvPath = argv[++i];
    else if (arg == "--adapter" && i + 1 < argc)
      adapter = argv[++i];
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
                "dice ms", "build ms", "nodes", "depth", "node MB", "hits", "prim ms", "prim Mr/s", "shadow",
                "occluded", "shad ms", "shad Mr/s", "max rel depth", "mismatches");
    std::vector<Row> rows;
    for (const char* path : {"scenes/examples/preview.json", "scenes/cages/suzanne.obj", "scenes/cages/cube.obj"}) {
      const Row r = measureScene(device, path);
      std::printf(
          "%-28s %3s %7zu %7.1f %8.1f %6zu %5d %7.2f %6zu %7.2f %9.2f %6zu %8zu %7.2f %9.2f %13.2e %4zu/%-5zu\n",
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
             "shadow_rays,occluded,shadow_ms,shadow_mrays,checked,hit_mismatches,max_rel_depth,shadow_checked,shadow_"
             "mismatches\n";
      for (const Row& r : rows)
        csv << r.scene << ',' << r.dicing << ',' << r.triangles << ',' << r.diceMs << ',' << r.buildMs << ',' << r.nodes
            << ',' << r.depth << ',' << r.nodeBytes << ',' << r.triBytes << ',' << r.hits << ',' << r.primaryMs << ','
            << r.primaryMrays << ',' << r.shadowRays << ',' << r.occluded << ',' << r.shadowMs << ',' << r.shadowMrays
            << ',' << r.checked << ',' << r.hitMismatch << ',' << r.maxRelDepth << ',' << r.shadowChecked << ','
            << r.shadowMismatch << '\n';
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ceiling_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
