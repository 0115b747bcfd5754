#include "engine/gpu_backend/prefilter_gpu.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "engine/ibl/prefilter_steps.h"
#include "facet_ibl_kernels/spirv.h"
#include "rules/rules.h"

namespace facet::gpu_backend {

namespace {

using gpu::BufferUsage;

struct DownsampleParams {
  std::uint32_t finerOffset;
  std::uint32_t coarserOffset;
  std::int32_t coarserWidth;
  std::int32_t coarserHeight;
};

struct PrefilterParams {
  std::int32_t width;
  std::int32_t height;
  float alpha;
  std::int32_t samples;
  std::int32_t sourceWidth;
  std::int32_t sourceHeight;
  std::int32_t chainLevels;
  std::uint32_t outputOffset;
};

struct ShProjectParams {
  std::int32_t width;
  std::int32_t height;
};

struct IrradianceParams {
  std::int32_t width;
  std::int32_t height;
  std::int32_t sourceWidth;
  std::int32_t sourceHeight;
  std::uint32_t sourceOffset;
};

struct DfgParams {
  std::int32_t size;
  std::int32_t samples;
};

std::uint32_t groupsFor(int items, int groupSize) { return std::uint32_t((items + groupSize - 1) / groupSize); }

class PrefilterJob {
 public:
  explicit PrefilterJob(gpu::Device& device) : device_(device), encoder_(device.createCommandEncoder({"prefilter"})) {}

  template <class Params>
  gpu::Buffer uniform(const char* label, const Params& params) {
    gpu::Buffer buffer = device_.createBuffer({label, sizeof(Params), BufferUsage::Uniform | BufferUsage::CopyDst});
    device_.queue().writeBuffer(buffer, 0, &params, sizeof(Params));
    return buffer;
  }

  gpu::Buffer storage(const char* label, std::uint64_t bytes) {
    return device_.createBuffer({label, bytes, BufferUsage::Storage | BufferUsage::CopySrc | BufferUsage::CopyDst});
  }

  gpu::ComputePipeline pipeline(const char* label, std::span<const std::uint32_t> code,
                                std::vector<gpu::ConstantEntry> constants = {}) {
    gpu::ShaderModule module = device_.createShaderModule({label, code});
    return device_.createComputePipeline({label, nullptr, &module, "main", std::move(constants)});
  }

  void dispatch(const gpu::ComputePipeline& pipeline, std::vector<gpu::BindGroupEntry> entries, std::uint32_t x,
                std::uint32_t y = 1) {
    gpu::BindGroupLayout layout = pipeline.getBindGroupLayout(0);
    gpu::BindGroup group = device_.createBindGroup({"prefilter", &layout, std::move(entries)});
    gpu::ComputePassEncoder pass = encoder_.beginComputePass();
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups(x, y);
    pass.end();
  }

  // Copies each buffer to a host-visible one, runs everything recorded and
  // waits for it.
  std::vector<std::vector<std::byte>> finish(const std::vector<const gpu::Buffer*>& results) {
    std::vector<gpu::Buffer> staging;
    for (const gpu::Buffer* result : results) {
      staging.push_back(
          device_.createBuffer({"prefilter readback", result->size(), BufferUsage::MapRead | BufferUsage::CopyDst}));
      encoder_.copyBufferToBuffer(*result, 0, staging.back(), 0, result->size());
    }
    device_.queue().submit(encoder_.finish());
    device_.queue().waitIdle();
    std::vector<std::vector<std::byte>> bytes;
    for (gpu::Buffer& buffer : staging) {
      const auto mapped = buffer.mappedRange();
      bytes.emplace_back(mapped.begin(), mapped.end());
    }
    return bytes;
  }

 private:
  gpu::Device& device_;
  gpu::CommandEncoder encoder_;
};

template <class T>
std::vector<T> valuesAt(const std::vector<std::byte>& bytes, std::size_t offset, std::size_t count) {
  std::vector<T> values(count);
  std::memcpy(values.data(), bytes.data() + offset, count * sizeof(T));
  return values;
}

std::uint64_t chainBytes(int width, int height) {
  std::uint64_t bytes = 0;
  for (const facet::ibl::LevelSize& size : facet::ibl::sourceChainSizes(width, height))
    bytes += 12 * std::uint64_t(size.width) * std::uint64_t(size.height);
  return bytes;
}

scene::EnvironmentMap halved(const scene::EnvironmentMap& map) {
  scene::EnvironmentMap half;
  half.width = map.width / 2;
  half.height = map.height / 2;
  half.rgb.resize(3 * std::size_t(half.width) * std::size_t(half.height));
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x) {
      const glm::dvec3 mean = facet::ibl::coarserTexel(map.rgb.data(), map.width, map.height, x, y);
      for (int channel = 0; channel < 3; ++channel)
        half.rgb[3 * (std::size_t(y) * half.width + x) + channel] = float(mean[channel]);
    }
  return half;
}

// The chain must fit one storage binding (lavapipe binds 128 MiB: maps up
// to 4096 x 2048); a larger map is halved on the host first, and returned.
// The levels it loses are ones no sample reads at the default settings:
// level 1's narrowest samples read lod 5.8 of a 16384 x 8192 map's chain.
std::optional<scene::EnvironmentMap> reducedToFit(gpu::Device& device, const scene::EnvironmentMap& map) {
  std::optional<scene::EnvironmentMap> reduced;
  const scene::EnvironmentMap* fitting = &map;
  while (chainBytes(fitting->width, fitting->height) > device.limits().maxStorageBufferBindingSize) {
    if (fitting->width % 2 != 0 || fitting->height % 2 != 0)
      throw gpu::Error("prefilterOnGpu: the mip chain of a " + std::to_string(map.width) + " x " +
                       std::to_string(map.height) + " map does not fit a storage binding and cannot be halved");
    reduced = halved(*fitting);
    fitting = &*reduced;
  }
  return reduced;
}

// One DFG table per (distribution, geometry) pair, in the pairs' order.
std::vector<gpu::Buffer> dispatchDfgTables(PrefilterJob& job, const gpu::Buffer& params,
                                           const facet::ibl::ModelPairs& models, int size) {
  namespace spirv = gpu_backend::ibl::spirv;
  std::vector<gpu::Buffer> tables;
  for (const auto& [distribution, geometry] : models) {
    tables.push_back(job.storage("DFG table", 8 * std::uint64_t(size) * std::uint64_t(size)));
    const std::string label = "dfg D=" + std::to_string(distribution) + " G=" + std::to_string(geometry);
    job.dispatch(
        job.pipeline(label.c_str(), spirv::dfg, {{"D_MODEL", double(distribution)}, {"G_MODEL", double(geometry)}}),
        {{0, &params}, {1, &tables.back()}}, groupsFor(size, FACET_IBL_TILE_SIZE),
        groupsFor(size, FACET_IBL_TILE_SIZE));
  }
  return tables;
}

// The prefiltered levels after the first, one after another in `bytes`.
void readPrefilteredLevels(facet::ibl::PrefilteredEnvironment& env, const std::vector<std::byte>& bytes) {
  std::size_t offset = 0;
  for (std::size_t i = 1; i < env.levels.size(); ++i) {
    facet::ibl::RadianceLevel& level = env.levels[i];
    const std::size_t count = 3 * std::size_t(level.width) * std::size_t(level.height);
    level.rgb = valuesAt<float>(bytes, offset, count);
    offset += count * sizeof(float);
  }
}

// Each source row's five sums, as sh_project writes them: one vec4 each.
std::vector<facet::ibl::ShRowSums> shRowSums(const std::vector<std::byte>& bytes, int height) {
  const std::vector<float> sums = valuesAt<float>(bytes, 0, 20 * std::size_t(height));
  std::vector<facet::ibl::ShRowSums> rows(height);
  for (int y = 0; y < height; ++y)
    for (int k = 0; k < 5; ++k) {
      const float* sum = &sums[4 * (5 * std::size_t(y) + k)];
      rows[y][k] = glm::dvec3(sum[0], sum[1], sum[2]);
    }
  return rows;
}

}  // namespace

facet::ibl::PrefilteredEnvironment prefilterOnGpu(gpu::Device& device, const scene::EnvironmentMap& map,
                                                  const facet::ibl::ModelPairs& models,
                                                  const facet::ibl::PrefilterSettings& settings) {
  // facet::ibl in full throughout: the kernels' gpu_backend::ibl hides it here.
  namespace spirv = gpu_backend::ibl::spirv;
  const std::optional<scene::EnvironmentMap> reduced = reducedToFit(device, map);
  const scene::EnvironmentMap& source = reduced ? *reduced : map;
  const std::vector<facet::ibl::LevelSize> chainSizes = facet::ibl::sourceChainSizes(source.width, source.height);
  std::vector<std::uint32_t> chainOffsets;
  std::uint64_t chainFloats = 0;
  for (const facet::ibl::LevelSize& size : chainSizes) {
    chainOffsets.push_back(std::uint32_t(chainFloats));
    chainFloats += 3 * std::uint64_t(size.width) * std::uint64_t(size.height);
  }

  PrefilterJob job(device);
  gpu::Buffer chain = job.storage("source mip chain", 4 * chainFloats);
  device.queue().writeBuffer(chain, 0, source.rgb.data(), source.rgb.size() * sizeof(float));

  std::vector<gpu::Buffer> uniforms;
  gpu::ComputePipeline downsample = job.pipeline("downsample", spirv::downsample);
  for (std::size_t l = 1; l < chainSizes.size(); ++l) {
    const facet::ibl::LevelSize size = chainSizes[l];
    uniforms.push_back(job.uniform("downsample params",
                                   DownsampleParams{chainOffsets[l - 1], chainOffsets[l], size.width, size.height}));
    job.dispatch(downsample, {{0, &uniforms.back()}, {1, &chain}}, groupsFor(size.width, FACET_IBL_TILE_SIZE),
                 groupsFor(size.height, FACET_IBL_TILE_SIZE));
  }

  facet::ibl::PrefilteredEnvironment env;
  env.levels.push_back({map.width, map.height, 0.0, map.rgb});
  std::uint64_t levelFloats = 0;
  for (int i = 1; i < settings.levels; ++i) {
    const facet::ibl::LevelSize size = facet::ibl::prefilteredLevelSize(map, settings, i);
    env.levels.push_back({size.width, size.height, rules::f64::prefiltered_level_alpha(i, settings.levels), {}});
    levelFloats += 3 * std::uint64_t(size.width) * std::uint64_t(size.height);
  }
  gpu::Buffer levels = job.storage("prefiltered levels", 4 * std::max<std::uint64_t>(levelFloats, 1));
  gpu::ComputePipeline prefilter = job.pipeline("prefilter", spirv::prefilter);
  std::uint32_t levelOffset = 0;
  for (std::size_t i = 1; i < env.levels.size(); ++i) {
    const facet::ibl::RadianceLevel& level = env.levels[i];
    uniforms.push_back(job.uniform("prefilter params", PrefilterParams{level.width, level.height, float(level.alpha),
                                                                       settings.samples, source.width, source.height,
                                                                       std::int32_t(chainSizes.size()), levelOffset}));
    job.dispatch(prefilter, {{0, &uniforms.back()}, {1, &chain}, {2, &levels}},
                 groupsFor(level.width, FACET_IBL_TILE_SIZE), groupsFor(level.height, FACET_IBL_TILE_SIZE));
    levelOffset += 3 * std::uint32_t(level.width * level.height);
  }

  gpu::Buffer rowSums = job.storage("SH row sums", 5 * 16 * std::uint64_t(source.height));
  uniforms.push_back(job.uniform("SH params", ShProjectParams{source.width, source.height}));
  job.dispatch(job.pipeline("sh_project", spirv::sh_project), {{0, &uniforms.back()}, {1, &chain}, {2, &rowSums}},
               groupsFor(source.height, FACET_WORKGROUP_SIZE));

  const facet::ibl::LevelSize irradianceSize = facet::ibl::irradianceMapSize(settings);
  const int irradianceSource = rules::f64::irradiance_source_level(source.width, int(chainSizes.size()));
  gpu::Buffer irradiance =
      job.storage("irradiance map", 12 * std::uint64_t(irradianceSize.width) * std::uint64_t(irradianceSize.height));
  uniforms.push_back(
      job.uniform("irradiance params",
                  IrradianceParams{irradianceSize.width, irradianceSize.height, chainSizes[irradianceSource].width,
                                   chainSizes[irradianceSource].height, chainOffsets[irradianceSource]}));
  job.dispatch(job.pipeline("irradiance", spirv::irradiance), {{0, &uniforms.back()}, {1, &chain}, {2, &irradiance}},
               groupsFor(irradianceSize.width, FACET_IBL_TILE_SIZE),
               groupsFor(irradianceSize.height, FACET_IBL_TILE_SIZE));

  uniforms.push_back(job.uniform("DFG params", DfgParams{settings.dfgSize, settings.dfgSamples}));
  const std::vector<gpu::Buffer> tables = dispatchDfgTables(job, uniforms.back(), models, settings.dfgSize);

  std::vector<const gpu::Buffer*> results{&levels, &rowSums, &irradiance};
  for (const gpu::Buffer& table : tables) results.push_back(&table);
  const std::vector<std::vector<std::byte>> bytes = job.finish(results);

  readPrefilteredLevels(env, bytes[0]);
  env.irradianceSh = facet::ibl::shFromRowSums(shRowSums(bytes[1], source.height));
  env.irradianceMap = {irradianceSize.width, irradianceSize.height, 0.0,
                       valuesAt<float>(bytes[2], 0, 3 * std::size_t(irradianceSize.width) * irradianceSize.height)};
  env.irradianceFromMap = facet::ibl::usesIrradianceMap(env.irradianceSh, env.irradianceMap);
  for (std::size_t p = 0; p < models.size(); ++p)
    env.dfg.push_back(
        {models[p].first, models[p].second, settings.dfgSize,
         valuesAt<float>(bytes[3 + p], 0, 2 * std::size_t(settings.dfgSize) * std::size_t(settings.dfgSize))});
  return env;
}

}  // namespace facet::gpu_backend
