// Parsing a SPIR-V module's words into the tables of spirv::Module.
#include "engine/gpu/describe.h"
#include "engine/gpu/spirv_module.h"

namespace facet::gpu::spirv {
namespace {

constexpr std::uint32_t kMagic = 0x07230203;

std::string literalString(std::span<const std::uint32_t> words) {
  std::string s;
  for (std::uint32_t w : words) {
    for (int i = 0; i < 4; ++i) {
      char c = char((w >> (8 * i)) & 0xff);
      if (c == 0) return s;
      s.push_back(c);
    }
  }
  return s;
}

// Operand words a type instruction needs, its result id included; sizeOf
// and scalarValue read these without further checks.
std::size_t typeOperandWords(std::uint32_t op) {
  switch (op) {
    case OpTypeBool:
    case OpTypeSampler:
    case OpTypeStruct:  // member types follow, any number
      return 1;
    case OpTypeFloat:         // width
    case OpTypeRuntimeArray:  // element type
    case OpTypeSampledImage:  // image type
      return 2;
    case OpTypeImage:  // sampled type, dim, depth, arrayed, multisampled, sampled, format
      return 8;
    default:  // int: width, signedness; vector, matrix: component type, count;
              // array: element type, length; pointer: storage class, type
      return 3;
  }
}

// Decorations whose one literal operand reflection reads.
bool takesLiteral(std::uint32_t decoration) {
  switch (decoration) {
    case SpecId:
    case ArrayStride:
    case MatrixStride:
    case BuiltIn:
    case BindingDecoration:
    case DescriptorSet:
    case Offset:
      return true;
    default:
      return false;
  }
}

}  // namespace

Module::Module(std::span<const std::uint32_t> words, const std::string& label) : label_(label) {
  if (words.size() < 5 || words[0] != kMagic) fail("not a SPIR-V module (bad magic number or too short)");
  for (std::size_t at = 5; at < words.size();) {
    std::uint32_t count = words[at] >> 16;
    if (count == 0 || at + count > words.size()) fail("truncated instruction at word " + std::to_string(at));
    parse(words[at] & 0xffff, words.subspan(at + 1, count - 1));
    at += count;
  }
}

void Module::fail(const std::string& rule) const {
  throw Error(detail::describe("shader module", label_) + ": " + rule);
}

void Module::parse(std::uint32_t op, std::span<const std::uint32_t> w) {
  // `n`: the instruction's operand words after the opcode, per the specification.
  auto need = [&](std::size_t n) {
    if (w.size() < n)
      fail("malformed instruction (opcode " + std::to_string(op) + " has " + std::to_string(w.size()) +
           " operand words, at least " + std::to_string(n) + " needed)");
  };
  switch (op) {
    case OpName:
      need(1);
      names_[w[0]] = literalString(w.subspan(1));
      break;
    case OpEntryPoint:
      need(3);
      if (w[0] == ExecutionModelGLCompute) entryPoints_.push_back(literalString(w.subspan(2)));
      break;
    case OpExecutionMode:
      need(2);
      if (w[1] == ExecutionModeLocalSize) {
        need(5);
        workgroupSize_ = {w[2], w[3], w[4]};
      }
      break;
    case OpExecutionModeId:
      need(2);
      // LocalSizeId in a Vulkan 1.2 module needs the maintenance4 feature,
      // which facet::gpu does not enable: Vulkan would reject the pipeline.
      if (w[1] == ExecutionModeLocalSizeId)
        fail(
            "uses the LocalSizeId execution mode, which needs Vulkan's maintenance4 (not enabled); compile for "
            "Vulkan 1.2 (glslangValidator --target-env vulkan1.2) so local_size_x_id becomes a WorkgroupSize "
            "constant");
      break;
    case OpTypeBool:
    case OpTypeStruct:
    case OpTypeFloat:
    case OpTypeRuntimeArray:
    case OpTypeInt:
    case OpTypeVector:
    case OpTypeMatrix:
    case OpTypeArray:
    case OpTypePointer:
    case OpTypeImage:
    case OpTypeSampler:
    case OpTypeSampledImage:
      need(typeOperandWords(op));
      types_[w[0]] = Type{op, {w.begin() + 1, w.end()}};
      break;
    case OpConstant:
    case OpSpecConstant:
    case OpConstantComposite:
    case OpSpecConstantTrue:
    case OpSpecConstantFalse:
    case OpSpecConstantComposite:
      // Result type, result id, then a scalar's value (required) or a composite's constituents.
      need(op == OpConstant || op == OpSpecConstant ? 3 : 2);
      constants_[w[1]] = Type{op, {w.begin() + 2, w.end()}};
      constantTypes_[w[1]] = w[0];
      break;
    case OpVariable:
      need(3);
      variables_[w[1]] = Type{op, {w[0], w[2]}};  // pointer type, storage class
      break;
    case OpDecorate:
      need(takesLiteral(w.size() >= 2 ? w[1] : 0) ? 3 : 2);
      decorations_[w[0]].byKind[w[1]] = {w.begin() + 2, w.end()};
      if (w[1] == BuiltIn && w.size() >= 3 && w[2] == BuiltInWorkgroupSize) builtinWorkgroupSize_ = w[0];
      break;
    case OpMemberDecorate:
      need(takesLiteral(w.size() >= 3 ? w[2] : 0) ? 4 : 3);
      memberDecorations_[w[0]][w[1]].byKind[w[2]] = {w.begin() + 3, w.end()};
      break;
    default:
      break;
  }
}

}  // namespace facet::gpu::spirv
