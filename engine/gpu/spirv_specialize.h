// Internal: a pipeline's constants folded into its shader's code before the
// driver sees it, as WebGPU's implementations substitute pipeline-overridable
// constants. The code a constant makes unreachable is removed with it, so a
// driver that compiles every function of a module before it prunes branches
// (lavapipe) compiles only what the pipeline runs.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "engine/gpu/spirv_reflect.h"

namespace facet::gpu::spirv {

// The literal words of `value` as a constant of `constant`'s type: a bool is
// 0 or 1, a value of up to 32 bits one word (signed ones sign-extended, as
// SPIR-V's literals are), a 64-bit value two words, low word first.
std::vector<std::uint32_t> literalWords(const SpecConstant& constant, double value);

// `words` with each specialization constant frozen at its value in `values`
// (by constant_id) or its default, and the code left dead removed. Throws
// Error naming `label` when the optimizer rejects the module.
std::vector<std::uint32_t> specialize(std::span<const std::uint32_t> words,
                                      const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& values,
                                      const std::string& label);

// specialize(), run once per process for each module and values: a process
// that creates the same pipeline again (another device, renderer or
// picture) reuses the code instead of running the optimizer again.
std::shared_ptr<const std::vector<std::uint32_t>> specializeOnce(
    std::span<const std::uint32_t> words, const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& values,
    const std::string& label);

}  // namespace facet::gpu::spirv
