// A picture refined pass by pass, for a watch (engine/scene_watch.h): the
// rounds of engine/adaptive_render.h over the whole image, each pass one
// round of the scene's samples with its own random numbers, the beauty
// their mean and the AOVs the first pass's, which passes through each
// pixel's centre.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "engine/image/image.h"
#include "engine/image/sample_rounds.h"
#include "engine/renderer.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet {

class ProgressivePicture {
 public:
  ProgressivePicture(Renderer& renderer, Backend backend, unsigned threads)
      : renderer_(renderer), backend_(backend), threads_(threads) {}

  struct Pass {
    double renderMilliseconds = 0;  // wall clock of its renders
    double stageMilliseconds = 0;   // the sum of their stages
    // On the GPU, whether it diced the geometry anew; none on the CPU
    // reference, which keeps nothing between renders.
    std::optional<bool> geometryDiced;
  };

  // Renders pass `pass` of `scene` into the picture; pass 0 starts it anew.
  // A refining pass is rendered in strips of whole rows, each of about
  // kStripMilliseconds of the last render's stages, and ends unfinished,
  // returning nothing and the picture as it was, when `stale` says so
  // between two: a change waits for a strip, not a pass. Pass 0 takes
  // `geometry` for the picture where one is given (built from `scene`), else
  // builds it; the later passes keep it.
  std::optional<Pass> render(const scene::Scene& scene, int pass, const std::function<bool()>& stale,
                             std::shared_ptr<const scene::SceneGeometry> geometry = nullptr);

  Image image() const;                      // as the passes so far make it
  int passes() const { return passes_; }    // in image()
  int samples() const { return samples_; }  // per pixel, in image()'s beauty

 private:
  Renderer& renderer_;
  Backend backend_;
  unsigned threads_;
  std::optional<SampleRounds> rounds_;
  std::shared_ptr<const scene::SceneGeometry> geometry_;  // of the picture pass 0 began
  int samples_ = 0, passes_ = 0;
  double millisecondsPerRay_ = 0;  // of the last render's stages, their fixed costs included
  Image first_;
};

}  // namespace facet
