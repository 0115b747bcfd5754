// The renderer front-end: the one place where a scene meets a backend. Both
// backends fill the same Image; the report says what each stage cost.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/cpu/path_tracer.h"
#include "engine/gpu/gpu.h"
#include "engine/image/image.h"
#include "engine/image/pixel_rect.h"
#include "engine/stages/stages.h"
#include "scenes/light_transport.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet {

enum class Backend { Cpu, Gpu };
const char* toString(Backend backend);

// What part of the image to render, and on how many threads.
struct RenderOptions {
  std::optional<PixelRect> crop;  // of the full image; none: all of it
  unsigned threads = 0;           // CPU backend's workers; 0: every core
  // The scene's refined objects and their BVHs, built by the caller from
  // this scene's objects, camera and image size (an adaptive render's rounds
  // share one, and count its time); none: built here.
  std::shared_ptr<const scene::SceneGeometry> geometry;
};

struct RenderReport {
  Image image;                  // the crop's pixels, or the whole image
  PixelRect window;             // where `image` lies in the full image
  std::string device;           // what ran the render
  std::string geometrySummary;  // refinement, patch counts and memory per object
  // The light transport rendered, stated or chosen, and what was chosen and
  // why (scenes/light_transport.h).
  scene::LightTransport lightTransport;
  // The camera samples per pixel of one pass; 0 for adaptive rounds
  // (engine/adaptive_render.h). Where facet chose the sampling, why
  // (scenes/sampling_choice.h).
  int samplesPerPixel = 0;
  std::string samplingNote;
  int patches = 0;
  std::vector<StageTime> stages;
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  // With bounces > 0 (either backend): the rays of bounce 0 (camera rays) to the last
  std::vector<cpu::BounceRays> raysPerBounce;
  std::uint64_t newtonFallbacks = 0;  // GPU exact method: cells whose domain was subdivided
  std::uint64_t cells = 0;            // GPU: of the micro-grid
  std::uint64_t gpuBytes = 0;         // GPU: scene arrays and one band's ray buffers
  // Once each, for the render that met it: a damaged or foreign cache file
  // that was ignored and rebuilt.
  std::vector<std::string> warnings;

  double totalMilliseconds() const;
};

// The GPU choices a user makes through the environment, read here for every
// front-end (facet::gpu takes them as arguments):
//   FACET_VALIDATION=1  the Khronos validation layer, when installed
//   FACET_VALIDATION=required  the layer, or an error where it is missing
//   FACET_ADAPTER=NAME  the adapter, when `adapter` (--adapter) is empty
gpu::InstanceDescriptor gpuInstanceFromEnvironment();
gpu::AdapterOptions gpuAdapterFromEnvironment(const std::string& adapter);

// Renders scenes on either backend; the GPU one on the adapter
// gpuAdapterFromEnvironment(adapter) names. Its GPU context (instance,
// device, and the pipelines each kernel variant compiles once) is made at
// the first GPU render and lives as long as the Renderer: an owner in a
// caller's scope ends the device before the process unloads the libraries
// Vulkan loaded, which a static owner would outlive.
class Renderer {
 public:
  explicit Renderer(std::string adapter = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  RenderReport render(const scene::Scene& scene, Backend backend, const std::function<void(double)>& progress = {},
                      const RenderOptions& options = {});

 private:
  struct GpuContext;
  GpuContext& gpuContext();

  std::string adapter_;
  std::unique_ptr<GpuContext> gpu_;
};

// One render by a Renderer of its own.
RenderReport render(const scene::Scene& scene, Backend backend, const std::function<void(double)>& progress = {},
                    const std::string& adapter = {});

}  // namespace facet
