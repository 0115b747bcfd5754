#include "engine/stages/stages.h"

#include <gtest/gtest.h>

#include <set>
#include <string_view>
#include <utility>

namespace facet {
namespace {

// `facet render` prints these names and writes them as --json keys, and a
// report merges stages by value: each stage keeps its own name.
TEST(StagesTest, EachStageHasItsOwnPrintedName) {
  const std::pair<Stage, std::string_view> expected[] = {{Stage::RefineBvh, "refine + BVH"},
                                                         {Stage::Device, "device"},
                                                         {Stage::Environment, "environment"},
                                                         {Stage::Pipelines, "pipelines"},
                                                         {Stage::TraceShade, "trace + shade"},
                                                         {Stage::TopLevels, "top levels"},
                                                         {Stage::DiceGrid, "dice grid"},
                                                         {Stage::DiceCells, "dice cells"},
                                                         {Stage::Quadtrees, "quadtrees"},
                                                         {Stage::Refit, "refit"},
                                                         {Stage::Intersect, "intersect"},
                                                         {Stage::Compact, "compact"},
                                                         {Stage::Fallbacks, "fallbacks"},
                                                         {Stage::Surface, "surface"},
                                                         {Stage::ShadowRays, "shadow rays"},
                                                         {Stage::ShadowFallbacks, "shadow fallbacks"},
                                                         {Stage::Gather, "gather"},
                                                         {Stage::Resolve, "resolve"}};
  std::set<std::string_view> names;
  for (const auto& [stage, name] : expected) {
    EXPECT_EQ(stageName(stage), name);
    names.insert(stageName(stage));
  }
  EXPECT_EQ(names.size(), std::size(expected));
}

// Readers that sum the stages of casting and shading leave these out.
TEST(StagesTest, OnlyTheDeviceAndThePipelinesAreStartUp) {
  EXPECT_TRUE(isStartup(Stage::Device));
  EXPECT_TRUE(isStartup(Stage::Pipelines));
  for (Stage stage : {Stage::RefineBvh, Stage::Environment, Stage::TopLevels, Stage::Surface, Stage::Resolve})
    EXPECT_FALSE(isStartup(stage)) << stageName(stage);
}

}  // namespace
}  // namespace facet
