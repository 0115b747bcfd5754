// The ray-casting benchmark (not a test): facet's GPU path (lavapipe)
// and double-precision CPU reference, exact and tessellated methods, on cages
// from 6 to ~100k patches at 512² and 1024², against Embree 3's subdivision
// geometry (when found at build time) at equal depth error.
//
//   raycast_bench [--quick] [--csv out.csv] [--adapter NAME]
//   raycast_bench --incoherent [--quick] [--cage OBJ]... [--size N] [--repeats N] [--csv out.csv]
//                 [--adapter NAME]
//
// --incoherent: secondary (continuation) rays against the ceiling kernel and
// Embree on the same rays (incoherent/incoherent_bench.h, issue 24); --quick
// there is the cube at 64².
//
// Every scene is a bare cage framed by sceneFromCage (default camera, default
// key light, default refinement choice). Depth errors are those of
// analysis/image_compare.h, against facet's CPU exact depth image. Results
// and method: BENCHMARKS.md.

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "benchmarks/incoherent/incoherent_bench.h"
#include "benchmarks/raycast_measure.h"
#include "benchmarks/raycast_report.h"
#include "benchmarks/uniform_refinement.h"
#include "engine/renderer.h"
#include "scenes/obj_cage.h"

namespace {

namespace raycast = facet::benchmarks::raycast;
using facet::benchmarks::refineUniformly;
using facet::scene::ControlCage;
using raycast::NamedCage;

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, incoherent = false;
  int size = 512, repeats = 11;
  std::string csvPath, adapter;
  std::vector<std::string> cages;  // --incoherent: OBJ cages relative to the source tree
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      quick = true;
    } else if (a == "--incoherent") {
      incoherent = true;
    } else if (a == "--cage" && i + 1 < argc) {
      cages.push_back(argv[++i]);
    } else if (a == "--size" && i + 1 < argc) {
      size = std::stoi(argv[++i]);
    } else if (a == "--repeats" && i + 1 < argc) {
      repeats = std::stoi(argv[++i]);
    } else if (a == "--csv" && i + 1 < argc) {
      csvPath = argv[++i];
    } else if (a == "--adapter" && i + 1 < argc) {
      adapter = argv[++i];
    } else {
      std::fprintf(
          stderr,
          "usage: raycast_bench [--quick] [--csv out.csv] [--adapter NAME]\n"
          "       raycast_bench --incoherent [--quick] [--cage OBJ]... [--size N] [--repeats N] [--csv out.csv] "
          "[--adapter NAME]\n");
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  try {
    if (incoherent) {
      facet::benchmarks::incoherent::Options options;
      options.cages = !cages.empty() ? cages
                      : quick        ? std::vector<std::string>{"scenes/cages/cube.obj"}
                                     : std::vector<std::string>{"scenes/cages/newell_teacup.obj",
                                                                "scenes/cages/chess_pawn.obj", "scenes/cages/suzanne.obj"};
      options.size = quick ? 64 : size;
      options.repeats = quick ? 3 : repeats;
      options.threads = raycast::kThreads;
      options.adapter = adapter;
      options.csvPath = csvPath;
      if (facet::benchmarks::incoherent::runIncoherent(options)) return 0;
      std::fprintf(stderr, "raycast_bench: over 5%% of the rays' hits differ between contestants (see the table)\n");
      return 1;
    }
    const std::filesystem::path root = FACET_SOURCE_DIR;
    facet::Renderer renderer(adapter);
    std::vector<NamedCage> cages;
    cages.push_back({"cube", facet::scene::loadObjCage(root / "scenes/cages/cube.obj")});
    if (!quick) {
      cages.push_back({"superball", facet::scene::loadObjCage(root / "scenes/examples/superball.obj")});
      const ControlCage suzanne = facet::scene::loadObjCage(root / "scenes/cages/suzanne.obj");
      cages.push_back({"suzanne", suzanne});
      cages.push_back({"suzanne L1", refineUniformly(suzanne, 1)});
      cages.push_back({"suzanne L2", refineUniformly(suzanne, 2)});
      cages.push_back({"suzanne L3", refineUniformly(suzanne, 3)});
    }
    const std::vector<int> sizes = quick ? std::vector<int>{64} : std::vector<int>{512, 1024};
    // Embree's tessellation rate: segments per cage edge, so ~faces × rate² grid
    // quads in memory. Rates past kEmbreeGridBudget (~2 GB) are left out (said in the output).
    const std::vector<int> allRates =
        quick ? std::vector<int>{1, 4, 16} : std::vector<int>{1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024};
    const raycast::Measurements run = raycast::measureAll(renderer, cages, sizes, allRates, quick);
    raycast::printTables(run, quick);

    if (!csvPath.empty()) {
      raycast::writeRowsCsv(csvPath, run.rows);
      std::printf("wrote %s\n", csvPath.c_str());
    }
    if (!run.checksPassed) {
      std::fprintf(stderr, "raycast_bench: rtcIntersect8's depth image differs from rtcIntersect1's (see check:)\n");
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raycast_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
