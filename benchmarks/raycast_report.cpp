#include "benchmarks/raycast_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "engine/image/image_io.h"

namespace facet::benchmarks::raycast {
namespace {

std::string csvField(double v) {
  if (!std::isfinite(v)) return "";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

bool isEmbree(const Row& r) {
  return std::find(std::begin(kEmbreeEngines), std::end(kEmbreeEngines), r.engine) != std::end(kEmbreeEngines);
}

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

// Matches are taken once every row is in (rows holds them by address).
std::vector<Match> matchesOf(const std::vector<Row>& rows) {
  std::vector<Match> matches;
  for (const Row& facetRow : rows) {
    if (facetRow.engine != "facet-gpu") continue;
    for (const std::string& engine : kEmbreeEngines) {
      Match m{};
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
  return matches;
}

}  // namespace

void printTables(const Measurements& run, bool quick) {
  const std::vector<Row>& rows = run.rows;
  const std::vector<Match> matches = matchesOf(rows);
  std::printf("\nfacet raycast_bench%s: %d threads; GPU adapter via facet::Renderer; depth errors vs facet CPU exact\n",
              quick ? " --quick" : "", kThreads);
  std::printf(
      "\n| cage | patches | size | engine | method | refine+BVH / commit ms | primary ms | shadow ms | "
      "trace+shade ms | primary Mrays/s | shadow Mrays/s | all rays Mrays/s | depth rel. err max | mean |\n");
  std::printf("| --- | ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (const Row& r : rows) {
    std::printf("| %s | %d | %d² | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.cage.c_str(), r.patches,
                r.size, r.engine.c_str(), r.method.c_str(), fmt(r.refineMs).c_str(), fmt(r.primaryMs).c_str(),
                fmt(r.shadowMs).c_str(), fmt(r.traceMs).c_str(), fmt(r.primaryMrays(), "%.2f").c_str(),
                fmt(r.shadowMrays(), "%.2f").c_str(), isEmbree(r) ? "—" : fmt(r.allMrays(), "%.2f").c_str(),
                fmtSci(r.error.maxRelative).c_str(), fmtSci(r.error.meanRelative).c_str());
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
  for (const std::string& s : run.skipped) std::printf("\nnote: %s", s.c_str());
  for (const std::string& c : run.checks) std::printf("\ncheck: %s", c.c_str());
  std::printf("\n\ntotal run time %.1f s\n", run.seconds);
}

void writeRowsCsv(const std::string& csvPath, const std::vector<Row>& rows) {
  facet::writeAtomically(csvPath, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary);
    out << "cage,patches,size,engine,method,refine_or_commit_ms,primary_ms,shadow_ms,trace_ms,primary_rays,"
           "shadow_rays,primary_mrays,shadow_mrays,all_mrays,depth_rel_max,depth_rel_mean,both_covered,"
           "coverage_mismatch,stages,note\n";
    for (const Row& r : rows) {
      out << '"' << r.cage << "\"," << r.patches << ',' << r.size << ',' << r.engine << ",\"" << r.method << "\","
          << csvField(r.refineMs) << ',' << csvField(r.primaryMs) << ',' << csvField(r.shadowMs) << ','
          << csvField(r.traceMs) << ',' << r.primaryRays << ',' << r.shadowRays << ',' << csvField(r.primaryMrays())
          << ',' << csvField(r.shadowMrays()) << ',' << (isEmbree(r) ? std::string() : csvField(r.allMrays())) << ','
          << csvField(r.error.maxRelative) << ',' << csvField(r.error.meanRelative) << ',' << r.error.bothCovered << ','
          << r.error.coverageMismatch << ",\"" << r.stages << "\",\"" << r.note << "\"\n";
    }
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  });
}

}  // namespace facet::benchmarks::raycast
