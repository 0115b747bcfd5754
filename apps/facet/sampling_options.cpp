#include "sampling_options.h"

#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/adaptive_render.h"

namespace facet::cli {
namespace {

std::invalid_argument broken(const char* flag, double value, const char* rule) {
  std::ostringstream text;
  text << flag << " '" << value << "': " << rule;
  return std::invalid_argument(text.str());
}

}  // namespace

double checkedNoiseThreshold(double threshold) {
  if (!scene::validNoiseThreshold(threshold)) throw broken("--noise-threshold", threshold, scene::kNoiseThresholdRule);
  return threshold;
}

int checkedMaxSpp(long long spp) {
  if (!scene::validMaxSpp(spp)) throw broken("--max-spp", double(spp), scene::kMaxSppRule);
  return int(spp);
}

double checkedTimeLimit(double seconds) {
  if (!validTimeLimit(seconds)) throw broken("--time-limit", seconds, kTimeLimitRule);
  return seconds;
}

}  // namespace facet::cli
