// Stored renders judged against golden ones: paired by the seed their
// settings record, judged by the paired t-test where they are an estimate,
// and refused where the two sets estimate different pictures (made-up
// images written as EXRs with the provenance facet render writes).
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "analysis/stored_parity.h"
#include "engine/image/exr_file.h"
#include "tests/support/noisy_square.h"
#include "tests/support/temp_dir.h"

namespace facet::analysis {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDigest = "00112233445566aa";

// The settings text facet render writes for a render of seed `seed`.
std::string settings(const std::string& backend, int seed, const std::string& spp = "4") {
  return "backend=" + backend + " size=20x20 spp=" + spp + " method=exact bounces=8 ibl=sampled iblSamples=4 " +
         "iblOcclusion=on iblSeed=" + std::to_string(seed);
}

class StoredParity : public testing::TempDirTest {
 protected:
  // A noisy estimate of seed `seed` (10% noise on 0.5), the same numbers for
  // every call with that seed, as both backends draw them.
  static Image estimate(int seed, float scale = 1.0f) {
    std::mt19937 random(std::uint32_t(100 + seed));
    std::normal_distribution<float> noise(0.5f, 0.05f);
    return testing::noisySquare([&] { return noise(random) * scale; });
  }
  // Written as `name`.exr with its provenance.
  fs::path write(const std::string& name, const Image& image, const ExrProvenance& made) {
    ExrOptions options;
    options.metadata.provenance = made;
    const fs::path file = dir_ / (name + ".exr");
    writeExr(file, image, options);
    return file;
  }
  fs::path render(const std::string& set, int seed, float scale = 1.0f, const std::string& spp = "4",
                  const std::string& digest = kDigest) {
    return write(set + std::to_string(seed), estimate(seed, scale),
                 {"facet 0.0.0", settings(set == "golden" ? "cpu" : "gpu", seed, spp), digest, std::uint32_t(seed)});
  }
  std::vector<fs::path> set(const std::string& name, std::vector<int> seeds, float scale = 1.0f) {
    std::vector<fs::path> files;
    for (int seed : seeds) files.push_back(render(name, seed, scale));
    return files;
  }
};

TEST_F(StoredParity, TheSettingsTextReadsAsFields) {
  const auto fields = settingsFields("backend=gpu size=64x48 spp=4 ibl=none flag");
  EXPECT_EQ(fields.at("backend"), "gpu");
  EXPECT_EQ(fields.at("size"), "64x48");
  EXPECT_EQ(fields.at("ibl"), "none");
  EXPECT_EQ(fields.at("flag"), "");
  EXPECT_EQ(fields.size(), 5u);
}

TEST_F(StoredParity, AHealthyCandidateSetPassesThePairedTest) {
  const StoredJudgement judged =
      judgeStoredRenders(set("golden", {0, 1, 2, 3, 4, 5, 6, 7}), set("candidate", {0, 1, 2, 3, 4, 5, 6, 7}), {});
  ASSERT_EQ(judged.judged.runs.size(), 1u);
  const ParityReport& report = judged.judged.runs.front().report;
  EXPECT_TRUE(report.pass) << describe(report);
  EXPECT_EQ(testing::beautyOf(report).test, "paired t-test");
  EXPECT_EQ(testing::beautyOf(report).renders, 8);
  EXPECT_TRUE(judged.warnings.empty());
  EXPECT_EQ(judged.judged.settings["seeds"], nlohmann::json({0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(judged.judged.settings["pictureDigest"], kDigest);
}

TEST_F(StoredParity, APercentBiasFails) {
  const StoredJudgement judged = judgeStoredRenders(set("golden", {0, 1, 2, 3, 4, 5, 6, 7}),
                                                    set("candidate", {0, 1, 2, 3, 4, 5, 6, 7}, 1.01f), {});
  const ParityReport& report = judged.judged.runs.front().report;
  EXPECT_EQ(report.verdict, Verdict::Fail);
  EXPECT_EQ(testing::beautyOf(report).test, "paired t-test");
}

// Paired by place, render i of one set would meet another seed's noise.
TEST_F(StoredParity, RendersArePairedBySeedWhateverTheirOrder) {
  const StoredJudgement judged = judgeStoredRenders(set("golden", {0, 1, 2, 3}), set("candidate", {3, 1, 0, 2}), {});
  const ParityReport& report = judged.judged.runs.front().report;
  EXPECT_TRUE(report.pass) << describe(report);
  EXPECT_EQ(testing::beautyOf(report).maxAbsolute, 0.0);
}

TEST_F(StoredParity, OtherSettingsAreNotComparableAndNamed) {
  const std::vector<fs::path> golden = set("golden", {0, 1});
  const std::vector<fs::path> candidates{render("candidate", 0, 1.0f, "16"), render("candidate", 1, 1.0f, "16")};
  try {
    judgeStoredRenders(golden, candidates, {});
    FAIL() << "judged";
  } catch (const NotComparable& e) {
    EXPECT_EQ(std::string(e.what()), "not comparable with " + golden[0].string() + ": spp 16 against 4");
  }
}

TEST_F(StoredParity, AnotherSceneIsNotComparable) {
  const std::vector<fs::path> candidates{render("candidate", 0, 1.0f, "4", "ffffffffffffffff")};
  EXPECT_THROW(judgeStoredRenders({render("golden", 0)}, candidates, {}), NotComparable);
}

TEST_F(StoredParity, OtherSeedsAreNotComparable) {
  try {
    judgeStoredRenders(set("golden", {0, 1}), set("candidate", {1, 2}), {});
    FAIL() << "judged";
  } catch (const NotComparable& e) {
    EXPECT_NE(std::string(e.what()).find("seeds 1, 2 against 0, 1"), std::string::npos) << e.what();
  }
}

TEST_F(StoredParity, SetsThatCannotBePairedAreBadInput) {
  const std::vector<fs::path> golden = set("golden", {0, 1});
  // A seed twice in one set.
  EXPECT_THROW(judgeStoredRenders({golden[0], golden[0]}, golden, {}), std::invalid_argument);
  // Two pictures in one set.
  EXPECT_THROW(judgeStoredRenders({golden[0], render("golden_spp", 1, 1.0f, "16")}, set("candidate", {0, 1}), {}),
               std::invalid_argument);
  // Counts apart.
  EXPECT_THROW(judgeStoredRenders(golden, {golden[0]}, {}), std::invalid_argument);
  EXPECT_THROW(judgeStoredRenders({}, {}, {}), std::invalid_argument);
}

TEST_F(StoredParity, OnePairOfAnEstimateIsJudgedPerPixelAndSaysSo) {
  const StoredJudgement judged = judgeStoredRenders({render("golden", 0)}, {render("candidate", 0)}, {});
  EXPECT_EQ(testing::beautyOf(judged.judged.runs.front().report).test, "tolerance");
  ASSERT_EQ(judged.warnings.size(), 1u);
  EXPECT_NE(judged.warnings[0].find("one render of a Monte Carlo estimate"), std::string::npos);
}

// Renders without an environment draw fixed numbers: no seed, no t-test, any order.
TEST_F(StoredParity, RendersWithoutAnEnvironmentPairInAnyOrder) {
  const Image picture = estimate(0);
  const ExrProvenance cpu{"facet 0.0.0", "backend=cpu size=20x20 spp=4 method=exact ibl=none", kDigest, {}};
  ExrProvenance gpu = cpu;
  gpu.renderSettings = "backend=gpu size=20x20 spp=4 method=exact ibl=none";
  const StoredJudgement judged = judgeStoredRenders({write("g0", picture, cpu), write("g1", picture, cpu)},
                                                    {write("c0", picture, gpu), write("c1", picture, gpu)}, {});
  const ParityReport& report = judged.judged.runs.front().report;
  EXPECT_TRUE(report.pass);
  EXPECT_EQ(testing::beautyOf(report).test, "tolerance");
  EXPECT_TRUE(judged.warnings.empty());
}

TEST_F(StoredParity, AFileWithoutProvenanceIsJudgedAloneWithAWarning) {
  const fs::path bare = write("bare", estimate(0), {});
  const StoredJudgement judged = judgeStoredRenders({render("golden", 0)}, {bare}, {});
  EXPECT_TRUE(judged.judged.runs.front().report.pass);
  ASSERT_EQ(judged.warnings.size(), 1u);
  EXPECT_NE(judged.warnings[0].find("whether the two renders are comparable is not checked"), std::string::npos);
  EXPECT_THROW(judgeStoredRenders(set("golden", {0, 1}), {bare, bare}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace facet::analysis
