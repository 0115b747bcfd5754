// The scene as the GPU ray caster receives it (engine/gpu_backend/gpu_scene.h):
// the collapsed 4-wide top levels, the rebased patches, and the shared
// headers' layout as glslang lays them out.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "tests/support/channels_gltf.h"
#include "tests/support/translate_scene.h"
#include "engine/gpu_backend/gpu_scene.h"
#include "scenes/scene_file.h"
#include "facet_gpu_backend_test_spirv/spirv.h"

namespace facet::gpu_backend {
namespace {

namespace layout = gpu_layout;

// A torture cage by name, or a test mesh by its file name.
scene::Scene cageScene(const std::string& name, const glm::dvec3& offset = glm::dvec3(0.0)) {
  const std::filesystem::path file = name.ends_with(".obj") ? std::filesystem::path(FACET_TEST_DATA_DIR) / name
                                                            : std::filesystem::path(FACET_CAGE_DIR) / (name + ".obj");
  scene::Scene scene = scene::loadScene(file);
  facet::testing::translateScene(scene, offset);
  return scene;
}

float boxValue(const GpuScene& packed, std::size_t node, int texel, int slot) {
  return std::bit_cast<float>(
      packed.topNodes[node * layout::FACET_BVH4_TEXELS + std::size_t(texel)][std::size_t(slot)]);
}

class PackedCage : public ::testing::TestWithParam<std::string> {};

// Every patch is reached exactly once from the root, through boxes that
// contain its control hull, within the traversal's depth.
TEST_P(PackedCage, TopLevelsReachEveryPatchOnceThroughEnclosingBoxes) {
  const scene::Scene scene = cageScene(GetParam());
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const glm::dvec3 origin = scene.camera.eye;
  const GpuScene packed = packScene(scene, geometry, origin, 0.0, false);
  ASSERT_EQ(packed.objects.size(), 1u);
  const layout::ObjectRange& range = packed.objects[0];
  const scene::PatchBvh& bvh = geometry.objects[0].bvh;
  const std::size_t topNodes = packed.topNodes.size() / layout::FACET_BVH4_TEXELS;
  std::vector<int> reached(bvh.leafPatches().size(), 0);
  struct Visit {
    std::uint32_t node;
    int depth;
  };
  std::vector<Visit> stack{{packed.rootNode, 1}};
  int deepest = 0;
  while (!stack.empty()) {
    const Visit visit = stack.back();
    stack.pop_back();
    ASSERT_LT(visit.node, topNodes);
    deepest = std::max(deepest, visit.depth);
    const layout::uint* references =
        packed.topNodes[visit.node * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES].data();
    for (int slot = 0; slot < 4; ++slot) {
      const layout::uint reference = references[slot];
      if (reference == layout::FACET_BVH4_EMPTY) continue;
      if (reference >= range.firstQuadtreeNode) {
        const std::uint32_t offset = reference - range.firstQuadtreeNode;
        ASSERT_EQ(offset % range.quadtreeNodes, 0u);
        const std::size_t patch = offset / range.quadtreeNodes;
        ASSERT_LT(patch, reached.size());
        ++reached[patch];
        const scene::Aabb hull = scene::patchBounds(geometry.objects[0].surface.bezierPatch(bvh.leafPatches()[patch]));
        for (int axis = 0; axis < 3; ++axis) {
          EXPECT_LE(double(boxValue(packed, visit.node, 2 * axis, slot)), hull.lo[axis] - origin[axis]);
          EXPECT_GE(double(boxValue(packed, visit.node, 2 * axis + 1, slot)), hull.hi[axis] - origin[axis]);
        }
      } else {
        stack.push_back({reference, visit.depth + 1});
      }
    }
  }
  for (int count : reached) EXPECT_EQ(count, 1);
  EXPECT_EQ(deepest + int(range.quadtreeLevels), packed.depth);
  EXPECT_LE(std::uint32_t(deepest) + range.quadtreeLevels, layout::FACET_BVH4_MAX_DEPTH);
  // Four wide: about a third of the binary tree's depth... at most its depth.
  EXPECT_LE(deepest, bvh.statistics().maxDepth + 1);
}

// A patch's points as the GPU reads them (compute/layout/patch_records.h),
// relative to the eye or, with `placed` false, to the patch's first point.
scene::BezierPatch packedPatch(const GpuScene& packed, const Texel& header, bool placed) {
  scene::BezierPatch patch;
  patch.gregory = header[layout::FACET_HEADER_KIND] == layout::FACET_PATCH_GREGORY;
  const std::uint32_t firstPoint = header[layout::FACET_HEADER_FIRST_POINT];
  const glm::dvec3 anchor = placed ? glm::dvec3(glm::vec3(packed.points[firstPoint])) : glm::dvec3(0.0);
  auto read = [&](std::uint32_t k) {
    return k == 0 ? anchor : anchor + glm::dvec3(glm::vec3(packed.points[firstPoint + k]));
  };
  for (std::uint32_t k = 0; k < 16; ++k) patch.points[k] = read(k);
  if (patch.gregory)
    for (std::uint32_t k = 0; k < 4; ++k) patch.alternates[k] = read(16 + k);
  return patch;
}

// The float points, relative to the eye, still describe OpenSubdiv's surface
// to float precision of the scene's size, however far it is from the origin.
TEST_P(PackedCage, RebasedPointsEvaluateToTheLimitSurfaceFarFromTheOrigin) {
  const scene::Scene scene = cageScene(GetParam(), glm::dvec3(1e6, -2e6, 3e6));
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const scene::SubdivisionSurface& surface = geometry.objects[0].surface;
  const glm::dvec3 origin = scene.camera.eye;
  const GpuScene packed = packScene(scene, geometry, origin, 0.0, true);
  ASSERT_EQ(packed.patches.size(), std::size_t(surface.patchCount()));
  EXPECT_EQ(packed.gridVertices,
            packed.patches.size() * std::size_t((packed.objects[0].rate + 1) * (packed.objects[0].rate + 1)));
  std::mt19937 random(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  ASSERT_EQ(packed.headers.size(), layout::FACET_HEADER_TEXELS * packed.patches.size());
  const layout::ObjectRange& range = packed.objects[0];
  for (std::size_t slot = 0; slot < packed.patches.size(); ++slot) {
    const layout::PatchRecord& record = packed.patches[slot];
    const Texel& first = packed.headers[layout::FACET_HEADER_TEXELS * slot];
    const Texel& second = packed.headers[layout::FACET_HEADER_TEXELS * slot + 1];
    const scene::PatchInfo& info = surface.patch(int(record.sourcePatch));
    EXPECT_EQ(first[layout::FACET_HEADER_KIND], surface.bezierPatch(int(record.sourcePatch)).gregory
                                                    ? layout::FACET_PATCH_GREGORY
                                                    : layout::FACET_PATCH_BEZIER);
    EXPECT_EQ(first[layout::FACET_HEADER_TRANSITION_MASK], info.transitionMask);
    EXPECT_EQ(record.ptexFace, std::uint32_t(info.ptexFace));
    EXPECT_EQ(record.coarseFace, std::uint32_t(info.coarseFace));
    EXPECT_EQ(first[layout::FACET_HEADER_RATE], range.rate);
    EXPECT_EQ(second[layout::FACET_HEADER_FIRST_CELL], range.firstCell + slot * range.rate * range.rate);
    EXPECT_EQ(second[layout::FACET_HEADER_FIRST_GRID_VERTEX],
              range.firstGridVertex + slot * (range.rate + 1) * (range.rate + 1));
    EXPECT_EQ(second[layout::FACET_HEADER_FIRST_EDGE_MIDPOINT], range.firstEdgeMidpoint + slot * 4 * range.rate);
    EXPECT_EQ(second[layout::FACET_HEADER_OBJECT], 0u);
    const scene::BezierPatch fromGpu = packedPatch(packed, first, true);
    for (int sample = 0; sample < 4; ++sample) {
      const double s = unit(random), t = unit(random);
      const glm::dvec3 osd = surface
                                 .evaluatePatch(int(record.sourcePatch), record.faceU0 + s * record.faceSize,
                                                record.faceV0 + t * record.faceSize)
                                 .position;
      worst = std::max(worst, glm::length(scene::evaluateBezierPatch(fromGpu, s, t).position + origin - osd));
    }
  }
  const double sceneSize =
      glm::length(surface.bounds().hi - surface.bounds().lo) + glm::length(surface.bounds().centre() - origin);
  EXPECT_LE(worst, 1e-6 * sceneSize) << GetParam();
}

// Derivatives come from points relative to the patch, so a patch far smaller
// than its distance from the eye keeps its normal: 1e4 from the eye, float
// points relative to the eye would turn these normals by up to 2 radians.
TEST_P(PackedCage, PatchPointsKeepTheNormalFarFromTheEye) {
  const scene::Scene scene = cageScene(GetParam(), glm::dvec3(0.0));
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const scene::SubdivisionSurface& surface = geometry.objects[0].surface;
  const GpuScene packed = packScene(scene, geometry, glm::dvec3(1e4, -2e4, 3e4), 0.0, false);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (std::size_t slot = 0; slot < packed.patches.size(); ++slot) {
    const layout::PatchRecord& record = packed.patches[slot];
    const scene::BezierPatch fromGpu = packedPatch(packed, packed.headers[layout::FACET_HEADER_TEXELS * slot], false);
    for (int sample = 0; sample < 4; ++sample) {
      const double s = unit(random), t = unit(random);
      const scene::LimitPoint osd = surface.evaluatePatch(int(record.sourcePatch), record.faceU0 + s * record.faceSize,
                                                          record.faceV0 + t * record.faceSize);
      const glm::dvec3 normal = glm::cross(osd.du, osd.dv);
      if (glm::length(normal) < 1e-3 * glm::length(osd.du) * glm::length(osd.dv)) continue;
      const scene::BezierSample gpu = scene::evaluateBezierPatch(fromGpu, s, t);
      const double cosine = glm::dot(glm::normalize(normal), glm::normalize(glm::cross(gpu.du, gpu.dv)));
      worst = std::max(worst, std::acos(std::clamp(cosine, -1.0, 1.0)));
    }
  }
  EXPECT_LE(worst, 1e-4) << GetParam();
}

// Over several objects the scene's own nodes lead to every object's patches,
// each once, through boxes that hold the object.
TEST(PackedScene, OneRootReachesEveryPatchOfEveryObjectOnce) {
  const scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "preview.json");
  ASSERT_GT(scene.objects.size(), 4u);
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const GpuScene packed = packScene(scene, geometry, scene.camera.eye, 0.0, false);
  const std::size_t topNodes = packed.topNodes.size() / layout::FACET_BVH4_TEXELS;
  std::map<std::uint32_t, int> reached;  // quadtree root -> times
  std::vector<std::uint32_t> stack{packed.rootNode};
  while (!stack.empty()) {
    const std::uint32_t node = stack.back();
    stack.pop_back();
    ASSERT_LT(node, topNodes);
    for (int slot = 0; slot < 4; ++slot) {
      const layout::uint reference =
          packed.topNodes[node * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES][std::size_t(slot)];
      if (reference == layout::FACET_BVH4_EMPTY) continue;
      if (reference >= topNodes)
        ++reached[reference];
      else
        stack.push_back(reference);
    }
  }
  std::size_t patches = 0;
  for (const layout::ObjectRange& range : packed.objects)
    for (std::uint32_t p = 0; p < range.patchCount; ++p, ++patches)
      EXPECT_EQ(reached[range.firstQuadtreeNode + p * range.quadtreeNodes], 1) << "object patch " << p;
  EXPECT_EQ(reached.size(), patches);
}

INSTANTIATE_TEST_SUITE_P(TortureCages, PackedCage,
                         ::testing::Values("cube", "valence_3_to_10", "pole24", "boundary_hole", "creased_box",
                                           "ngon_prism", "thin_slab", "nearly_flat", "suzanne", "catmark_bishop.obj"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

// The shared headers compiled as GLSL at build time (shaders/gpu_layout.comp):
// the member offsets and array strides glslang chose for the std430 buffers
// are the C++ ones.
class SpirvLayout {
 public:
  explicit SpirvLayout(std::span<const std::uint32_t> words) {
    for (size_t at = 5; at < words.size();) {
      const std::uint32_t count = words[at] >> 16, opcode = words[at] & 0xffffu;
      const std::span<const std::uint32_t> operands = words.subspan(at + 1, count - 1);
      constexpr std::uint32_t kOpName = 5, kOpMemberName = 6, kOpTypeRuntimeArray = 29, kOpDecorate = 71,
                              kOpMemberDecorate = 72, kArrayStride = 6, kOffset = 35;
      if (opcode == kOpName) names_[operands[0]] = text(operands.subspan(1));
      if (opcode == kOpMemberName) memberNames_[{operands[0], operands[1]}] = text(operands.subspan(2));
      if (opcode == kOpTypeRuntimeArray) elementOf_[operands[0]] = operands[1];
      if (opcode == kOpDecorate && operands[1] == kArrayStride) strides_[operands[0]] = operands[2];
      if (opcode == kOpMemberDecorate && operands[2] == kOffset) offsets_[{operands[0], operands[1]}] = operands[3];
      at += count;
    }
  }

  // Offset of `member` in the buffer-block struct called `type`.
  std::optional<std::uint32_t> offset(const std::string& type, const std::string& member) const {
    for (const auto& [key, name] : memberNames_)
      if (name == member && nameOf(key.first) == type && offsets_.count(key)) return offsets_.at(key);
    return std::nullopt;
  }

  // Stride of the runtime array whose elements are `type`.
  std::optional<std::uint32_t> stride(const std::string& type) const {
    for (const auto& [array, element] : elementOf_)
      if (nameOf(element) == type && strides_.count(array)) return strides_.at(array);
    return std::nullopt;
  }

 private:
  static std::string text(std::span<const std::uint32_t> words) {
    std::string result;
    for (std::uint32_t word : words)
      for (int byte = 0; byte < 4; ++byte) {
        const char c = static_cast<char>((word >> (8 * byte)) & 0xffu);
        if (c == '\0') return result;
        result.push_back(c);
      }
    return result;
  }
  std::string nameOf(std::uint32_t id) const { return names_.count(id) ? names_.at(id) : std::string(); }

  std::map<std::uint32_t, std::string> names_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> memberNames_;
  std::map<std::uint32_t, std::uint32_t> elementOf_, strides_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> offsets_;
};

// Texcoord texels read back as the Gregory patch texcoord.glsl evaluates
// are OpenSubdiv's face-varying patch, to float precision.
TEST(PackedTexcoords, AreTheFaceVaryingPatchesInGregoryForm) {
  const scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_TEST_DATA_DIR) / "uv_checker_cube.obj");
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const scene::SubdivisionSurface& surface = geometry.objects[0].surface;
  const GpuScene packed = packScene(scene, geometry, scene.camera.eye, 0.0, false);
  ASSERT_EQ(packed.texcoords.size(), layout::FACET_TEXCOORD_TEXELS * packed.patches.size());
  double worst = 0.0;
  for (const layout::PatchRecord& record : packed.patches) {
    ASSERT_NE(record.firstTexcoord, layout::FACET_NO_TEXCOORDS);
    scene::BezierPatch fromGpu;
    fromGpu.gregory = true;
    std::array<glm::dvec3, 20> points;
    for (std::uint32_t k = 0; k < layout::FACET_TEXCOORD_TEXELS; ++k) {
      const glm::vec4 texel = packed.texcoords[record.firstTexcoord + k];
      points[2 * k] = glm::dvec3(texel.x, texel.y, 0.0);
      points[2 * k + 1] = glm::dvec3(texel.z, texel.w, 0.0);
    }
    std::copy(points.begin(), points.begin() + 16, fromGpu.points.begin());
    std::copy(points.begin() + 16, points.end(), fromGpu.alternates.begin());
    for (double s : {0.0, 0.3, 0.8})
      for (double t : {0.1, 0.5, 1.0}) {
        const scene::LimitTexcoord osd = surface.evaluateTexcoord(
            int(record.sourcePatch), record.faceU0 + s * record.faceSize, record.faceV0 + t * record.faceSize);
        const scene::BezierSample gpu = scene::evaluateBezierPatch(fromGpu, s, t);
        worst = std::max({worst, glm::distance(glm::dvec2(gpu.position), osd.uv),
                          glm::distance(glm::dvec2(gpu.du), osd.du * double(record.faceSize))});
      }
  }
  EXPECT_LT(worst, 1e-6);
}

// Every channel of a glTF quad with both sets and colours, subdivided: the
// channels follow one another per patch as channel_texel() finds them, and
// read back as Gregory patches they are OpenSubdiv's.
TEST(PackedTexcoords, EveryChannelFollowsTheLayoutOfTexcoordGlsl) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("facet_packed_channels_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  scene::Scene scene = scene::loadScene(facet::testing::writeChannelQuad(
      dir, "quad", {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TEXCOORD_1", 2}, {"COLOR_0", 3}}, {}));
  std::filesystem::remove_all(dir);
  for (scene::Object& object : scene.objects) object.subdivision = scene::Subdivision::CatmullClark;
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const scene::SubdivisionSurface& surface = geometry.objects[0].surface;
  const GpuScene packed = packScene(scene, geometry, scene.camera.eye, 0.0, false);
  ASSERT_EQ(packed.objects[0].channels,
            layout::FACET_CHANNEL_TEXCOORD0 | layout::FACET_CHANNEL_TEXCOORD1 | layout::FACET_CHANNEL_COLOR);
  const std::uint32_t perPatch = 2 * layout::FACET_TEXCOORD_TEXELS + layout::FACET_COLOR_TEXELS;
  ASSERT_EQ(packed.texcoords.size(), perPatch * packed.patches.size());
  double worst = 0.0;
  for (const layout::PatchRecord& record : packed.patches) {
    scene::BezierPatch uv1, colour;
    uv1.gregory = colour.gregory = true;
    for (std::uint32_t k = 0; k < 20; ++k) {
      const glm::vec4 pair = packed.texcoords[record.firstTexcoord + layout::FACET_TEXCOORD_TEXELS + k / 2];
      const glm::dvec3 p = k % 2 ? glm::dvec3(pair.z, pair.w, 0.0) : glm::dvec3(pair.x, pair.y, 0.0);
      const glm::dvec3 c(packed.texcoords[record.firstTexcoord + 2 * layout::FACET_TEXCOORD_TEXELS + k]);
      (k < 16 ? uv1.points[k] : uv1.alternates[k - 16]) = p;
      (k < 16 ? colour.points[k] : colour.alternates[k - 16]) = c;
    }
    for (double s : {0.0, 0.3, 0.8})
      for (double t : {0.1, 0.5, 1.0}) {
        const double u = record.faceU0 + s * record.faceSize, v = record.faceV0 + t * record.faceSize;
        const int source = int(record.sourcePatch);
        worst = std::max(
            {worst,
             glm::distance(glm::dvec2(scene::evaluateBezierPatch(uv1, s, t).position),
                           surface.evaluateTexcoord(source, u, v, 1).uv),
             glm::distance(scene::evaluateBezierPatch(colour, s, t).position, surface.evaluateColor(source, u, v))});
      }
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(PackedTexcoords, ACageWithoutThemHasNone) {
  const scene::Scene scene = cageScene("cube");
  const GpuScene packed = packScene(scene, scene::buildGeometry(scene), scene.camera.eye, 0.0, false);
  EXPECT_TRUE(packed.texcoords.empty());
  for (const layout::PatchRecord& record : packed.patches) EXPECT_EQ(record.firstTexcoord, layout::FACET_NO_TEXCOORDS);
}

TEST(GpuLayout, GlslLayoutOfTheSharedHeadersIsTheCppLayout) {
  using namespace gpu_layout;
  ASSERT_GT(facet::test_spirv::gpu_layout.size(), 5u);
  ASSERT_EQ(facet::test_spirv::gpu_layout[0], 0x07230203u);  // SPIR-V magic
  const SpirvLayout layout(facet::test_spirv::gpu_layout);

  EXPECT_EQ(layout.stride("PatchRecord"), sizeof(PatchRecord));
  EXPECT_EQ(layout.stride("ObjectRange"), sizeof(ObjectRange));
  EXPECT_EQ(layout.stride("ShadowRayRecord"), sizeof(ShadowRayRecord));
  EXPECT_EQ(layout.stride("HitRecord"), sizeof(HitRecord));
  EXPECT_EQ(layout.stride("FallbackRecord"), sizeof(FallbackRecord));
  EXPECT_EQ(layout.stride("PathState"), sizeof(PathState));
#define FACET_EXPECT_MEMBER(type, member) \
  EXPECT_EQ(layout.offset(#type, #member), offsetof(type, member)) << #type "." #member
  FACET_EXPECT_MEMBER(PatchRecord, sourcePatch);
  FACET_EXPECT_MEMBER(PatchRecord, coarseFace);
  FACET_EXPECT_MEMBER(PatchRecord, firstNormal);
  FACET_EXPECT_MEMBER(PatchRecord, firstTexcoord);
  FACET_EXPECT_MEMBER(PatchRecord, faceU0);
  FACET_EXPECT_MEMBER(PatchRecord, faceV0);
  FACET_EXPECT_MEMBER(PatchRecord, faceSize);
  FACET_EXPECT_MEMBER(PatchRecord, ptexFace);
  FACET_EXPECT_MEMBER(ObjectRange, firstPatch);
  FACET_EXPECT_MEMBER(FrameParams, rootNode);
  FACET_EXPECT_MEMBER(ObjectRange, rate);
  FACET_EXPECT_MEMBER(ObjectRange, firstQuadtreeNode);
  FACET_EXPECT_MEMBER(ObjectRange, firstEdgeMidpoint);
  FACET_EXPECT_MEMBER(ObjectRange, channels);
  FACET_EXPECT_MEMBER(ObjectRange, flags);
  FACET_EXPECT_MEMBER(ObjectRange, alphaCutoff);
  FACET_EXPECT_MEMBER(ObjectRange, alphaScaleY);
  FACET_EXPECT_MEMBER(ObjectRange, alphaTexCoord);
  FACET_EXPECT_MEMBER(ShadowRayRecord, slot);
  FACET_EXPECT_MEMBER(RenderCounters, shadowX);
  FACET_EXPECT_MEMBER(RenderCounters, cameraFallbacks);
  FACET_EXPECT_MEMBER(RenderCounters, cameraFallbackX);
  FACET_EXPECT_MEMBER(RenderCounters, shadowFallbackZ);
  FACET_EXPECT_MEMBER(RenderCounters, livePaths);
  FACET_EXPECT_MEMBER(RenderCounters, liveZ);
  FACET_EXPECT_MEMBER(FallbackRecord, cell);
  FACET_EXPECT_MEMBER(FallbackRecord, tParam);
  FACET_EXPECT_MEMBER(FrameParams, windowWidth);
  FACET_EXPECT_MEMBER(FrameParams, firstPixel);
  FACET_EXPECT_MEMBER(FrameParams, fallbackCapacity);
  FACET_EXPECT_MEMBER(FrameParams, patchCount);
  FACET_EXPECT_MEMBER(FrameParams, tolerance);
  FACET_EXPECT_MEMBER(FrameParams, dfgSize);
  FACET_EXPECT_MEMBER(FrameParams, compensationSize);
  FACET_EXPECT_MEMBER(FrameParams, transmissionBounces);
  FACET_EXPECT_MEMBER(FrameParams, eyeSigmaB);
  FACET_EXPECT_MEMBER(PathState, transmissionTaken);
#undef FACET_EXPECT_MEMBER
}

}  // namespace
}  // namespace facet::gpu_backend
