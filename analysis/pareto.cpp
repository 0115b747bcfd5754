#include "analysis/pareto.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace facet::analysis {

std::vector<std::size_t> paretoFront(const std::vector<Cost>& points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].milliseconds != points[b].milliseconds) return points[a].milliseconds < points[b].milliseconds;
    return points[a].error < points[b].error;
  });
  std::vector<std::size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i : order)
    if (points[i].error < best) {
      best = points[i].error;
      front.push_back(i);
    }
  return front;
}

}  // namespace facet::analysis
