#include "src/prime/bench/pareto.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace prime::bench {

std::vector<int> paretoFront(std::span<const CostError> points) {
  std::vector<int> order;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    if (!std::isnan(points[i].cost) && !std::isnan(points[i].error)) order.push_back(i);
  // Cheapest first; on equal cost the smaller error first; then list order.
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    return points[a].error < points[b].error;
  });
  // Sweep: a point is on the front when its error is strictly below every
  // cheaper-or-equal point's error seen so far.
  std::vector<int> front;
  double best = INFINITY;
  for (int i : order)
    if (points[i].error < best) {
      front.push_back(i);
      best = points[i].error;
    }
  return front;
}

}  // namespace prime::bench
