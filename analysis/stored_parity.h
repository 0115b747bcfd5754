// Stored renders judged against stored references (`facet compare`,
// docs/parity.md): K reference EXRs (golden images) and K candidate EXRs of
// one picture, paired by the seed of their estimate and judged by parity's
// rules, beauty by the paired t-test where it is a Monte Carlo estimate and
// K >= 2. Whether the two sets estimate the same picture is read from each
// file's provenance (engine/image/exr_metadata.h); a set made with other
// settings is not comparable, which is no verdict on the candidate.
#pragma once

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/parity_run.h"
#include "engine/image/exr_metadata.h"

namespace facet::analysis {

// The two sets estimate different pictures: "not comparable with REFERENCE:
// spp 4 against 16", the candidate's settings first.
class NotComparable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// facetRenderSettings as fields: "spp=4 method=exact" gives spp -> 4, method -> exact.
std::map<std::string, std::string> settingsFields(const std::string& text);

struct StoredJudgement {
  ParityCase judged;
  std::vector<std::string> warnings;  // what was not checked, and why
};

// `candidates` against `references`, as many of each, every file an EXR
// written by facet render with the ids layer, paired by seed (renders
// without an environment draw fixed numbers and pair in any order). Throws
// std::invalid_argument for files that cannot be judged (unreadable, no ids
// layer, sizes apart, a seed twice in one set, renders of two pictures in
// one set) and NotComparable where the sets' settings, scene or seeds
// differ. Reads one pair of images at a time.
StoredJudgement judgeStoredRenders(const std::vector<std::filesystem::path>& references,
                                   const std::vector<std::filesystem::path>& candidates,
                                   const ParityTolerances& tolerances);

}  // namespace facet::analysis
