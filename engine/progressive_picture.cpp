#include "engine/progressive_picture.h"

#include <algorithm>
#include <chrono>

#include "engine/adaptive_render.h"
#include "rules/rules.h"
#include "scenes/scene_geometry.h"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

// At 1 spp a pixel's one sample passes through its centre
// (rules/camera/sample_plan.h), so passes of 1 would all be alike: the
// first pass of such a picture is a quick look, and its refining passes
// take a net of this many samples each, their mean alone the beauty.
constexpr int kRefiningSpp = 4;
// A change waits at most about this long for the refining pass in progress.
constexpr double kStripMilliseconds = 100;

bool dicedCells(const RenderReport& report) {
  return std::any_of(report.stages.begin(), report.stages.end(),
                     [](const StageTime& s) { return s.stage == Stage::DiceCells; });
}

}  // namespace

std::optional<ProgressivePicture::Pass> ProgressivePicture::render(
    const scene::Scene& scene, int pass, const std::function<bool()>& stale,
    std::shared_ptr<const scene::SceneGeometry> geometry) {
  const int width = scene.render.width, height = scene.render.height;
  const bool quickLook = scene.render.samplesPerPixel == 1;
  RoundFrame frame = roundFrame(scene, pass);
  if (frame.scene.environment) frame.scene.environment->seed = scene.environment->seed + std::uint32_t(pass);
  if (quickLook && pass > 0) frame.scene.render.samplesPerPixel = kRefiningSpp;
  const int roundWidth = frame.scene.render.width;
  const std::uint32_t strata = rules::f64::sample_strata(std::uint32_t(frame.scene.render.samplesPerPixel));
  const double rays = double(rules::f64::rays_per_pixel(strata)) * roundWidth;  // per row
  const int rows = pass == 0 ? height : std::clamp(int(kStripMilliseconds / (millisecondsPerRay_ * rays)), 1, height);
  Image round;  // the pass's beauty over whole rows of the round's image
  round.width = roundWidth;
  round.height = height;
  Pass timing;
  if (pass == 0) {
    // One for the picture: its passes widen the image by pixels of the same
    // size, and its strips are crops (scenes/scene_geometry.h).
    const Clock::time_point start = Clock::now();
    geometry_ =
        geometry ? std::move(geometry) : std::make_shared<const scene::SceneGeometry>(scene::buildGeometry(scene));
    timing.renderMilliseconds += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
  for (int y0 = 0; y0 < height; y0 += rows) {
    if (y0 > 0 && stale()) return std::nullopt;
    // Whole rows of the round's larger image: a crop narrower than the
    // image is rendered a row at a time (one submission each).
    const int y1 = std::min(height, y0 + rows);
    const PixelRect crop{0, frame.dy + y0, roundWidth, frame.dy + y1};
    const Clock::time_point start = Clock::now();
    RenderReport report = renderer_.render(frame.scene, backend_, {}, {crop, threads_, geometry_});
    timing.renderMilliseconds += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    // By the stages: the wall clock of the first render holds the pipelines' compilation too.
    millisecondsPerRay_ = std::max(report.totalMilliseconds(), 0.01) / (rays * (y1 - y0));
    timing.stageMilliseconds += report.totalMilliseconds();
    if (backend_ == Backend::Gpu) timing.geometryDiced = timing.geometryDiced.value_or(false) || dicedCells(report);
    round.beauty.insert(round.beauty.end(), report.image.beauty.begin(), report.image.beauty.end());
    if (pass == 0) first_ = std::move(report.image);
  }
  if (pass == 0 || (quickLook && pass == 1)) {
    rounds_.emplace(width, height, std::max(width, height));
    samples_ = 0;
  }
  rounds_->add(round, {-frame.dx, 0, width + frame.dx, height}, {0});
  samples_ += frame.scene.render.samplesPerPixel;
  passes_ = pass + 1;
  return timing;
}

Image ProgressivePicture::image() const {
  Image image = first_;
  if (rounds_) image.beauty = rounds_->beauty();
  return image;
}

}  // namespace facet
