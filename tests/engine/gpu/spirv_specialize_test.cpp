// The constants a pipeline is created with are folded into its code before
// the driver sees it, and the code they leave dead goes with them.
#include "engine/gpu/spirv_specialize.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "facet_test_kernels/spirv.h"

namespace facet::gpu::spirv {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr std::uint32_t kOpFunction = 54;

// How many instructions of the module have one of `opcodes`.
int countOf(std::span<const std::uint32_t> words, std::initializer_list<std::uint32_t> opcodes) {
  int count = 0;
  for (std::size_t i = 5; i < words.size(); i += words[i] >> 16) {
    for (std::uint32_t op : opcodes) count += (words[i] & 0xffff) == op;
    if ((words[i] >> 16) == 0) break;
  }
  return count;
}

// OpSpecConstantTrue, False, the scalar, Composite and Op.
int specConstants(std::span<const std::uint32_t> words) { return countOf(words, {48, 49, 50, 51, 52}); }

TEST(SpirvSpecialize, AConstantThatTurnsAFunctionOffTakesItOutOfTheCode) {
  const std::span<const std::uint32_t> gated = test_spirv::constant_gated;
  ASSERT_GT(specConstants(gated), 0);
  ASSERT_EQ(countOf(gated, {kOpFunction}), 2);  // main and polynomial

  const std::vector<std::uint32_t> off = specialize(gated, {{0, {0}}}, "gated");
  EXPECT_EQ(specConstants(off), 0);
  EXPECT_EQ(countOf(off, {kOpFunction}), 1);
  EXPECT_LT(off.size(), gated.size());

  const std::vector<std::uint32_t> byDefault = specialize(gated, {}, "gated");
  EXPECT_EQ(specConstants(byDefault), 0);
  EXPECT_EQ(countOf(byDefault, {kOpFunction}), 2);
}

TEST(SpirvSpecialize, TheWorkgroupSizeConstantIsFoldedToo) {
  const std::vector<std::uint32_t> fill = specialize(test_spirv::specialized_fill, {{0, {32}}, {1, {1}}}, "fill");
  EXPECT_EQ(specConstants(fill), 0);
}

TEST(SpirvSpecialize, LiteralsFollowSpirvsRules) {
  EXPECT_THAT(literalWords({0, "b", ScalarKind::Bool, 32}, 2.0), ElementsAre(1u));
  EXPECT_THAT(literalWords({0, "b", ScalarKind::Bool, 32}, 0.0), ElementsAre(0u));
  EXPECT_THAT(literalWords({0, "i", ScalarKind::Int, 32}, -2.0), ElementsAre(0xfffffffeu));
  EXPECT_THAT(literalWords({0, "i", ScalarKind::Int, 16}, -2.0), ElementsAre(0xfffffffeu));  // sign-extended
  EXPECT_THAT(literalWords({0, "u", ScalarKind::UInt, 16}, 65535.0), ElementsAre(0xffffu));
  EXPECT_THAT(literalWords({0, "i", ScalarKind::Int, 64}, -1.0), ElementsAre(0xffffffffu, 0xffffffffu));
  EXPECT_THAT(literalWords({0, "f", ScalarKind::Float, 32}, 1.5), ElementsAre(std::bit_cast<std::uint32_t>(1.5f)));
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(0.1);
  EXPECT_THAT(literalWords({0, "d", ScalarKind::Float, 64}, 0.1),
              ElementsAre(std::uint32_t(bits), std::uint32_t(bits >> 32)));  // low word first
}

TEST(SpirvSpecialize, EachModuleAndValuesAreOptimizedOncePerProcess) {
  const std::span<const std::uint32_t> gated = test_spirv::constant_gated;
  const auto off = specializeOnce(gated, {{0, {0}}}, "gated");
  EXPECT_EQ(*off, specialize(gated, {{0, {0}}}, "gated"));
  // The same module under another label, as another device would give it.
  EXPECT_EQ(specializeOnce(std::vector<std::uint32_t>(gated.begin(), gated.end()), {{0, {0}}}, "again"), off);
  const auto on = specializeOnce(gated, {{0, {1}}}, "gated");
  EXPECT_NE(on, off);
  EXPECT_EQ(*on, specialize(gated, {{0, {1}}}, "gated"));
  const auto fill = specializeOnce(test_spirv::specialized_fill, {{0, {32}}, {1, {1}}}, "fill");
  EXPECT_NE(*fill, *off);
  EXPECT_EQ(specializeOnce(test_spirv::specialized_fill, {{1, {1}}, {0, {32}}}, "fill"), fill);
}

TEST(SpirvSpecialize, CodeTheOptimizerRejectsIsAnErrorNamingTheModule) {
  const std::vector<std::uint32_t> truncated(test_spirv::constant_gated.begin(),
                                             test_spirv::constant_gated.begin() + 40);
  try {
    specialize(truncated, {}, "cut short");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("shader module 'cut short'"));
  }
  for (int attempt = 0; attempt < 2; ++attempt)  // a failure is not remembered as code
    EXPECT_THROW(specializeOnce(truncated, {}, "cut short"), Error);
}

}  // namespace
}  // namespace facet::gpu::spirv
