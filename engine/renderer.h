// The renderer front-end: the one place where a scene meets a backend. Both
// backends fill the same Image; the report says what each stage cost.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "engine/gpu/gpu.h"
#include "engine/image/image.h"
#include "scenes/scene.h"

namespace facet {

enum class Backend { Cpu, Gpu };
const char* toString(Backend backend);

struct StageTime {
  std::string name;
  double milliseconds = 0;
};

struct RenderReport {
  Image image;
  std::string device;           // what ran the render
  std::string geometrySummary;  // refinement, patch counts and memory per object
  int patches = 0;
  std::vector<StageTime> stages;
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  std::uint64_t newtonFallbacks = 0;  // GPU exact method: cells whose domain was subdivided
  std::uint64_t cells = 0;            // GPU: of the micro-grid
  std::uint64_t gpuBytes = 0;         // GPU: scene arrays and one band's ray buffers

  double totalMilliseconds() const;
};

// The GPU choices a user makes through the environment, read here for every
// front-end (facet::gpu takes them as arguments):
//   FACET_VALIDATION=1  the Khronos validation layer, when installed
//   FACET_ADAPTER=NAME  the adapter, when `adapter` (--adapter) is empty
gpu::InstanceDescriptor gpuInstanceFromEnvironment();
gpu::AdapterOptions gpuAdapterFromEnvironment(const std::string& adapter);

// The GPU backend runs on the adapter gpuAdapterFromEnvironment(adapter)
// names; its device and pipelines are kept for the process, so each kernel
// variant is compiled once.
RenderReport render(const scene::Scene& scene, Backend backend, const std::function<void(double)>& progress = {},
                    const std::string& adapter = {});

}  // namespace facet
