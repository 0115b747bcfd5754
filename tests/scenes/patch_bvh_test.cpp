#include "scenes/patch_bvh.h"
#include "scenes/subdivision_surface.h"
#include "test_cages.h"
#include "tests_scenes_spirv/spirv.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <span>
#include <string>

namespace facet::scene {
namespace {

using testing::loadTortureCage;
using testing::tortureCageNames;

bool contains(const Aabb& box, const glm::dvec3& p, double slack) {
  for (int axis = 0; axis < 3; ++axis)
    if (p[axis] < box.lo[axis] - slack || p[axis] > box.hi[axis] + slack) return false;
  return true;
}

bool contains(const Aabb& outer, const Aabb& inner) {
  return contains(outer, inner.lo, 0.0) && contains(outer, inner.hi, 0.0);
}

class BvhOfEachCage : public ::testing::TestWithParam<std::string> {};

// The convex-hull property the BVH and the exact intersector rely on: every
// surface point OpenSubdiv evaluates lies in the hull box of its patch and in
// the restricted hull of any sub-square holding it (Gregory patches included).
TEST_P(BvhOfEachCage, HullsEncloseTheLimitSurface) {
  SubdivisionSurface surface = SubdivisionSurface::create(loadTortureCage(GetParam()));
  const double slack = 1e-12 * surface.bounds().diagonal();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 0; p < surface.patchCount(); ++p) {
    const BezierPatch& bezier = surface.bezierPatch(p);
    const PatchDomain& domain = surface.patch(p).domain;
    const Aabb whole = patchBounds(bezier);
    for (int sample = 0; sample < 8; ++sample) {
      double s0 = unit(random), s1 = unit(random), t0 = unit(random), t1 = unit(random);
      if (s0 > s1) std::swap(s0, s1);
      if (t0 > t1) std::swap(t0, t1);
      const Aabb piece = restrictBezierPatch(bezier, s0, s1, t0, t1).bounds();
      for (int k = 0; k < 4; ++k) {
        double s = s0 + (s1 - s0) * unit(random), t = t0 + (t1 - t0) * unit(random);
        glm::dvec3 point = surface.evaluatePatch(p, domain.u0 + s * domain.size, domain.v0 + t * domain.size).position;
        ASSERT_TRUE(contains(whole, point, slack)) << "patch " << p;
        ASSERT_TRUE(contains(piece, point, slack))
            << "patch " << p << " piece [" << s0 << "," << s1 << "]x[" << t0 << "," << t1 << "]";
      }
    }
  }
}

TEST_P(BvhOfEachCage, TreeAndGpuArraysDescribeTheSamePatches) {
  SubdivisionSurface surface = SubdivisionSurface::create(loadTortureCage(GetParam()));
  PatchBvh bvh = PatchBvh::build(surface);
  const auto& nodes = bvh.nodes();
  ASSERT_FALSE(nodes.empty());

  // Every patch in exactly one leaf, leaves within their parents' bounds.
  std::vector<int> seen(surface.patchCount(), 0);
  for (int i = 0; i < static_cast<int>(nodes.size()); ++i) {
    const PatchBvh::Node& node = nodes[i];
    if (node.leaf()) {
      for (int k = 0; k < node.patchCount; ++k) {
        int patch = bvh.leafPatches()[node.next + k];
        ++seen[patch];
        EXPECT_TRUE(contains(node.bounds, patchBounds(surface.bezierPatch(patch))));
      }
    } else {
      ASSERT_GT(node.next, i + 1);
      EXPECT_TRUE(contains(node.bounds, nodes[i + 1].bounds));
      EXPECT_TRUE(contains(node.bounds, nodes[node.next].bounds));
    }
  }
  for (int count : seen) EXPECT_EQ(count, 1);

  // GPU nodes: same topology, float bounds that contain the double ones.
  ASSERT_EQ(bvh.gpuNodes().size(), nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const gpu_layout::PatchBvhNode& g = bvh.gpuNodes()[i];
    EXPECT_EQ(g.next, static_cast<gpu_layout::uint>(nodes[i].next));
    EXPECT_EQ(g.patchCount, static_cast<gpu_layout::uint>(nodes[i].patchCount));
    EXPECT_LE(g.minX, nodes[i].bounds.lo.x);
    EXPECT_LE(g.minY, nodes[i].bounds.lo.y);
    EXPECT_LE(g.minZ, nodes[i].bounds.lo.z);
    EXPECT_GE(g.maxX, nodes[i].bounds.hi.x);
    EXPECT_GE(g.maxY, nodes[i].bounds.hi.y);
    EXPECT_GE(g.maxZ, nodes[i].bounds.hi.z);
  }

  // Patch records in leaf order, points in Bézier layout.
  ASSERT_EQ(bvh.gpuPatches().size(), static_cast<size_t>(surface.patchCount()));
  size_t expectedPoints = 0;
  for (size_t slot = 0; slot < bvh.gpuPatches().size(); ++slot) {
    const gpu_layout::PatchRecord& record = bvh.gpuPatches()[slot];
    const int patch = bvh.leafPatches()[slot];
    const PatchInfo& info = surface.patch(patch);
    const BezierPatch& bezier = surface.bezierPatch(patch);
    EXPECT_EQ(record.sourcePatch, static_cast<gpu_layout::uint>(patch));
    EXPECT_EQ(record.ptexFace, static_cast<gpu_layout::uint>(info.ptexFace));
    EXPECT_EQ(record.coarseFace, static_cast<gpu_layout::uint>(info.coarseFace));
    EXPECT_EQ(record.faceU0, static_cast<float>(info.domain.u0));
    EXPECT_EQ(record.faceV0, static_cast<float>(info.domain.v0));
    EXPECT_EQ(record.faceSize, static_cast<float>(info.domain.size));
    EXPECT_EQ(record.kind, bezier.gregory ? gpu_layout::FACET_PATCH_GREGORY : gpu_layout::FACET_PATCH_BEZIER);
    EXPECT_EQ(record.pointCount, bezier.gregory ? 20u : 16u);
    EXPECT_EQ(record.firstPoint, expectedPoints);
    EXPECT_EQ(record.boundaryMask, info.boundaryMask);
    EXPECT_EQ(record.transitionMask, info.transitionMask);
    expectedPoints += record.pointCount;
    const gpu_layout::PatchPoint& corner = bvh.gpuPoints()[record.firstPoint + 15];
    EXPECT_EQ(corner.x, static_cast<float>(bezier.points[15].x));
    EXPECT_EQ(corner.z, static_cast<float>(bezier.points[15].z));
    if (bezier.gregory) {
      EXPECT_EQ(bvh.gpuPoints()[record.firstPoint + 19].y, static_cast<float>(bezier.alternates[3].y));
    }
  }
  EXPECT_EQ(bvh.gpuPoints().size(), expectedPoints);
  EXPECT_EQ(bvh.statistics().gpuBytes, nodes.size() * 32 + bvh.gpuPatches().size() * 48 + expectedPoints * 12);
  EXPECT_NE(describe(bvh.statistics()).find("nodes"), std::string::npos);
}

// End to end for the GPU: the float points, read back through the record
// layout, still describe OpenSubdiv's surface (to float precision).
TEST_P(BvhOfEachCage, GpuArraysEvaluateToTheLimitSurface) {
  SubdivisionSurface surface = SubdivisionSurface::create(loadTortureCage(GetParam()));
  PatchBvh bvh = PatchBvh::build(surface);
  std::mt19937 random(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (const gpu_layout::PatchRecord& record : bvh.gpuPatches()) {
    BezierPatch fromGpu;
    fromGpu.gregory = record.kind == gpu_layout::FACET_PATCH_GREGORY;
    auto read = [&bvh](gpu_layout::uint index) {
      const gpu_layout::PatchPoint& p = bvh.gpuPoints()[index];
      return glm::dvec3(p.x, p.y, p.z);
    };
    for (gpu_layout::uint k = 0; k < 16; ++k) fromGpu.points[k] = read(record.firstPoint + k);
    if (fromGpu.gregory)
      for (gpu_layout::uint k = 0; k < 4; ++k) fromGpu.alternates[k] = read(record.firstPoint + 16 + k);
    for (int sample = 0; sample < 4; ++sample) {
      const double s = unit(random), t = unit(random);
      const glm::dvec3 osd =
          surface
              .evaluatePatch(static_cast<int>(record.sourcePatch), record.faceU0 + s * record.faceSize,
                             record.faceV0 + t * record.faceSize)
              .position;
      worst = std::max(worst, glm::length(evaluateBezierPatch(fromGpu, s, t).position - osd));
    }
  }
  EXPECT_LE(worst, 1e-6 * surface.bounds().diagonal()) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(TortureCages, BvhOfEachCage, ::testing::ValuesIn(tortureCageNames()));

// The shared header compiled as GLSL at build time (patch_bvh_layout.comp):
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

TEST(PatchBvhLayout, GlslLayoutOfTheSharedHeaderIsTheCppLayout) {
  using namespace gpu_layout;
  ASSERT_GT(facet::test_spirv::patch_bvh_layout.size(), 5u);
  ASSERT_EQ(facet::test_spirv::patch_bvh_layout[0], 0x07230203u);  // SPIR-V magic
  const SpirvLayout layout(facet::test_spirv::patch_bvh_layout);

  EXPECT_EQ(layout.stride("PatchBvhNode"), sizeof(PatchBvhNode));
  EXPECT_EQ(layout.stride("PatchRecord"), sizeof(PatchRecord));
  EXPECT_EQ(layout.stride("PatchPoint"), sizeof(PatchPoint));
#define FACET_EXPECT_MEMBER(type, member) \
  EXPECT_EQ(layout.offset(#type, #member), offsetof(type, member)) << #type "." #member
  FACET_EXPECT_MEMBER(PatchBvhNode, minX);
  FACET_EXPECT_MEMBER(PatchBvhNode, next);
  FACET_EXPECT_MEMBER(PatchBvhNode, maxX);
  FACET_EXPECT_MEMBER(PatchBvhNode, patchCount);
  FACET_EXPECT_MEMBER(PatchRecord, kind);
  FACET_EXPECT_MEMBER(PatchRecord, firstPoint);
  FACET_EXPECT_MEMBER(PatchRecord, ptexFace);
  FACET_EXPECT_MEMBER(PatchRecord, coarseFace);
  FACET_EXPECT_MEMBER(PatchRecord, faceU0);
  FACET_EXPECT_MEMBER(PatchRecord, faceV0);
  FACET_EXPECT_MEMBER(PatchRecord, faceSize);
  FACET_EXPECT_MEMBER(PatchRecord, sourcePatch);
  FACET_EXPECT_MEMBER(PatchRecord, boundaryMask);
  FACET_EXPECT_MEMBER(PatchRecord, depth);
  FACET_EXPECT_MEMBER(PatchRecord, pointCount);
  FACET_EXPECT_MEMBER(PatchRecord, transitionMask);
  FACET_EXPECT_MEMBER(PatchPoint, x);
  FACET_EXPECT_MEMBER(PatchPoint, z);
#undef FACET_EXPECT_MEMBER
}

}  // namespace
}  // namespace facet::scene
