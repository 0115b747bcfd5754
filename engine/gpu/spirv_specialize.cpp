#include "engine/gpu/spirv_specialize.h"

#include <algorithm>
#include <cstring>
#include <mutex>
#include <spirv-tools/optimizer.hpp>
#include <string_view>
#include <unordered_map>

#include "engine/gpu/describe.h"

namespace facet::gpu::spirv {

std::vector<std::uint32_t> literalWords(const SpecConstant& constant, double value) {
  if (constant.kind == ScalarKind::Bool) return {value != 0 ? 1u : 0u};
  if (constant.kind == ScalarKind::Float) {
    if (constant.width == 64) {
      std::uint32_t words[2];
      std::memcpy(words, &value, sizeof words);
      return {words[0], words[1]};
    }
    const float single = float(value);
    std::uint32_t word = 0;
    std::memcpy(&word, &single, sizeof word);
    return {word};
  }
  const std::int64_t integer = std::int64_t(value);
  const std::uint64_t bits = constant.kind == ScalarKind::Int || constant.width == 64
                                 ? std::uint64_t(integer)
                                 : std::uint64_t(integer) & ((std::uint64_t(1) << constant.width) - 1);
  if (constant.width == 64) return {std::uint32_t(bits), std::uint32_t(bits >> 32)};
  return {std::uint32_t(bits)};
}

std::vector<std::uint32_t> specialize(std::span<const std::uint32_t> words,
                                      const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& values,
                                      const std::string& label) {
  spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
  std::string messages;
  optimizer.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
    messages += messages.empty() ? message : std::string("; ") + message;
  });
  // Freezing turns the constants into plain ones and folding carries them
  // through the expressions built on them. The branches they decide go, and
  // with them the functions only those branches called. What a constant
  // decides through a local value (a flag in a struct, a factor set to 0)
  // becomes a constant once locals are values (scalar replacement, SSA) and
  // constants are propagated, and its branches go in a second round; last,
  // the code that fed only the dead goes.
  optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values))
      .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
      .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
      .RegisterPass(spvtools::CreateDeadBranchElimPass())
      .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
      .RegisterPass(spvtools::CreateScalarReplacementPass(0))  // 0: composites of any size
      .RegisterPass(spvtools::CreateLocalSingleStoreElimPass())
      .RegisterPass(spvtools::CreateSSARewritePass())
      .RegisterPass(spvtools::CreateCCPPass())
      .RegisterPass(spvtools::CreateDeadBranchElimPass())
      .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
      .RegisterPass(spvtools::CreateAggressiveDCEPass());
  // The kernels were validated when they were built, and the driver (or its
  // validation layer) checks what it is given.
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);
  std::vector<std::uint32_t> specialized;
  if (!optimizer.Run(words.data(), words.size(), &specialized, options))
    throw Error(detail::describe("shader module", label) + ": its constants could not be folded into the code" +
                (messages.empty() ? std::string() : ": " + messages));
  return specialized;
}

namespace {

// A module and its values, as one run of words: the values by constant id,
// each as its id, its length and its words, then the module.
std::vector<std::uint32_t> specializationKey(
    std::span<const std::uint32_t> words, const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& values) {
  std::vector<std::uint32_t> ids;
  for (const auto& entry : values) ids.push_back(entry.first);
  std::sort(ids.begin(), ids.end());
  std::vector<std::uint32_t> key;
  for (std::uint32_t id : ids) {
    const std::vector<std::uint32_t>& literal = values.at(id);
    key.push_back(id);
    key.push_back(std::uint32_t(literal.size()));
    key.insert(key.end(), literal.begin(), literal.end());
  }
  key.insert(key.end(), words.begin(), words.end());
  return key;
}

struct KeyHash {
  std::size_t operator()(const std::vector<std::uint32_t>& key) const {
    return std::hash<std::string_view>{}(
        std::string_view(reinterpret_cast<const char*>(key.data()), key.size() * sizeof(std::uint32_t)));
  }
};

}  // namespace

std::shared_ptr<const std::vector<std::uint32_t>> specializeOnce(
    std::span<const std::uint32_t> words, const std::unordered_map<std::uint32_t, std::vector<std::uint32_t>>& values,
    const std::string& label) {
  static std::mutex mutex;
  static std::unordered_map<std::vector<std::uint32_t>, std::shared_ptr<const std::vector<std::uint32_t>>, KeyHash>
      specialized;
  std::vector<std::uint32_t> key = specializationKey(words, values);
  {
    const std::lock_guard lock(mutex);
    const auto found = specialized.find(key);
    if (found != specialized.end()) return found->second;
  }
  // Two threads asking for one variant at once may both run the optimizer;
  // its result is the same, and the first one stored is kept.
  auto code = std::make_shared<const std::vector<std::uint32_t>>(specialize(words, values, label));
  const std::lock_guard lock(mutex);
  return specialized.emplace(std::move(key), std::move(code)).first->second;
}

}  // namespace facet::gpu::spirv
