// A watched scene through the public API: the engine's SceneWatch
// (engine/scene_watch.h), each load read as Renderer::render reads a scene
// with its settings, each pass handed to the caller.
#include "facet/watch.h"

#include <exception>
#include <string>

#include "api/errors.h"
#include "api/image_planes.h"
#include "api/render_settings.h"
#include "api/renderer_state.h"
#include "api/scene_data.h"
#include "engine/image_memory.h"
#include "engine/scene_watch.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"

namespace facet::v0 {
void Renderer::watch(const std::string& path, const std::function<bool(const WatchPass&)>& onPass,
                     const WatchSettings& settings, const std::function<bool(const Error&)>& onBadInput) {
  api::translateErrors([&] {
    if (settings.passes < 1 || settings.passes > 4096)
      api::refuse("watch settings", "passes", "expected passes in [1, 4096]");
    if (settings.changes < 0 || settings.changes > 1000000)
      api::refuse("watch settings", "changes", "expected changes in [0, 1000000]");
    bool stop = false;
    std::exception_ptr ended;  // what ended the watch, thrown once it returns
    int picture = -1;
    WatchedScene watched;
    watched.load = [&] {
      scene::Scene s = withSettings(api::sceneOf(scene::loadScene(path, {}, settings.variant), path), settings.render);
      // The watch refines each picture by its own passes.
      s.render.sampling = scene::Sampling::OnePass;
      checkImagesFitInMemory(s, 1, "watch settings: width x height");
      return s;
    };
    watched.write = [&](const scene::Scene&, const facet::Image& image, int passes, int samples) {
      if (passes == 1) ++picture;
      stop = stop || !onPass({picture, passes, samples, publicImage(image)});
    };
    WatchEvents events;
    events.stopRequested = [&] { return stop; };
    events.badInput = [&](const std::exception_ptr& error) {
      try {
        api::translateErrors([&] { std::rethrow_exception(error); });
      } catch (const Error& e) {
        if (onBadInput) {
          stop = stop || !onBadInput(e);
          return;
        }
        ended = std::current_exception();
        stop = true;
      }
    };
    const std::scoped_lock oneAtATime(state_->rendering);
    const facet::Backend backend = settings.render.backend == Backend::Cpu ? facet::Backend::Cpu : facet::Backend::Gpu;
    SceneWatch(state_->engine, watched, {backend, 0, settings.passes, settings.changes}, std::move(events)).run();
    if (ended) std::rethrow_exception(ended);
  });
}

}  // namespace facet::v0
