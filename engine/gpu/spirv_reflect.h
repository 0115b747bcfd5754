// Internal: just enough SPIR-V reflection to derive bind group layouts, check
// them against explicit ones, size-check bindings, and map constant names to
// specialization constant ids — so that a mismatch is an Error, not garbage.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "engine/gpu/gpu.h"

namespace facet::gpu::spirv {

// Every TexelFormat is four 32-bit components.
constexpr std::uint64_t kTexelBytes = 16;

struct Binding {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
  BindingType type = BindingType::Storage;
  std::uint64_t minSize = 0;  // fixed part of the block plus one runtime-array element, or one texel
  TexelFormat texelFormat = TexelFormat::Rgba32Float;  // texel bindings only
  bool written = false;  // storage, or storage texel not declared NonWritable: the shader may write it
  std::string name;
};

enum class ScalarKind { Bool, Int, UInt, Float };

struct SpecConstant {
  std::uint32_t id = 0;  // constant_id
  std::string name;
  ScalarKind kind = ScalarKind::Int;
  std::uint32_t width = 32;  // bits
  double defaultValue = 0;
};

struct Reflection {
  std::vector<std::string> computeEntryPoints;
  std::vector<Binding> bindings;
  std::vector<SpecConstant> specConstants;
  bool usesPushConstants = false;  // not part of WebGPU, so not of facet::gpu
  std::array<std::uint32_t, 3> workgroupSize{1, 1, 1};
  // constant_id that overrides each workgroup dimension, or -1.
  std::array<std::int64_t, 3> workgroupSizeSpecIds{-1, -1, -1};

  const SpecConstant* findConstant(const std::string& key) const;
};

// Throws Error naming `label` when the words are not a SPIR-V module.
Reflection reflect(std::span<const std::uint32_t> words, const std::string& label);

}  // namespace facet::gpu::spirv
