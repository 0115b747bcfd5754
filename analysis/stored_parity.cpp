#include "analysis/stored_parity.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <sstream>

#include "analysis/parity_statistics.h"
#include "engine/image/exr_file.h"
#include "scenes/exr_header.h"

namespace facet::analysis {
namespace {

struct StoredRender {
  std::filesystem::path file;
  ExrProvenance made;
  std::optional<std::uint32_t> seed;  // of its random numbers (seedOf); none without an environment
};

// The seed of a render's random numbers (its settings' iblSeed), where it
// has an environment; without one its numbers are fixed. A file whose
// facetEstimateSeed says another is not one facet wrote.
std::optional<std::uint32_t> seedOf(const std::filesystem::path& file, const ExrProvenance& made) {
  const std::map<std::string, std::string> fields = settingsFields(made.renderSettings);
  const auto seed = fields.find("iblSeed");
  if (seed == fields.end()) return std::nullopt;
  std::size_t end = 0;
  unsigned long value = 0;
  try {
    value = std::stoul(seed->second, &end);
  } catch (const std::exception&) {
  }
  if (end == 0 || end != seed->second.size() || value > UINT32_MAX ||
      (made.estimateSeed && *made.estimateSeed != value))
    throw std::invalid_argument(file.string() + ": " + kRenderSettingsAttribute + ": iblSeed '" + seed->second +
                                "' is not the render's seed (an integer 0..4294967295, its " + kEstimateSeedAttribute +
                                " where it has one)");
  return std::uint32_t(value);
}

// An unreadable file is bad input, not an internal error.
StoredRender readProvenance(const std::filesystem::path& file) {
  scene::checkTileFile(file, "the render");
  ExrProvenance made;
  try {
    made = readExrProvenance(file);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
  return {file, made, seedOf(file, made)};
}

// So is an EXR without the ids layer, whose pixels would all read as missed
// and be judged "insufficient coverage" when the surface is plainly there.
Image readJudged(const std::filesystem::path& file) {
  Image image;
  try {
    image = readExr(file);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
  const bool anyCovered =
      std::any_of(image.patchId.begin(), image.patchId.end(), [](std::uint32_t id) { return id != Image::kNoId; });
  const bool anyHit = std::any_of(image.beauty.begin(), image.beauty.end(), [](const glm::vec4& b) { return b.a > 0; });
  if (!anyCovered && anyHit)
    throw std::invalid_argument(file.string() +
                                ": has no ids layer (patchId), which says which pixels are covered: render it with "
                                "--aovs all (or a list with ids)");
  return image;
}

// "spp 4 against 16, bounces 12 against 8": the fields of `a` that differ
// from `b`'s, `ignored` aside, a's value first; "" where they agree.
std::string differing(const ExrProvenance& a, const ExrProvenance& b, const std::set<std::string>& ignored) {
  std::map<std::string, std::string> fa = settingsFields(a.renderSettings), fb = settingsFields(b.renderSettings);
  std::set<std::string> keys;
  for (const auto* fields : {&fa, &fb})
    for (const auto& [key, value] : *fields)
      if (!ignored.count(key)) keys.insert(key);
  std::string out;
  for (const std::string& key : keys)
    if (fa[key] != fb[key])
      out += (out.empty() ? "" : ", ") + key + " " + (fa[key].empty() ? "unsaid" : fa[key]) + " against " +
             (fb[key].empty() ? "unsaid" : fb[key]);
  return out;
}

const std::set<std::string> kRendererAndSeed{"backend", "iblSeed"};

// Every render of one set estimates one picture: the same digest, and the
// same settings apart from the backend and the seed.
void checkOnePicture(const std::vector<StoredRender>& set) {
  const StoredRender& first = set.front();
  for (const StoredRender& r : set) {
    if (const std::string d = differing(r.made, first.made, kRendererAndSeed); !d.empty())
      throw std::invalid_argument(r.file.string() + " and " + first.file.string() +
                                  " are not renders of one picture: " + d);
    if (r.made.pictureDigest != first.made.pictureDigest)
      throw std::invalid_argument(r.file.string() + " and " + first.file.string() +
                                  " are not renders of one picture: their scenes differ (facetPictureDigest " +
                                  r.made.pictureDigest + " against " + first.made.pictureDigest + ")");
  }
}

// The set in the order of its seeds, each seed once.
std::vector<StoredRender> bySeed(std::vector<StoredRender> set) {
  std::stable_sort(set.begin(), set.end(),
                   [](const StoredRender& a, const StoredRender& b) { return a.seed < b.seed; });
  for (std::size_t i = 1; i < set.size(); ++i)
    if (set[i].seed && set[i].seed == set[i - 1].seed)
      throw std::invalid_argument(set[i - 1].file.string() + " and " + set[i].file.string() + " are both seed " +
                                  std::to_string(*set[i].seed) +
                                  ": renders of one set are paired by their seeds, each once");
  return set;
}

std::string seedList(const std::vector<StoredRender>& set) {
  std::string out;
  for (const StoredRender& r : set)
    if (r.seed) out += (out.empty() ? "" : ", ") + std::to_string(*r.seed);
  return out;
}

std::string setName(const std::vector<StoredRender>& set) {
  const std::string first = set.front().file.string();
  return set.size() == 1 ? first : first + " and " + std::to_string(set.size() - 1) + " more";
}

// Checks that the two sets estimate one picture and orders both by seed,
// noting in `out` what the report needs; whether beauty gets the t-test.
bool pairBySeed(std::vector<StoredRender>& references, std::vector<StoredRender>& candidates, StoredJudgement& out) {
  const std::size_t k = references.size();
  checkOnePicture(references);
  checkOnePicture(candidates);
  const StoredRender reference = references.front(), candidate = candidates.front();  // before the sets are sorted
  const bool estimate = reference.made.estimateSeed.has_value();
  const std::string stem = "not comparable with " + reference.file.string() + ": ";
  if (const std::string d = differing(candidate.made, reference.made, kRendererAndSeed); !d.empty())
    throw NotComparable(stem + d);
  if (candidate.made.pictureDigest != reference.made.pictureDigest)
    throw NotComparable(
        stem + "the scene differs (its file, camera, environment map or subdivision): " + kPictureDigestAttribute +
        " " + candidate.made.pictureDigest + " against " + reference.made.pictureDigest);
  references = bySeed(references);
  candidates = bySeed(candidates);
  if (seedList(candidates) != seedList(references))
    throw NotComparable(stem + "seeds " + seedList(candidates) + " against " + seedList(references) +
                        ": each candidate is paired with the reference of its seed");
  if (estimate && k == 1)
    out.warnings.push_back(candidate.file.string() +
                           ": one render of a Monte Carlo estimate is judged pixel by pixel, where noise the "
                           "backends do not share fails it: give renders seeds apart (--seeds) for the paired "
                           "t-test (docs/parity.md)");
  nlohmann::json seeds = nlohmann::json::array();
  for (const StoredRender& r : references)
    if (r.seed) seeds.push_back(*r.seed);
  out.judged.settings = {{"pictureDigest", reference.made.pictureDigest},
                         {"text", reference.made.renderSettings},
                         {"rendersPerBackend", k},
                         {"seeds", seeds}};
  return estimate && k > 1;
}

}  // namespace

std::map<std::string, std::string> settingsFields(const std::string& text) {
  std::map<std::string, std::string> fields;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    const std::size_t equals = word.find('=');
    fields[word.substr(0, equals)] = equals == std::string::npos ? "" : word.substr(equals + 1);
  }
  return fields;
}

StoredJudgement judgeStoredRenders(const std::vector<std::filesystem::path>& referenceFiles,
                                   const std::vector<std::filesystem::path>& candidateFiles,
                                   const ParityTolerances& tolerances) {
  if (referenceFiles.empty() || referenceFiles.size() != candidateFiles.size())
    throw std::invalid_argument("compare: " + std::to_string(referenceFiles.size()) + " reference(s) and " +
                                std::to_string(candidateFiles.size()) +
                                " candidate(s): give as many candidates as references, at least one");
  std::vector<StoredRender> references, candidates;
  for (const auto& file : referenceFiles) references.push_back(readProvenance(file));
  for (const auto& file : candidateFiles) candidates.push_back(readProvenance(file));
  const std::size_t k = references.size();

  StoredJudgement out;
  const StoredRender* unrecorded = nullptr;
  for (const auto* set : {&references, &candidates})
    for (const StoredRender& r : *set)
      if (!unrecorded && r.made.pictureDigest.empty()) unrecorded = &r;
  bool statistical = false;
  if (unrecorded) {
    const std::string why = unrecorded->file.string() + ": no " + kPictureDigestAttribute +
                            " (written by another program or an earlier facet)";
    if (k > 1) throw std::invalid_argument(why + ": several renders are paired by the seeds their headers record");
    out.warnings.push_back(why + ": whether the two renders are comparable is not checked");
  } else {
    statistical = pairBySeed(references, candidates, out);
  }

  out.judged.scene = setName(candidates);
  out.judged.reference = setName(references);
  out.judged.joiner = " against ";
  PairedRenders pairs;
  for (std::size_t i = 0; i < k; ++i) {
    const Image reference = readJudged(references[i].file), candidate = readJudged(candidates[i].file);
    if (reference.width != candidate.width || reference.height != candidate.height)
      throw std::invalid_argument(candidates[i].file.string() + ": " + std::to_string(candidate.width) + "x" +
                                  std::to_string(candidate.height) + " pixels, and " + references[i].file.string() +
                                  " has " + std::to_string(reference.width) + "x" + std::to_string(reference.height));
    pairs.add(reference, candidate);
  }
  out.judged.runs.push_back(
      {out.judged.reference, nlohmann::json::object(), 0,
       compareImages(pairs.referenceMean(), pairs.candidateMean(), tolerances, statistical ? &pairs : nullptr)});
  return out;
}

}  // namespace facet::analysis
