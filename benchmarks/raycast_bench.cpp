// The ray-casting benchmark (not a test): facet's GPU path (lavapipe)
// and double-precision CPU reference, exact and tessellated methods, on cages
// from 6 to ~100k patches at 512² and 1024², against Embree 3's subdivision
// geometry (when found at build time) at equal depth error.
//
//   raycast_bench [--quick] [--csv out.csv] [--adapter NAME]
//
// Every scene is a bare cage framed by sceneFromCage (default camera, default
// key light, default refinement choice). Depth errors are those of
// analysis/image_compare.h, against facet's CPU exact depth image. Results
// and method: BENCHMARKS.md.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/image_compare.h"
#include "engine/image/image_io.h"
#include "engine/renderer.h"
#include "scenes/obj_cage.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"

#if FACET_HAVE_EMBREE
#include "analysis/peers/embree_peer.h"
#endif

namespace {

using facet::Image;
using facet::RenderReport;
using facet::analysis::compareDepth;
using facet::analysis::DepthError;
using facet::scene::ControlCage;
using facet::scene::IntersectionMethod;
using facet::scene::Scene;

constexpr int kThreads = 2;

double nowMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// ---------------------------------------------------------------- cages

struct Vertex {
  glm::dvec3 p{0.0};
  void Clear() { p = glm::dvec3(0.0); }
  void AddWithWeight(const Vertex& src, float weight) { p += double(weight) * src.p; }
};

// The cage `levels` uniform Catmull-Clark steps finer than `cage`, as a new
// control cage (the same limit surface). Creases and corners are not carried
// over (the cages refined here have none); holes neither.
ControlCage refineUniformly(const ControlCage& cage, int levels) {
  namespace Far = OpenSubdiv::Far;
  namespace Sdc = OpenSubdiv::Sdc;
  if (!cage.creases.empty() || !cage.corners.empty() || !cage.holes.empty())
    throw std::runtime_error("refineUniformly: cages with creases, corners or holes are not supported");
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = cage.vertexCount();
  descriptor.numFaces = cage.faceCount();
  descriptor.numVertsPerFace = cage.faceVertexCounts.data();
  descriptor.vertIndicesPerFace = cage.faceVertexIndices.data();
  Sdc::Options options;
  switch (cage.options.boundary) {
    case facet::scene::BoundaryInterpolation::None:
      options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_NONE);
      break;
    case facet::scene::BoundaryInterpolation::EdgeOnly:
      options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
      break;
    case facet::scene::BoundaryInterpolation::EdgeAndCorner:
      options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
      break;
  }
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_CATMARK, options)));
  if (!refiner) throw std::runtime_error("refineUniformly: OpenSubdiv rejected " + cage.source);
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));

  std::vector<Vertex> current(cage.positions.size());
  for (std::size_t i = 0; i < current.size(); ++i) current[i].p = cage.positions[i];
  Far::PrimvarRefiner primvar(*refiner);
  for (int level = 1; level <= levels; ++level) {
    std::vector<Vertex> next(std::size_t(refiner->GetLevel(level).GetNumVertices()));
    Vertex* destination = next.data();
    primvar.Interpolate(level, current.data(), destination);
    current = std::move(next);
  }

  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  ControlCage out;
  out.source = cage.source + " (uniform level " + std::to_string(levels) + ")";
  out.options = cage.options;
  for (const Vertex& v : current) out.positions.push_back(v.p);
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    Far::ConstIndexArray vertices = last.GetFaceVertices(f);
    out.faceVertexCounts.push_back(vertices.size());
    for (int i = 0; i < vertices.size(); ++i) out.faceVertexIndices.push_back(vertices[i]);
  }
  return out;
}

struct NamedCage {
  std::string name;
  ControlCage cage;
};

// ---------------------------------------------------------------- results

struct Row {
  std::string cage;
  int patches = 0;  // facet: limit patches after isolation; Embree: cage faces
  int size = 0;
  std::string engine;                                          // facet-gpu, facet-cpu, embree, embree8
  std::string method;                                          // exact, tess k=.., rate=..
  double refineMs = std::numeric_limits<double>::quiet_NaN();  // refine + BVH, or Embree commit
  double primaryMs = std::numeric_limits<double>::quiet_NaN();
  double shadowMs = std::numeric_limits<double>::quiet_NaN();
  double traceMs = std::numeric_limits<double>::quiet_NaN();  // every stage after refine + BVH
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  DepthError error;
  std::string stages;  // "name=ms;..."
  std::string note;

  double primaryMrays() const { return primaryRays / (primaryMs * 1e3); }
  double shadowMrays() const { return shadowRays / (shadowMs * 1e3); }
  double allMrays() const { return (primaryRays + shadowRays) / (traceMs * 1e3); }
};

std::string fmt(double v, const char* format = "%.1f") {
  if (!std::isfinite(v)) return "—";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::string fmtSci(double v) { return fmt(v, "%.1e"); }

std::string csvField(double v) {
  if (!std::isfinite(v)) return "";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

// Embree's rows: "embree" casts one rtcIntersect1 per pixel, "embree8" one
// rtcIntersect8 per 4×2 pixel tile (the same rays).
const std::string kEmbreeEngines[] = {"embree", "embree8"};

bool isEmbree(const Row& r) {
  return std::find(std::begin(kEmbreeEngines), std::end(kEmbreeEngines), r.engine) != std::end(kEmbreeEngines);
}

// ---------------------------------------------------------------- facet

Row runFacet(facet::Renderer& renderer, const NamedCage& cage, const Scene& scene, facet::Backend backend,
             std::vector<float>* depthOut) {
  const RenderReport report = renderer.render(scene, backend);
  Row row;
  row.cage = cage.name;
  row.patches = report.patches;
  row.size = scene.render.width;
  row.engine = backend == facet::Backend::Gpu ? "facet-gpu" : "facet-cpu";
  if (scene.render.method == IntersectionMethod::Exact) {
    row.method = "exact";
  } else {
    const auto choice = facet::scene::chooseRefinement(scene.objects[0], scene.camera, scene.render);
    row.method = "tess k=" + std::to_string(scene.render.tessellationRate.value_or(choice.tessellationRate));
  }
  row.primaryRays = report.primaryRays;
  row.shadowRays = report.shadowRays;
  row.traceMs = 0;
  double primary = 0;  // GPU: camera rays generated and intersected, fallbacks included (Embree's loop does both too)
  for (const auto& stage : report.stages) {
    row.stages += stage.name + "=" + fmt(stage.milliseconds, "%.2f") + ";";
    if (stage.name == "refine + BVH") {
      row.refineMs = stage.milliseconds;
      continue;
    }
    row.traceMs += stage.milliseconds;
    if (stage.name == "intersect" || stage.name == "fallbacks") primary += stage.milliseconds;
    if (stage.name == "shadow rays" || stage.name == "shadow fallbacks")
      row.shadowMs = (std::isnan(row.shadowMs) ? 0 : row.shadowMs) + stage.milliseconds;
  }
  if (primary > 0) row.primaryMs = primary;
  if (depthOut) *depthOut = report.image.depth;
  return row;
}

// ---------------------------------------------------------------- matching

// Among `engine`'s rows, the one whose mean depth error is the largest not
// above `target` (the fastest rate that is at least as accurate).
const Row* matchEmbree(const std::vector<Row>& rows, const std::string& engine, const std::string& cage, int size,
                       double target) {
  const Row* best = nullptr;
  for (const Row& r : rows) {
    if (r.engine != engine || r.cage != cage || r.size != size) continue;
    if (!(r.error.meanRelative <= target)) continue;
    if (!best || r.error.meanRelative > best->error.meanRelative) best = &r;
  }
  return best;
}

const Row* mostAccurateEmbree(const std::vector<Row>& rows, const std::string& engine, const std::string& cage,
                              int size) {
  const Row* best = nullptr;
  for (const Row& r : rows)
    if (r.engine == engine && r.cage == cage && r.size == size && std::isfinite(r.error.meanRelative) &&
        (!best || r.error.meanRelative < best->error.meanRelative))
      best = &r;
  return best;
}

struct Match {
  std::string cage;
  int size = 0;
  std::string facetMethod;
  double facetMrays = 0;
  double facetError = 0;
  std::string embreeEngine;
  const Row* embree = nullptr;  // null: no rate reached the error
  const Row* closest = nullptr;
};

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string csvPath, adapter;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      quick = true;
    } else if (a == "--csv" && i + 1 < argc) {
      csvPath = argv[++i];
    } else if (a == "--adapter" && i + 1 < argc) {
      adapter = argv[++i];
    } else {
      std::fprintf(stderr, "usage: raycast_bench [--quick] [--csv out.csv] [--adapter NAME]\n");
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  try {
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
    [[maybe_unused]] constexpr double kEmbreeGridBudget = 40e6;
    // The CPU exact method is the slow oracle; it would be skipped where it
    // dominates the run (said in the output); no cage here is that large.
    auto skipCpuExact = [&](const NamedCage& c, int size) { return size >= 1024 && c.cage.faceCount() > 1000000; };

    const double runStart = nowMs();
    std::vector<Row> rows;
    std::vector<std::string> skipped;
    std::vector<Match> matches;
    std::vector<std::string> checks;  // --quick: embree8's depth against embree's
    bool checksPassed = true;

    // Warm-up: compile every GPU pipeline once outside the timed renders.
    {
      Scene warm = facet::scene::sceneFromCage(cages[0].cage);
      warm.render.width = warm.render.height = 32;
      for (IntersectionMethod m : {IntersectionMethod::Exact, IntersectionMethod::Tessellated}) {
        warm.render.method = m;
        (void)renderer.render(warm, facet::Backend::Gpu);
      }
    }

    for (const NamedCage& cage : cages) {
#if FACET_HAVE_EMBREE
      facet::peers::EmbreeSubdivision embree(cage.cage, kThreads);
      std::vector<int> rates;
      for (int rate : allRates)
        if (double(cage.cage.faceCount()) * rate * rate <= kEmbreeGridBudget) rates.push_back(rate);
      if (rates.size() < allRates.size())
        skipped.push_back("Embree rates above " + std::to_string(rates.back()) + " skipped on " + cage.name +
                          " (faces × rate² > 40M grid quads)");
      std::vector<double> commitMs(rates.size());
#endif
      for (int size : sizes) {
        Scene scene = facet::scene::sceneFromCage(cage.cage);
        scene.render.width = scene.render.height = size;
        std::vector<float> referenceDepth;
        std::fprintf(stderr, "[%6.1f s] %s %d²\n", (nowMs() - runStart) / 1e3, cage.name.c_str(), size);

        scene.render.method = IntersectionMethod::Exact;
        if (skipCpuExact(cage, size)) {
          skipped.push_back("CPU exact skipped on " + cage.name + " at " + std::to_string(size) +
                            "² (too slow for the time budget); no depth errors there");
        } else {
          Row row = runFacet(renderer, cage, scene, facet::Backend::Cpu, &referenceDepth);
          row.error = compareDepth(referenceDepth, referenceDepth);
          rows.push_back(row);
        }
        std::vector<float> depth;
        Row gpuExact = runFacet(renderer, cage, scene, facet::Backend::Gpu, &depth);
        gpuExact.error = compareDepth(depth, referenceDepth);
        rows.push_back(gpuExact);

        scene.render.method = IntersectionMethod::Tessellated;
        Row cpuTess = runFacet(renderer, cage, scene, facet::Backend::Cpu, &depth);
        cpuTess.error = compareDepth(depth, referenceDepth);
        rows.push_back(cpuTess);
        Row gpuTess = runFacet(renderer, cage, scene, facet::Backend::Gpu, &depth);
        gpuTess.error = compareDepth(depth, referenceDepth);
        rows.push_back(gpuTess);

#if FACET_HAVE_EMBREE
        // Median of 3 casts by `cast` into `out`, as a row of `engine`.
        using Cast = double (facet::peers::EmbreeSubdivision::*)(const facet::scene::Camera&, int, int,
                                                                 std::vector<float>&) const;
        auto embreeRow = [&](const std::string& engine, Cast cast, double commit, int rate, std::vector<float>& out) {
          std::vector<double> times;
          for (int rep = 0; rep < 3; ++rep) times.push_back((embree.*cast)(scene.camera, size, size, out));
          std::sort(times.begin(), times.end());
          Row row;
          row.cage = cage.name;
          row.patches = cage.cage.faceCount();
          row.size = size;
          row.engine = engine;
          row.method = "rate=" + std::to_string(rate);
          row.refineMs = commit;
          row.primaryMs = times[1];
          row.traceMs = times[1];
          row.primaryRays = std::uint64_t(size) * std::uint64_t(size);
          row.error = compareDepth(out, referenceDepth);
          row.stages = "commit=" + fmt(commit, "%.2f") + ";intersect(median of 3)=" + fmt(times[1], "%.2f") + ";";
          row.note = embree.notes();
          return row;
        };
        std::vector<float> depth8;
        for (std::size_t r = 0; r < rates.size(); ++r) {
          commitMs[r] = embree.setTessellationRate(rates[r]);
          rows.push_back(embreeRow(kEmbreeEngines[0], &facet::peers::EmbreeSubdivision::castPrimary, commitMs[r],
                                   rates[r], depth));
          rows.push_back(embreeRow(kEmbreeEngines[1], &facet::peers::EmbreeSubdivision::castPrimary8, commitMs[r],
                                   rates[r], depth8));
          if (quick) {
            // rtcIntersect8 must see what rtcIntersect1 sees: same coverage, depth to float rounding.
            const DepthError e = compareDepth(depth8, depth);
            const bool ok = e.coverageMismatch == 0 && !(e.maxRelative >= 1e-5);
            checksPassed = checksPassed && ok;
            checks.push_back("embree8 vs embree depth on " + cage.name + " " + std::to_string(size) +
                             "² rate=" + std::to_string(rates[r]) + ": max rel. diff " + fmtSci(e.maxRelative) +
                             " over " + std::to_string(e.bothCovered) + " pixels, coverage mismatch " +
                             std::to_string(e.coverageMismatch) + (ok ? ": ok" : ": FAILED (limit 1e-5, 0)"));
          }
        }
#endif
      }
    }
    const double runSeconds = (nowMs() - runStart) / 1e3;

    // Matches are taken once every row is in (rows holds them by address).
    for (const Row& facetRow : rows) {
      if (facetRow.engine != "facet-gpu") continue;
      for (const std::string& engine : kEmbreeEngines) {
        Match m;
        m.cage = facetRow.cage;
        m.size = facetRow.size;
        m.facetMethod = facetRow.method;
        m.facetMrays = facetRow.primaryMrays();
        m.facetError = facetRow.error.meanRelative;
        m.embreeEngine = engine;
        if (std::isfinite(m.facetError)) {
          m.embree = matchEmbree(rows, engine, m.cage, m.size, m.facetError);
          m.closest = mostAccurateEmbree(rows, engine, m.cage, m.size);
        }
        matches.push_back(m);
      }
    }

    // ------------------------------------------------------------ table
    std::printf("\nfacet raycast_bench%s: %d threads; GPU adapter via facet::Renderer; depth errors vs facet CPU exact\n",
                quick ? " --quick" : "", kThreads);
    std::printf(
        "\n| cage | patches | size | engine | method | refine+BVH / commit ms | primary ms | shadow ms | "
        "trace+shade ms | primary Mrays/s | shadow Mrays/s | all rays Mrays/s | depth rel. err max | mean |\n");
    std::printf("| --- | ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const Row& r : rows) {
      std::printf("| %s | %d | %d² | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.cage.c_str(),
                  r.patches, r.size, r.engine.c_str(), r.method.c_str(), fmt(r.refineMs).c_str(),
                  fmt(r.primaryMs).c_str(), fmt(r.shadowMs).c_str(), fmt(r.traceMs).c_str(),
                  fmt(r.primaryMrays(), "%.2f").c_str(), fmt(r.shadowMrays(), "%.2f").c_str(),
                  isEmbree(r) ? "—" : fmt(r.allMrays(), "%.2f").c_str(), fmtSci(r.error.maxRelative).c_str(),
                  fmtSci(r.error.meanRelative).c_str());
    }
#if FACET_HAVE_EMBREE
    std::printf(
        "\nEmbree at equal depth error: the fastest tessellation rate whose mean relative depth error is not\n"
        "above facet GPU's (primary rays only on %d threads; embree: rtcIntersect1 per pixel, embree8:\n"
        "rtcIntersect8 per 4×2 pixel tile):\n\n",
        kThreads);
    std::printf(
        "| cage | size | facet GPU method | facet mean err | facet primary Mrays/s | Embree engine | Embree rate | "
        "Embree mean err | Embree Mrays/s | facet / Embree |\n");
    std::printf("| --- | ---: | --- | ---: | ---: | --- | --- | ---: | ---: | ---: |\n");
    for (const Match& m : matches) {
      if (m.embree) {
        std::printf("| %s | %d² | %s | %s | %s | %s | %s | %s | %s | **%s×** |\n", m.cage.c_str(), m.size,
                    m.facetMethod.c_str(), fmtSci(m.facetError).c_str(), fmt(m.facetMrays, "%.2f").c_str(),
                    m.embreeEngine.c_str(), m.embree->method.c_str(), fmtSci(m.embree->error.meanRelative).c_str(),
                    fmt(m.embree->primaryMrays(), "%.2f").c_str(),
                    fmt(m.facetMrays / m.embree->primaryMrays(), "%.3f").c_str());
      } else if (m.closest) {
        std::printf("| %s | %d² | %s | %s | %s | %s | none reaches it; finest: %s | %s | %s | ≤ %s× (vs finest) |\n",
                    m.cage.c_str(), m.size, m.facetMethod.c_str(), fmtSci(m.facetError).c_str(),
                    fmt(m.facetMrays, "%.2f").c_str(), m.embreeEngine.c_str(), m.closest->method.c_str(),
                    fmtSci(m.closest->error.meanRelative).c_str(), fmt(m.closest->primaryMrays(), "%.2f").c_str(),
                    fmt(m.facetMrays / m.closest->primaryMrays(), "%.3f").c_str());
      } else {
        std::printf("| %s | %d² | %s | — | %s | %s | no reference depth | — | — | — |\n", m.cage.c_str(), m.size,
                    m.facetMethod.c_str(), fmt(m.facetMrays, "%.2f").c_str(), m.embreeEngine.c_str());
      }
    }
#else
    std::printf("\nEmbree 3 was not found at build time: no peer comparison.\n");
#endif
    for (const std::string& s : skipped) std::printf("\nnote: %s", s.c_str());
    for (const std::string& c : checks) std::printf("\ncheck: %s", c.c_str());
    std::printf("\n\ntotal run time %.1f s\n", runSeconds);

    // ------------------------------------------------------------ CSV
    if (!csvPath.empty()) {
      facet::writeAtomically(csvPath, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary);
        out << "cage,patches,size,engine,method,refine_or_commit_ms,primary_ms,shadow_ms,trace_ms,primary_rays,"
               "shadow_rays,primary_mrays,shadow_mrays,all_mrays,depth_rel_max,depth_rel_mean,both_covered,"
               "coverage_mismatch,stages,note\n";
        for (const Row& r : rows) {
          out << '"' << r.cage << "\"," << r.patches << ',' << r.size << ',' << r.engine << ",\"" << r.method << "\","
              << csvField(r.refineMs) << ',' << csvField(r.primaryMs) << ',' << csvField(r.shadowMs) << ','
              << csvField(r.traceMs) << ',' << r.primaryRays << ',' << r.shadowRays << ',' << csvField(r.primaryMrays())
              << ',' << csvField(r.shadowMrays()) << ',' << (isEmbree(r) ? std::string() : csvField(r.allMrays()))
              << ',' << csvField(r.error.maxRelative) << ',' << csvField(r.error.meanRelative) << ','
              << r.error.bothCovered << ',' << r.error.coverageMismatch << ",\"" << r.stages << "\",\"" << r.note
              << "\"\n";
        }
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
      });
      std::printf("wrote %s\n", csvPath.c_str());
    }
    if (!checksPassed) {
      std::fprintf(stderr, "raycast_bench: rtcIntersect8's depth image differs from rtcIntersect1's (see check:)\n");
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raycast_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
