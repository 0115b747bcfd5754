#include "benchmarks/incoherent/incoherent_report.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "benchmarks/raycast_rows.h"
#include "engine/image/image_io.h"

namespace facet::benchmarks::incoherent {
namespace {

using raycast::fmt;

// The row of the same scene whose rays are the camera rays that hit.
const Row* cameraHitsRow(const Report& report, const Row& row) {
  for (const Row& r : report.rows)
    if (r.scene == row.scene && r.rays == "camera hits") return &r;
  return nullptr;
}

}  // namespace

void printReport(const Report& report) {
  std::printf(
      "\nfacet raycast_bench --incoherent: %s, %d² camera rays per scene, tessellated method; medians of %d passes;\n"
      "Embree rtcIntersect1 on %d threads over the ceiling's triangles; ratios: median of each pass's ratio\n",
      report.adapter.c_str(), report.size, report.repeats, report.threads);
  std::printf(
      "\n| scene | k | triangles | rays | count | hit %% | facet Mrays/s | ceiling Mrays/s | Embree Mrays/s | "
      "facet / ceiling | facet / Embree | hits differing: facet, Embree vs ceiling |\n");
  std::printf("| --- | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (const Row& r : report.rows)
    std::printf("| %s | %d | %zu | %s | %zu | %.0f | %s | %s | %s | **%s×** | %s× | %zu, %zu |\n", r.scene.c_str(), r.k,
                r.triangles, r.rays.c_str(), r.count, 100 * r.hitFraction, fmt(r.mrays(r.facetMs), "%.2f").c_str(),
                fmt(r.mrays(r.ceilingMs), "%.2f").c_str(), fmt(r.mrays(r.embreeMs), "%.2f").c_str(),
                fmt(r.facetOverCeiling, "%.2f").c_str(), fmt(r.facetOverEmbree, "%.2f").c_str(), r.facetVsCeiling,
                r.embreeVsCeiling);
  std::printf(
      "\nWhere the time goes, per ray (counted copies of both traversals; a step is a node or a leaf; lanes: steps\n"
      "over the longest of each %d consecutive rays, which a lavapipe SIMD group waits for; step cost: facet's time\n"
      "per SIMD step over the ceiling's; slowdown: time per ray over the camera hits'):\n\n",
      kLanes);
  std::printf(
      "| scene | rays | facet nodes | facet cells | facet lanes | ceiling nodes | ceiling leaves | ceiling triangles | "
      "ceiling lanes | facet / ceiling step cost | facet ns/ray | ceiling ns/ray | facet slowdown | ceiling slowdown | "
      "Embree slowdown |\n");
  std::printf(
      "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (const Row& r : report.rows) {
    const Row* c = cameraHitsRow(report, r);
    auto perRay = [&](const Row& row, double Row::*ms) { return row.*ms * 1e6 / double(row.count); };
    auto slowdown = [&](double Row::*ms) {
      return c ? fmt(perRay(r, ms) / perRay(*c, ms), "%.2f×") : std::string("—");
    };
    const WorkStats &f = r.facetWork, &g = r.ceilingWork;
    const double stepCost = (r.facetMs / f.groupSteps) / (r.ceilingMs / g.groupSteps);
    std::printf(
        "| %s | %s | %.1f | %.1f | %.0f%% | %.1f | %.1f | %.1f | %.0f%% | %.2f× | %.0f | %.0f | %s | %s | %s |\n",
        r.scene.c_str(), r.rays.c_str(), f.nodes, f.leaves, 100 * f.steps / f.groupSteps, g.nodes, g.leaves, g.items,
        100 * g.steps / g.groupSteps, stepCost, perRay(r, &Row::facetMs), perRay(r, &Row::ceilingMs),
        slowdown(&Row::facetMs).c_str(), slowdown(&Row::ceilingMs).c_str(), slowdown(&Row::embreeMs).c_str());
  }
#if !FACET_HAVE_EMBREE
  std::printf("\nEmbree 3 was not found at build time: no Embree column.\n");
#endif
  std::printf("\ntotal run time %.1f s\n", report.seconds);
}

void writeReportCsv(const std::string& path, const Report& report) {
  facet::writeAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    out << "scene,k,triangles,rays,count,hit_fraction,facet_ms,ceiling_ms,embree_ms,facet_mrays,ceiling_mrays,"
           "embree_mrays,facet_over_ceiling,facet_over_embree,facet_vs_ceiling,embree_vs_ceiling,facet_nodes,"
           "facet_leaves,facet_steps,facet_group_steps,ceiling_nodes,ceiling_leaves,ceiling_triangles,ceiling_steps,"
           "ceiling_group_steps\n";
    for (const Row& r : report.rows)
      out << r.scene << ',' << r.k << ',' << r.triangles << ',' << r.rays << ',' << r.count << ',' << r.hitFraction
          << ',' << r.facetMs << ',' << r.ceilingMs << ',' << r.embreeMs << ',' << r.mrays(r.facetMs) << ','
          << r.mrays(r.ceilingMs) << ',' << r.mrays(r.embreeMs) << ',' << r.facetOverCeiling << ',' << r.facetOverEmbree
          << ',' << r.facetVsCeiling << ',' << r.embreeVsCeiling << ',' << r.facetWork.nodes << ','
          << r.facetWork.leaves << ',' << r.facetWork.steps << ',' << r.facetWork.groupSteps << ','
          << r.ceilingWork.nodes << ',' << r.ceilingWork.leaves << ',' << r.ceilingWork.items << ','
          << r.ceilingWork.steps << ',' << r.ceilingWork.groupSteps << '\n';
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  });
}

}  // namespace facet::benchmarks::incoherent
