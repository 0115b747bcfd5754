#include "preview_options.h"

#include <cmath>
#include <stdexcept>

namespace facet::cli {

void addPreviewOptions(CLI::App& command, PreviewFlags& flags) {
  command.add_option("--exposure", flags.exposure, "PNG exposure in stops: the radiance is scaled by 2^stops");
  command.add_option(
      "--tonemap", flags.tonemap,
      std::string("PNG tone curve: ") + kToneCurveNames + " (default: pbr-neutral, Khronos PBR Neutral)");
  auto* background =
      command.add_option("--background", flags.background, "PNG background R,G,B (linear) in place of the environment")
          ->delimiter(',')
          ->expected(3)
          ->check(CLI::Number);
  command
      .add_flag("--alpha", flags.alpha, "PNG with straight (unpremultiplied) alpha: coverage, without the background")
      ->excludes(background);
}

PreviewOptions chosenPreview(const PreviewFlags& flags) {
  PreviewOptions options;
  if (!validExposure(flags.exposure))
    throw std::invalid_argument("--exposure '" + std::to_string(flags.exposure) + "': " + kExposureRule);
  options.exposure = flags.exposure;
  const std::optional<ToneCurve> curve = toneCurveNamed(flags.tonemap);
  if (!curve) throw std::invalid_argument("--tonemap '" + flags.tonemap + "': expected one of: " + kToneCurveNames);
  options.curve = *curve;
  if (!flags.background.empty()) {
    const glm::dvec3 colour(flags.background[0], flags.background[1], flags.background[2]);
    if (!validBackground(colour))
      throw std::invalid_argument("--background '" + CLI::detail::join(flags.background, ",") +
                                  "': " + kBackgroundRule);
    options.background = glm::vec3(colour);
  }
  options.straightAlpha = flags.alpha;
  return options;
}

}  // namespace facet::cli
