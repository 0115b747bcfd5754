#include "engine/gpu/spirv_reflect.h"

#include "engine/gpu/describe.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>

namespace facet::gpu::spirv {
namespace {

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
  ArrayStride = 6,
  MatrixStride = 7,
  BuiltIn = 11,
  NonWritable = 24,
  BindingDecoration = 33,
  DescriptorSet = 34,
  Offset = 35,
};
constexpr std::uint32_t kMagic = 0x07230203;
constexpr std::uint32_t kExecutionModelGLCompute = 5;
constexpr std::uint32_t kExecutionModeLocalSize = 17;
constexpr std::uint32_t kExecutionModeLocalSizeId = 38;
constexpr std::uint32_t kBuiltInWorkgroupSize = 25;
constexpr std::uint32_t kStorageClassUniform = 2;
constexpr std::uint32_t kStorageClassPushConstant = 9;
constexpr std::uint32_t kStorageClassStorageBuffer = 12;

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

struct Type {
  std::uint32_t op = 0;
  std::vector<std::uint32_t> operands;  // the instruction's words after the result id
};

struct Decorations {
  std::map<std::uint32_t, std::vector<std::uint32_t>> byKind;  // decoration → literals
  bool has(std::uint32_t d) const { return byKind.count(d) != 0; }
  std::uint32_t literal(std::uint32_t d) const { return byKind.at(d).empty() ? 0 : byKind.at(d)[0]; }
};

class Module {
 public:
  Module(std::span<const std::uint32_t> words, const std::string& label) : label_(label) {
    if (words.size() < 5 || words[0] != kMagic) fail("not a SPIR-V module (bad magic number or too short)");
    for (std::size_t at = 5; at < words.size();) {
      std::uint32_t count = words[at] >> 16;
      if (count == 0 || at + count > words.size()) fail("truncated instruction at word " + std::to_string(at));
      parse(words[at] & 0xffff, words.subspan(at + 1, count - 1));
      at += count;
    }
  }

  Reflection reflection() const {
    Reflection r;
    r.computeEntryPoints = entryPoints_;
    r.workgroupSize = workgroupSize_;
    for (int i = 0; i < 3; ++i) {
      if (workgroupSizeIds_[i]) resolveWorkgroupDimension(*workgroupSizeIds_[i], r, i);
    }
    if (builtinWorkgroupSize_) {
      const auto& components = constants_.at(*builtinWorkgroupSize_).operands;
      for (int i = 0; i < 3 && std::size_t(i) < components.size(); ++i) resolveWorkgroupDimension(components[i], r, i);
    }
    for (const auto& [id, c] : constants_) {
      auto deco = decorations_.find(id);
      if (deco == decorations_.end() || !deco->second.has(SpecId)) continue;
      r.specConstants.push_back(specConstant(id, c, deco->second.literal(SpecId)));
    }
    for (const auto& [id, var] : variables_) reflectVariable(id, var, r);
    return r;
  }

 private:
  [[noreturn]] void fail(const std::string& rule) const {
    throw Error(detail::describe("shader module", label_) + ": " + rule);
  }

  void parse(std::uint32_t op, std::span<const std::uint32_t> w) {
    auto need = [&](std::size_t n) {
      if (w.size() < n) fail("malformed instruction (opcode " + std::to_string(op) + ")");
    };
    switch (op) {
      case OpName:
        need(1);
        names_[w[0]] = literalString(w.subspan(1));
        break;
      case OpEntryPoint:
        need(3);
        if (w[0] == kExecutionModelGLCompute) entryPoints_.push_back(literalString(w.subspan(2)));
        break;
      case OpExecutionMode:
        need(2);
        if (w[1] == kExecutionModeLocalSize && w.size() >= 5) workgroupSize_ = {w[2], w[3], w[4]};
        break;
      case OpExecutionModeId:
        need(5);
        if (w[1] == kExecutionModeLocalSizeId)
          for (int i = 0; i < 3; ++i) workgroupSizeIds_[i] = w[2 + i];
        break;
      case OpTypeBool:
      case OpTypeInt:
      case OpTypeFloat:
      case OpTypeVector:
      case OpTypeMatrix:
      case OpTypeArray:
      case OpTypeRuntimeArray:
      case OpTypeStruct:
      case OpTypePointer:
        need(1);
        types_[w[0]] = Type{op, {w.begin() + 1, w.end()}};
        break;
      case OpConstant:
      case OpConstantComposite:
      case OpSpecConstantTrue:
      case OpSpecConstantFalse:
      case OpSpecConstant:
      case OpSpecConstantComposite:
        need(2);  // result type, result id, values
        constants_[w[1]] = Type{op, {w.begin() + 2, w.end()}};
        constantTypes_[w[1]] = w[0];
        break;
      case OpVariable:
        need(3);
        variables_[w[1]] = Type{op, {w[0], w[2]}};  // pointer type, storage class
        break;
      case OpDecorate:
        need(2);
        decorations_[w[0]].byKind[w[1]] = {w.begin() + 2, w.end()};
        if (w[1] == BuiltIn && w.size() >= 3 && w[2] == kBuiltInWorkgroupSize) builtinWorkgroupSize_ = w[0];
        break;
      case OpMemberDecorate:
        need(3);
        memberDecorations_[w[0]][w[1]].byKind[w[2]] = {w.begin() + 3, w.end()};
        break;
      default:
        break;
    }
  }

  double scalarValue(std::uint32_t constantId) const {
    const Type& c = constants_.at(constantId);
    if (c.op == OpSpecConstantTrue) return 1;
    if (c.op == OpSpecConstantFalse) return 0;
    const Type& t = types_.at(constantTypes_.at(constantId));
    if (c.operands.empty()) return 0;
    if (t.op == OpTypeFloat) {
      if (t.operands[0] == 64 && c.operands.size() >= 2) {
        std::uint64_t bits = c.operands[0] | (std::uint64_t(c.operands[1]) << 32);
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
      float f;
      std::memcpy(&f, &c.operands[0], sizeof f);
      return f;
    }
    if (t.op == OpTypeInt && t.operands[1] == 1) return double(std::int32_t(c.operands[0]));
    return double(c.operands[0]);
  }

  SpecConstant specConstant(std::uint32_t id, const Type& c, std::uint32_t specId) const {
    SpecConstant s;
    s.id = specId;
    auto name = names_.find(id);
    s.name = name != names_.end() ? name->second : "";
    s.defaultValue = scalarValue(id);
    if (c.op == OpSpecConstantTrue || c.op == OpSpecConstantFalse) {
      s.kind = ScalarKind::Bool;
      return s;
    }
    const Type& t = types_.at(constantTypes_.at(id));
    s.width = t.operands.empty() ? 32 : t.operands[0];
    s.kind = t.op == OpTypeFloat ? ScalarKind::Float
                                 : (t.operands.size() > 1 && t.operands[1] ? ScalarKind::Int : ScalarKind::UInt);
    return s;
  }

  void resolveWorkgroupDimension(std::uint32_t constantId, Reflection& r, int dim) const {
    r.workgroupSize[dim] = std::uint32_t(scalarValue(constantId));
    auto deco = decorations_.find(constantId);
    if (deco != decorations_.end() && deco->second.has(SpecId))
      r.workgroupSizeSpecIds[dim] = deco->second.literal(SpecId);
  }

  std::uint64_t sizeOf(std::uint32_t typeId, std::uint32_t matrixStride = 0) const {
    const Type& t = types_.at(typeId);
    switch (t.op) {
      case OpTypeBool:
        return 4;
      case OpTypeInt:
      case OpTypeFloat:
        return t.operands[0] / 8;
      case OpTypeVector:
        return t.operands[1] * sizeOf(t.operands[0]);
      case OpTypeMatrix:
        return t.operands[1] * (matrixStride ? matrixStride : sizeOf(t.operands[0]));
      case OpTypeArray:
        return std::uint64_t(scalarValue(t.operands[1])) * decorationOr(typeId, ArrayStride, sizeOf(t.operands[0]));
      case OpTypeRuntimeArray:
        return decorationOr(typeId, ArrayStride, sizeOf(t.operands[0]));
      case OpTypeStruct: {
        std::uint64_t size = 0;
        auto members = memberDecorations_.find(typeId);
        for (std::uint32_t m = 0; m < t.operands.size(); ++m) {
          std::uint64_t offset = 0, stride = 0;
          if (members != memberDecorations_.end() && members->second.count(m)) {
            const Decorations& d = members->second.at(m);
            if (d.has(Offset)) offset = d.literal(Offset);
            if (d.has(MatrixStride)) stride = d.literal(MatrixStride);
          }
          size = std::max(size, offset + sizeOf(t.operands[m], std::uint32_t(stride)));
        }
        return size;
      }
      default:
        return 0;
    }
  }

  std::uint64_t decorationOr(std::uint32_t id, std::uint32_t decoration, std::uint64_t fallback) const {
    auto d = decorations_.find(id);
    return d != decorations_.end() && d->second.has(decoration) ? d->second.literal(decoration) : fallback;
  }

  bool allMembersNonWritable(std::uint32_t structId) const {
    const Type& t = types_.at(structId);
    auto members = memberDecorations_.find(structId);
    if (members == memberDecorations_.end()) return false;
    for (std::uint32_t m = 0; m < t.operands.size(); ++m) {
      auto d = members->second.find(m);
      if (d == members->second.end() || !d->second.has(NonWritable)) return false;
    }
    return true;
  }

  void reflectVariable(std::uint32_t id, const Type& var, Reflection& r) const {
    std::uint32_t storageClass = var.operands[1];
    if (storageClass == kStorageClassPushConstant) r.usesPushConstants = true;
    if (storageClass != kStorageClassUniform && storageClass != kStorageClassStorageBuffer) return;
    auto deco = decorations_.find(id);
    if (deco == decorations_.end() || !deco->second.has(BindingDecoration)) return;
    const Type& pointer = types_.at(var.operands[0]);
    std::uint32_t blockType = pointer.operands[1];
    bool bufferBlock = decorations_.count(blockType) && decorations_.at(blockType).has(BufferBlock);
    Binding b;
    b.set = deco->second.has(DescriptorSet) ? deco->second.literal(DescriptorSet) : 0;
    b.binding = deco->second.literal(BindingDecoration);
    bool storage = storageClass == kStorageClassStorageBuffer || bufferBlock;
    bool readOnly = deco->second.has(NonWritable) || allMembersNonWritable(blockType);
    b.type = !storage ? BindingType::Uniform : readOnly ? BindingType::ReadOnlyStorage : BindingType::Storage;
    b.minSize = sizeOf(blockType);
    auto name = names_.find(id);
    b.name = name != names_.end() && !name->second.empty() ? name->second
             : names_.count(blockType)                     ? names_.at(blockType)
                                                           : "";
    r.bindings.push_back(b);
  }

  std::string label_;
  std::map<std::uint32_t, std::string> names_;
  std::vector<std::string> entryPoints_;
  std::array<std::uint32_t, 3> workgroupSize_{1, 1, 1};
  std::array<std::optional<std::uint32_t>, 3> workgroupSizeIds_;
  std::optional<std::uint32_t> builtinWorkgroupSize_;
  std::map<std::uint32_t, Type> types_;
  std::map<std::uint32_t, Type> constants_;
  std::map<std::uint32_t, std::uint32_t> constantTypes_;
  std::map<std::uint32_t, Type> variables_;
  std::map<std::uint32_t, Decorations> decorations_;
  std::map<std::uint32_t, std::map<std::uint32_t, Decorations>> memberDecorations_;
};

}  // namespace

const SpecConstant* Reflection::findConstant(const std::string& key) const {
  for (const auto& c : specConstants)
    if (c.name == key || std::to_string(c.id) == key) return &c;
  return nullptr;
}

Reflection reflect(std::span<const std::uint32_t> words, const std::string& label) {
  return Module(words, label).reflection();
}

}  // namespace facet::gpu::spirv
