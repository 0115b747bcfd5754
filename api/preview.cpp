// The preview stage through the public API: its settings checked by the
// rules `facet preview` applies to its flags, then the engine's stage
// (engine/preview_stage.h) on the Renderer's device.
#include "facet/preview.h"

#include <cstdlib>
#include <string>

#include "api/errors.h"
#include "api/image_planes.h"
#include "api/renderer_state.h"
#include "api/scene_data.h"
#include "engine/image/image_io.h"
#include "engine/image/child_process.h"
#include "engine/image/movie.h"
#include "engine/image_memory.h"
#include "engine/preview_stage.h"
#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/value_rules.h"

namespace facet::v0 {
namespace {

constexpr const char* kSettings = "preview settings";  // what errors name for a bad setting

[[noreturn]] void refuseSetting(const std::string& field, const std::string& rule) {
  api::refuse(kSettings, field, rule);
}

facet::ToneCurve engineCurve(v0::ToneCurve curve) {
  return curve == v0::ToneCurve::Aces    ? facet::ToneCurve::Aces
         : curve == v0::ToneCurve::Clamp ? facet::ToneCurve::Clamp
                                         : facet::ToneCurve::PbrNeutral;
}

PreviewStageSettings stageSettings(const PreviewSettings& s) {
  if (s.materials.empty()) refuseSetting("materials", "give at least one material (a preset or a material file)");
  if (!scene::validNoiseThreshold(s.noiseThreshold)) refuseSetting("noiseThreshold", scene::kNoiseThresholdRule);
  if (!scene::validMaxSpp(s.maxSpp)) refuseSetting("maxSpp", scene::kMaxSppRule);
  if (s.timeLimit && !validTimeLimit(*s.timeLimit)) refuseSetting("timeLimit", kTimeLimitRule);
  if (s.turntable && (*s.turntable < 2 || *s.turntable > 3600))
    refuseSetting("turntable", "expected frames in [2, 3600]");
  if (const auto rule = scene::rangeRule(s.exposure, -64, 64)) refuseSetting("exposure", *rule);
  PreviewStageSettings out;
  out.adaptive.noiseThreshold = s.noiseThreshold;
  out.adaptive.maxSpp = s.maxSpp;
  out.adaptive.timeLimitSeconds = s.timeLimit.value_or(kNoTimeLimit);
  out.look.exposure = float(s.exposure);
  out.look.curve = engineCurve(s.toneCurve);
  out.columns = s.columns;
  out.turntable = s.turntable;
  out.turn = s.turn == Turn::Environment ? scene::TurntableTurn::Environment : scene::TurntableTurn::Model;
  out.ground = s.ground;
  out.backend = s.backend == Backend::Cpu ? facet::Backend::Cpu : facet::Backend::Gpu;
  return out;
}

// The model lit as the stage lights it, at the pictures' size.
scene::Scene litModel(const Scene& model, const PreviewSettings& s) {
  if (const auto rule = scene::rangeRule(s.width, 1, 16384)) refuseSetting("width", *rule);
  if (const auto rule = scene::rangeRule(s.height, 1, 16384)) refuseSetting("height", *rule);
  if (s.columns < 0 || s.columns > int(s.materials.size()))
    refuseSetting("columns", "expected 0 (chosen) up to one per material");
  scene::Scene lit = studioLitModel(model.data().scene);
  if (s.environment) {
    Scene withMap = model;
    withMap.setEnvironment(s.environment);
    lit.environment = withMap.data().scene.environment;
  }
  lit.render.width = s.width;
  lit.render.height = s.height;
  checkImagesFitInMemory(lit, int(s.materials.size()) + 1, std::string(kSettings) + ": width x height");
  return lit;
}

PreviewSheet publicSheet(const facet::PreviewSheet& sheet, const ContactSheetLayout& layout) {
  PreviewSheet out{sheet.frame, {}, layout.width(), layout.height(), sheet.rgba};
  for (const facet::PreviewPicture& p : sheet.pictures)
    out.pictures.push_back({p.label, publicImage(p.report.image), p.rgba, api::adaptiveSampling(p.report)});
  return out;
}

}  // namespace

PreviewSheet Renderer::preview(const Scene& model, const PreviewSettings& settings, int frame) {
  return api::translateErrors([&] {
    const PreviewStage stage(litModel(model, settings), settings.materials, stageSettings(settings));
    if (frame < 0 || frame >= stage.frames())
      refuseSetting("frame", "expected one of the " + std::to_string(stage.frames()) + " frames, from 0");
    const std::scoped_lock oneAtATime(state_->rendering);
    return publicSheet(stage.render(state_->engine, frame), stage.layout());
  });
}

void Renderer::writePreview(const Scene& model, const PreviewSettings& settings, const std::string& output,
                            double fps) {
  api::translateErrors([&] {
    if (!(fps >= 1 && fps <= 120)) refuseSetting("fps", "expected frames per second in [1, 120]");
    const char* searchPath = std::getenv("PATH");
    const std::string path = searchPath ? searchPath : "";
    checkOutputPath("output", output);
    if (!settings.turntable) {
      checkOutputExtension("output", output, ".png");
    } else {
      if (!movieFormat(output)) throw OutputError("output '" + output + "': a turntable is a movie: .mp4 or .gif");
      if (!findOnPath("ffmpeg", path)) throw OutputError("output '" + output + "': " + kFfmpegMissing);
    }
    std::vector<std::filesystem::path> inputs = model.data().inputs;
    const scene::InputFileLog read;  // the material files and the environment map
    const PreviewStage stage(litModel(model, settings), settings.materials, stageSettings(settings));
    inputs.insert(inputs.end(), read.files().begin(), read.files().end());
    checkNotAnInput("output", output, inputs);
    const std::scoped_lock oneAtATime(state_->rendering);
    writePreviewStage(state_->engine, stage, output, fps, path);
  });
}

}  // namespace facet::v0
