// What spirv::Module's types and constants mean: a constant's scalar value and
// a buffer block's size.
#include <algorithm>
#include <cstring>

#include "engine/gpu/spirv_module.h"

namespace facet::gpu::spirv {

// Real blocks nest a few levels; a type that contains itself (invalid
// SPIR-V) would otherwise recurse until the stack overflows.
constexpr int kMaxTypeDepth = 64;

const Type& Module::type(std::uint32_t id, const char* usedAs) const {
  auto it = types_.find(id);
  if (it == types_.end()) fail(std::string(usedAs) + " %" + std::to_string(id) + " is not a type facet::gpu knows");
  return it->second;
}
const Type& Module::constant(std::uint32_t id, const char* usedAs) const {
  auto it = constants_.find(id);
  if (it == constants_.end())
    fail(std::string(usedAs) + " %" + std::to_string(id) +
         " is not a literal constant (facet::gpu cannot evaluate OpSpecConstantOp or OpConstantNull there)");
  return it->second;
}

double Module::scalarValue(std::uint32_t constantId, const char* usedAs) const {
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

const Type& Module::scalarType(std::uint32_t constantId, const char* usedAs) const {
  const Type& t = type(constantTypes_.at(constantId), usedAs);
  if (t.op != OpTypeBool && t.op != OpTypeInt && t.op != OpTypeFloat)
    fail(std::string(usedAs) + " %" + std::to_string(constantId) + " is not a scalar constant");
  return t;
}

std::uint64_t Module::sizeOf(std::uint32_t typeId, MatrixLayout matrix, int depth) const {
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

std::uint64_t Module::decorationOr(std::uint32_t id, std::uint32_t decoration, std::uint64_t fallback) const {
  auto d = decorations_.find(id);
  return d != decorations_.end() && d->second.has(decoration) ? d->second.literal(decoration) : fallback;
}

}  // namespace facet::gpu::spirv
