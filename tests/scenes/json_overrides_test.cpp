// --set PATH=VALUE: the path's syntax, how the value is read, where the
// merge creates objects, what it refuses, and which fields it concerns.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

#include "scenes/json_overrides.h"

namespace facet::scene {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

json applied(json document, const std::string& assignment) {
  applyJsonOverride(document, parseJsonOverride(assignment));
  return document;
}

std::string errorOf(const json& document, const std::string& assignment) {
  try {
    applied(document, assignment);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(JsonOverrides, SplitAtTheFirstEquals) {
  const JsonOverride o = parseJsonOverride("objects[0].name=a=b");
  EXPECT_EQ(o.path, "objects[0].name");
  EXPECT_EQ(o.value, "a=b");
  EXPECT_EQ(o.text(), "objects[0].name=a=b");
}

TEST(JsonOverrides, ValuesAreJsonWhereTheyParseAndStringsOtherwise) {
  EXPECT_EQ(applied({}, "render.spp=16")["render"]["spp"], json(16));
  EXPECT_EQ(applied({}, "environment.occlusion=false")["environment"]["occlusion"], json(false));
  EXPECT_EQ(applied({}, "camera.eye=[0, 1, 2]")["camera"]["eye"], json::array({0, 1, 2}));
  EXPECT_EQ(applied({}, "a={\"preset\": \"gold\"}")["a"], json({{"preset", "gold"}}));
  EXPECT_EQ(applied({}, "a=silver")["a"], json("silver"));
  EXPECT_EQ(applied({}, "a=\"16\"")["a"], json("16"));  // quoted: the string
  EXPECT_EQ(applied({}, "a=")["a"], json(""));
}

TEST(JsonOverrides, MissingObjectsOnThePathAreMadeAndOthersKept) {
  const json document = {{"render", {{"width", 64}}}, {"materials", {{"gold", {{"preset", "gold"}}}}}};
  const json result = applied(applied(document, "render.spp=4"), "materials.gold.roughness=0.2");
  EXPECT_EQ(result["render"], json({{"width", 64}, {"spp", 4}}));
  EXPECT_EQ(result["materials"]["gold"], json({{"preset", "gold"}, {"roughness", 0.2}}));
  EXPECT_EQ(applied({}, "camera.fov=40"), json({{"camera", {{"fov", 40}}}}));
}

TEST(JsonOverrides, IndicesNameExistingElements) {
  const json document = {{"objects", json::array({{{"mesh", "a.obj"}}, {{"mesh", "b.obj"}}})}};
  const json result = applied(document, "objects[1].material=silver");
  EXPECT_EQ(result["objects"][1], json({{"mesh", "b.obj"}, {"material", "silver"}}));
  EXPECT_EQ(result["objects"][0], document["objects"][0]);
  EXPECT_EQ(errorOf(document, "objects[2].material=silver"),
            "--set objects[2].material=silver: objects has 2 entries (indices from 0)");
  EXPECT_EQ(errorOf({}, "lights[0].color=1"), "--set lights[0].color=1: lights is not in the scene");
  EXPECT_EQ(errorOf(document, "objects.name=x"), "--set objects.name=x: objects is an array, not an object");
}

TEST(JsonOverrides, AScalarOnThePathIsNamed) {
  const json document = {{"objects", json::array({{{"mesh", "a.obj"}, {"material", "gold"}}})}};
  EXPECT_EQ(errorOf(document, "objects[0].material.roughness=0.2"),
            "--set objects[0].material.roughness=0.2: objects[0].material is a string, not an object");
}

TEST(JsonOverrides, MalformedAssignmentsAreRefused) {
  for (const char* bad : {"render.spp", "=4", ".spp=4", "render.=4", "render..spp=4", "objects[]=1", "objects[x]=1",
                          "objects[0]x=1", "objects[0=1", "[0]=1"})
    EXPECT_THROW(parseJsonOverride(bad), std::invalid_argument) << bad;
  EXPECT_THAT(errorOf({}, "render.spp"), HasSubstr("--set 'render.spp': expected PATH=VALUE"));
  EXPECT_NO_THROW(parseJsonOverride("materials.red plastic.roughness=0.2"));  // keys may hold spaces
  EXPECT_NO_THROW(parseJsonOverride("a[0][1].b=1"));
}

TEST(JsonOverrides, AnOverrideConcernsItsFieldWhatItHoldsAndWhatHoldsIt) {
  const JsonOverride o = parseJsonOverride("objects[0].material=x");
  EXPECT_TRUE(overrideConcerns(o, "objects[0].material"));
  EXPECT_TRUE(overrideConcerns(o, "objects[0].material.roughness"));
  EXPECT_TRUE(overrideConcerns(o, "objects[0]"));
  EXPECT_FALSE(overrideConcerns(o, "objects[0].mesh"));
  EXPECT_FALSE(overrideConcerns(o, "objects[0].materials"));
  EXPECT_FALSE(overrideConcerns(o, "objects[1]"));
  EXPECT_FALSE(overrideConcerns(o, ""));
}

}  // namespace
}  // namespace facet::scene
