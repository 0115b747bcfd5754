#include "api/render_settings.h"

#include <string>

#include "api/scene_data.h"
#include "scenes/input_error.h"

namespace facet::v0 {
namespace {

void require(bool valid, const std::string& field, const std::string& rule) {
  if (!valid) throw scene::InputError("render settings", 0, field, rule);
}

}  // namespace

scene::Scene withSettings(const Scene& input, const RenderSettings& s) {
  scene::Scene out = input.data().scene;
  if (s.width) require(*s.width >= 1 && *s.width <= 16384, "width", "must be in [1, 16384]");
  if (s.height) require(*s.height >= 1 && *s.height <= 16384, "height", "must be in [1, 16384]");
  if (s.spp)
    require(*s.spp >= 1 && *s.spp <= 4096 && scene::isSquare(*s.spp), "spp",
            std::string("must be in [1, 4096]; ") + scene::kSamplesPerPixelRule);
  if (s.tessLevel) require(*s.tessLevel >= 1 && *s.tessLevel <= 256, "tessLevel", "must be in [1, 256]");
  if (s.bounces)
    require(*s.bounces >= 0 && *s.bounces <= scene::kMaxBounces, "bounces",
            "must be in [0, " + std::to_string(scene::kMaxBounces) + "]");
  out.render.width = s.width.value_or(out.render.width);
  out.render.height = s.height.value_or(out.render.height);
  if (s.spp) {
    out.render.samplesPerPixel = *s.spp;
    out.render.sampling = scene::Sampling::OnePass;
  }
  if (s.method)
    out.render.method =
        *s.method == Method::Exact ? scene::IntersectionMethod::Exact : scene::IntersectionMethod::Tessellated;
  if (s.tessLevel) out.render.tessellationRate = s.tessLevel;
  if (s.bounces) {
    out.render.bounces = *s.bounces;
    out.render.bouncesStated = true;
  }
  require(!scene::bouncesContradictEnvironment(out.render, out.environment), "bounces",
          scene::kBouncesNeedOcclusionRule);
  return out;
}

}  // namespace facet::v0
