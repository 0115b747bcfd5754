#include "analysis/timing.h"

#include <algorithm>
#include <stdexcept>

namespace facet::analysis {

double median(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("median of no values");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double medianMilliseconds(int repeats, const std::function<double()>& run) {
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) times.push_back(run());
  return median(times);
}

double traceMilliseconds(const RenderReport& report) {
  double total = 0;
  for (const StageTime& stage : report.stages)
    if (stage.stage != Stage::RefineBvh && stage.stage != Stage::Environment && !isStartup(stage.stage))
      total += stage.milliseconds;
  return total;
}

double preparationMilliseconds(const RenderReport& report) {
  for (const StageTime& stage : report.stages)
    if (stage.stage == Stage::Environment) return stage.milliseconds;
  return 0;
}

}  // namespace facet::analysis
