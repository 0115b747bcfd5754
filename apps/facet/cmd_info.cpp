// facet info: the adapters found, the chosen one's limits, and the smoke job.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>

#include "commands.h"
#include "engine/gpu/gpu.h"
#include "engine/renderer.h"
#include "engine/smoke.h"

namespace facet::cli {
namespace {

struct InfoOptions {
  std::string adapter;
};

void printLimits(const gpu::Limits& l) {
  std::printf("  maxBufferSize                    %llu\n", (unsigned long long)l.maxBufferSize);
  std::printf("  maxStorageBufferBindingSize      %llu\n", (unsigned long long)l.maxStorageBufferBindingSize);
  std::printf("  maxComputeWorkgroupsPerDimension %u %u %u\n", l.maxComputeWorkgroupsPerDimension[0],
              l.maxComputeWorkgroupsPerDimension[1], l.maxComputeWorkgroupsPerDimension[2]);
  std::printf("  maxComputeInvocationsPerWorkgroup %u\n", l.maxComputeInvocationsPerWorkgroup);
  std::printf("  maxComputeWorkgroupStorageSize   %u\n", l.maxComputeWorkgroupStorageSize);
  std::printf("  subgroupSize                     %u\n", l.subgroupSize);
  std::printf("  timestampPeriod                  %g ns%s\n", l.timestampPeriodNs,
              l.timestampPeriodNs > 0 ? "" : " (no timestamps)");
  std::printf("  shaderFloat64                    %s\n", l.shaderFloat64 ? "yes" : "no");
}

void runInfo(const InfoOptions& options) {
  auto instance = gpu::Instance::create(gpuInstanceFromEnvironment());
  std::printf("adapters:\n");
  for (const auto& info : instance.enumerateAdapters())
    std::printf("  %s (%s, %s)\n", info.name.c_str(), gpu::toString(info.type), info.driver.c_str());
  auto adapter = instance.requestAdapter(gpuAdapterFromEnvironment(options.adapter));
  const auto& info = adapter.info();
  std::printf("using: %s\n  driver %s %s, Vulkan %s, %s\n", info.name.c_str(), info.driver.c_str(),
              info.driverInfo.c_str(), info.apiVersion.c_str(), gpu::toString(info.type));
  printLimits(adapter.limits());
  auto device = adapter.requestDevice({"facet info"});
  SmokeResult smoke = runSmokeJob(device);
  std::printf("smoke job: y = a*x + y on %zu floats: %zu mismatches, %.3f ms GPU time\n", smoke.elements,
              smoke.mismatches, smoke.gpuMilliseconds);
  if (smoke.mismatches != 0) throw gpu::Error("smoke job: the device computed wrong results");
  std::printf("smoke job: OK\n");
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  auto options = std::make_shared<InfoOptions>();
  auto* command =
      app.add_subcommand("info", "List Vulkan adapters, show the chosen one's limits, run a checked compute job");
  command->add_option("--adapter", options->adapter,
                      "Adapter name (substring); default: $FACET_ADAPTER, else a GPU, else lavapipe");
  command->callback([options] { runInfo(*options); });
}

}  // namespace facet::cli
