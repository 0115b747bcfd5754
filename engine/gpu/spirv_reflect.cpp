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
    if (builtinWorkgroupSize_) {
      const auto& components = constant(*builtinWorkgroupSize_, "the WorkgroupSize built-in").operands;
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

  // Looks up what an instruction refers to; an id this reflection did not
  // parse (OpSpecConstantOp, OpConstantNull, or a bad module) is an Error.
  const Type& type(std::uint32_t id, const char* usedAs) const {
    auto it = types_.find(id);
    if (it == types_.end()) fail(std::string(usedAs) + " %" + std::to_string(id) + " is not a type facet::gpu knows");
    return it->second;
  }
  const Type& constant(std::uint32_t id, const char* usedAs) const {
    auto it = constants_.find(id);
    if (it == constants_.end())
      fail(std::string(usedAs) + " %" + std::to_string(id) +
           " is not a literal constant (facet::gpu cannot evaluate OpSpecConstantOp or OpConstantNull there)");
    return it->second;
  }

  // Operand words a type instruction needs, its result id included; sizeOf
  // and scalarValue read these without further checks.
  static std::size_t typeOperandWords(std::uint32_t op) {
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
  static bool takesLiteral(std::uint32_t decoration) {
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

  void parse(std::uint32_t op, std::span<const std::uint32_t> w) {
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

  double scalarValue(std::uint32_t constantId, const char* usedAs) const {
    const Type& c = constant(constantId, usedAs);
    if (c.op == OpSpecConstantTrue) return 1;
    if (c.op == OpSpecConstantFalse) return 0;
    const Type& t = scalarType(constantId, usedAs);
    if (c.operands.empty())
      fail(std::string(usedAs) + " %" + std::to_string(constantId) + " is a composite, not a scalar");
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

  // The type of a scalar constant: bool, int or float.
  const Type& scalarType(std::uint32_t constantId, const char* usedAs) const {
    const Type& t = type(constantTypes_.at(constantId), usedAs);
    if (t.op != OpTypeBool && t.op != OpTypeInt && t.op != OpTypeFloat)
      fail(std::string(usedAs) + " %" + std::to_string(constantId) + " is not a scalar constant");
    return t;
  }

  SpecConstant specConstant(std::uint32_t id, const Type& c, std::uint32_t specId) const {
    SpecConstant s;
    s.id = specId;
    auto name = names_.find(id);
    s.name = name != names_.end() ? name->second : "";
    s.defaultValue = scalarValue(id, "specialization constant");
    if (c.op == OpSpecConstantTrue || c.op == OpSpecConstantFalse) {
      s.kind = ScalarKind::Bool;
      return s;
    }
    const Type& t = scalarType(id, "specialization constant");
    s.width = t.op == OpTypeBool ? 32 : t.operands[0];
    s.kind = t.op == OpTypeFloat  ? ScalarKind::Float
             : t.op == OpTypeBool ? ScalarKind::Bool
             : t.operands[1]      ? ScalarKind::Int
                                  : ScalarKind::UInt;
    return s;
  }

  void resolveWorkgroupDimension(std::uint32_t constantId, Reflection& r, int dim) const {
    r.workgroupSize[dim] = std::uint32_t(scalarValue(constantId, "workgroup size component"));
    auto deco = decorations_.find(constantId);
    if (deco != decorations_.end() && deco->second.has(SpecId))
      r.workgroupSizeSpecIds[dim] = deco->second.literal(SpecId);
  }

  // Real blocks nest a few levels; a type that contains itself (invalid
  // SPIR-V) would otherwise recurse until the stack overflows.
  static constexpr int kMaxTypeDepth = 64;

  std::uint64_t sizeOf(std::uint32_t typeId, MatrixLayout matrix = {}, int depth = 0) const {
    if (depth > kMaxTypeDepth) fail("type %" + std::to_string(typeId) + " nests too deeply (does it contain itself?)");
    const Type& t = type(typeId, "block member type");
    switch (t.op) {
      case OpTypeBool:
        return 4;
      case OpTypeInt:
      case OpTypeFloat:
        return t.operands[0] / 8;
      case OpTypeVector:
        return t.operands[1] * sizeOf(t.operands[0], {}, depth + 1);
      case OpTypeMatrix: {
        const std::uint64_t columns = t.operands[1];
        if (!matrix.stride) return columns * sizeOf(t.operands[0], {}, depth + 1);
        // Each column (column-major) or each row (row-major) takes one stride;
        // a column vector has one component per row.
        const Type& column = type(t.operands[0], "matrix column type");
        if (column.op != OpTypeVector) fail("matrix type %" + std::to_string(typeId) + " has non-vector columns");
        const std::uint64_t rows = column.operands[1];
        return (matrix.rowMajor ? rows : columns) * matrix.stride;
      }
      case OpTypeArray: {
        const double length = scalarValue(t.operands[1], "array length");
        if (!(length >= 1)) fail("array type %" + std::to_string(typeId) + " has length " + std::to_string(length));
        return std::uint64_t(length) * decorationOr(typeId, ArrayStride, sizeOf(t.operands[0], matrix, depth + 1));
      }
      case OpTypeRuntimeArray:
        return decorationOr(typeId, ArrayStride, sizeOf(t.operands[0], matrix, depth + 1));
      case OpTypeStruct: {
        std::uint64_t size = 0;
        auto members = memberDecorations_.find(typeId);
        for (std::uint32_t m = 0; m < t.operands.size(); ++m) {
          std::uint64_t offset = 0;
          MatrixLayout memberMatrix;
          if (members != memberDecorations_.end() && members->second.count(m)) {
            const Decorations& d = members->second.at(m);
            if (d.has(Offset)) offset = d.literal(Offset);
            if (d.has(MatrixStride)) memberMatrix.stride = d.literal(MatrixStride);
            memberMatrix.rowMajor = d.has(RowMajor);
          }
          size = std::max(size, offset + sizeOf(t.operands[m], memberMatrix, depth + 1));
        }
        return size;
      }
      default:
        fail("type %" + std::to_string(typeId) + " (opcode " + std::to_string(t.op) + ") cannot be in a buffer block");
    }
  }

  std::uint64_t decorationOr(std::uint32_t id, std::uint32_t decoration, std::uint64_t fallback) const {
    auto d = decorations_.find(id);
    return d != decorations_.end() && d->second.has(decoration) ? d->second.literal(decoration) : fallback;
  }

  bool allMembersNonWritable(std::uint32_t structId) const {
    const Type& t = type(structId, "block type");
    auto members = memberDecorations_.find(structId);
    if (members == memberDecorations_.end()) return false;
    for (std::uint32_t m = 0; m < t.operands.size(); ++m) {
      auto d = members->second.find(m);
      if (d == members->second.end() || !d->second.has(NonWritable)) return false;
    }
    return true;
  }

  // A texel buffer is an image of Dim Buffer, sampled (Sampled 1, possibly
  // wrapped in a sampled image type) or storage (Sampled 2), whose four
  // 32-bit components are the texel format.
  void reflectTexelBuffer(std::uint32_t typeId, const std::string& binding, bool nonWritable, Binding& b) const {
    auto find = [&](std::uint32_t id) {
      auto it = types_.find(id);
      return it == types_.end() ? nullptr : &it->second;
    };
    const Type* image = find(typeId);
    if (image && image->op == OpTypeSampledImage) image = find(image->operands[0]);
    if (!image || image->op != OpTypeImage || image->operands[1] != DimBuffer ||
        (image->operands[5] != 1 && image->operands[5] != 2))
      fail(binding +
           " is an image, a sampler or an array of them: facet::gpu supports only uniform, storage and texel "
           "buffers, one per binding");
    const bool storage = image->operands[5] == 2;
    const Type& component = type(image->operands[0], "image component type");
    const bool isFloat = component.op == OpTypeFloat;
    if ((!isFloat && component.op != OpTypeInt) || component.operands[0] != 32)
      fail(binding + " does not have 32-bit components: facet::gpu supports only 4 x 32-bit texel formats");
    const bool isSigned = !isFloat && component.operands[1] == 1;
    const std::uint32_t format = isFloat ? ImageFormatRgba32f : isSigned ? ImageFormatRgba32i : ImageFormatRgba32ui;
    if (storage && image->operands[6] != format)
      fail(binding + " has image format " + std::to_string(image->operands[6]) +
           ": facet::gpu supports only 4 x 32-bit texel formats (rgba32f, rgba32ui, rgba32i, as the component type)");
    b.type = storage ? BindingType::StorageTexelBuffer : BindingType::TexelBuffer;
    b.texelFormat = isFloat ? TexelFormat::Rgba32Float : isSigned ? TexelFormat::Rgba32Sint : TexelFormat::Rgba32Uint;
    b.written = storage && !nonWritable;
    b.minSize = kTexelBytes;
  }

  void reflectVariable(std::uint32_t id, const Type& var, Reflection& r) const {
    std::uint32_t storageClass = var.operands[1];
    if (storageClass == StorageClassPushConstant) r.usesPushConstants = true;
    auto deco = decorations_.find(id);
    if (deco == decorations_.end() || !deco->second.has(BindingDecoration)) return;
    if (storageClass != StorageClassUniformConstant && storageClass != StorageClassUniform &&
        storageClass != StorageClassStorageBuffer)
      return;
    auto name = names_.find(id);
    Binding b;
    b.set = deco->second.has(DescriptorSet) ? deco->second.literal(DescriptorSet) : 0;
    b.binding = deco->second.literal(BindingDecoration);
    b.name = name != names_.end() ? name->second : "";
    const std::string binding = "binding (group " + std::to_string(b.set) + ", binding " + std::to_string(b.binding) +
                                (b.name.empty() ? "" : ", '" + b.name + "'") + ")";
    const Type& pointer = type(var.operands[0], "variable type");
    if (pointer.op != OpTypePointer) fail(binding + " does not have a pointer type");
    std::uint32_t blockType = pointer.operands[1];
    if (storageClass == StorageClassUniformConstant) {
      reflectTexelBuffer(blockType, binding, deco->second.has(NonWritable), b);
      r.bindings.push_back(b);
      return;
    }
    const Type& block = type(blockType, "block type");
    if (block.op == OpTypeArray || block.op == OpTypeRuntimeArray)
      fail(binding + " is an array of blocks: facet::gpu supports one buffer per binding; give each its own binding");
    if (block.op != OpTypeStruct) fail(binding + " is not a block (struct) type");
    bool bufferBlock = decorations_.count(blockType) && decorations_.at(blockType).has(BufferBlock);
    bool storage = storageClass == StorageClassStorageBuffer || bufferBlock;
    bool readOnly = deco->second.has(NonWritable) || allMembersNonWritable(blockType);
    b.type = !storage ? BindingType::Uniform : readOnly ? BindingType::ReadOnlyStorage : BindingType::Storage;
    b.written = b.type == BindingType::Storage;
    b.minSize = sizeOf(blockType);
    if (b.name.empty() && names_.count(blockType)) b.name = names_.at(blockType);
    r.bindings.push_back(b);
  }

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
