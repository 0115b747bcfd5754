// Internal: a SPIR-V module parsed into the tables that reflection reads.
// Only the engine/gpu/spirv_*.cpp files include this header: parsing the words
// (spirv_parse.cpp), reading types and constants (spirv_types.cpp), and
// building the Reflection (spirv_reflect.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/gpu/spirv_reflect.h"

namespace facet::gpu::spirv {

// Opcodes, decorations and enumerants from the SPIR-V 1.5 specification.
enum Op : std::uint32_t {
  OpName = 5,
  OpEntryPoint = 15,
  OpExecutionMode = 16,
  OpTypeBool = 20,
  OpTypeInt = 21,
  OpTypeFloat = 22,
  OpTypeVector = 23,
  OpTypeMatrix = 24,
  OpTypeImage = 25,
  OpTypeSampler = 26,
  OpTypeSampledImage = 27,
  OpTypeArray = 28,
  OpTypeRuntimeArray = 29,
  OpTypeStruct = 30,
  OpTypePointer = 32,
  OpConstant = 43,
  OpConstantComposite = 44,
  OpSpecConstantTrue = 48,
  OpSpecConstantFalse = 49,
  OpSpecConstant = 50,
  OpSpecConstantComposite = 51,
  OpVariable = 59,
  OpDecorate = 71,
  OpMemberDecorate = 72,
  OpExecutionModeId = 331,
};
enum Decoration : std::uint32_t {
  SpecId = 1,
  BufferBlock = 3,
  RowMajor = 4,
  ArrayStride = 6,
  MatrixStride = 7,
  BuiltIn = 11,
  NonWritable = 24,
  BindingDecoration = 33,
  DescriptorSet = 34,
  Offset = 35,
};
enum ExecutionModel : std::uint32_t { ExecutionModelGLCompute = 5 };
enum ExecutionMode : std::uint32_t { ExecutionModeLocalSize = 17, ExecutionModeLocalSizeId = 38 };
enum BuiltInVariable : std::uint32_t { BuiltInWorkgroupSize = 25 };
enum StorageClass : std::uint32_t {
  StorageClassUniformConstant = 0,
  StorageClassUniform = 2,
  StorageClassPushConstant = 9,
  StorageClassStorageBuffer = 12,
};
enum Dim : std::uint32_t { DimBuffer = 5 };
enum ImageFormat : std::uint32_t { ImageFormatRgba32f = 1, ImageFormatRgba32i = 21, ImageFormatRgba32ui = 30 };

struct Type {
  std::uint32_t op = 0;
  std::vector<std::uint32_t> operands;  // the instruction's words after the result id
};

struct Decorations {
  std::map<std::uint32_t, std::vector<std::uint32_t>> byKind;  // decoration → literals
  bool has(std::uint32_t d) const { return byKind.count(d) != 0; }
  std::uint32_t literal(std::uint32_t d) const { return byKind.at(d).empty() ? 0 : byKind.at(d)[0]; }
};

// How a struct member lays out the matrices in it (SPIR-V puts these on the
// member, not the matrix type).
struct MatrixLayout {
  std::uint32_t stride = 0;  // 0: tightly packed
  bool rowMajor = false;
};

class Module {
 public:
  Module(std::span<const std::uint32_t> words, const std::string& label);

  Reflection reflection() const;

 private:
  [[noreturn]] void fail(const std::string& rule) const;
  void parse(std::uint32_t op, std::span<const std::uint32_t> w);

  // Looks up what an instruction refers to; an id this reflection did not
  // parse (OpSpecConstantOp, OpConstantNull, or a bad module) is an Error.
  const Type& type(std::uint32_t id, const char* usedAs) const;
  const Type& constant(std::uint32_t id, const char* usedAs) const;

  double scalarValue(std::uint32_t constantId, const char* usedAs) const;
  // The type of a scalar constant: bool, int or float.
  const Type& scalarType(std::uint32_t constantId, const char* usedAs) const;
  std::uint64_t sizeOf(std::uint32_t typeId, MatrixLayout matrix = {}, int depth = 0) const;
  std::uint64_t decorationOr(std::uint32_t id, std::uint32_t decoration, std::uint64_t fallback) const;

  SpecConstant specConstant(std::uint32_t id, const Type& c, std::uint32_t specId) const;
  void resolveWorkgroupDimension(std::uint32_t constantId, Reflection& r, int dim) const;
  bool allMembersNonWritable(std::uint32_t structId) const;
  void reflectTexelBuffer(std::uint32_t typeId, const std::string& binding, bool nonWritable, Binding& b) const;
  void reflectVariable(std::uint32_t id, const Type& var, Reflection& r) const;

  std::string label_;
  std::map<std::uint32_t, std::string> names_;
  std::vector<std::string> entryPoints_;
  std::array<std::uint32_t, 3> workgroupSize_{1, 1, 1};
  std::optional<std::uint32_t> builtinWorkgroupSize_;
  std::map<std::uint32_t, Type> types_;
  std::map<std::uint32_t, Type> constants_;
  std::map<std::uint32_t, std::uint32_t> constantTypes_;
  std::map<std::uint32_t, Type> variables_;
  std::map<std::uint32_t, Decorations> decorations_;
  std::map<std::uint32_t, std::map<std::uint32_t, Decorations>> memberDecorations_;
};

}  // namespace facet::gpu::spirv
