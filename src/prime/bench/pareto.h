// The Pareto front of (cost, error) points: the settings no other setting
// beats on both time and error.
#pragma once
#include <span>
#include <vector>

namespace prime::bench {

struct CostError {
  double cost = 0;   // e.g. CPU seconds
  double error = 0;  // e.g. RMSE
};

// Indices of the points that no other point dominates (a point dominates
// another when it is no worse in both coordinates and better in at least
// one), in increasing cost. Of several identical points the first is kept.
// Points with a NaN coordinate are never on the front.
std::vector<int> paretoFront(std::span<const CostError> points);

}  // namespace prime::bench
