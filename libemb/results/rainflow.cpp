#include "libemb/results/rainflow.h"

#include <algorithm>
#include <cmath>

namespace emb::results {

std::vector<double> Reversals(const std::vector<double>& history) {
  std::vector<double> r;
  for (double x : history) {
    if (!r.empty() && x == r.back()) continue;
    // Drop the middle point of a monotonic run: r.back() between its neighbours.
    if (r.size() >= 2 && (r.back() - r[r.size() - 2]) * (x - r.back()) > 0.0)
      r.back() = x;
    else
      r.push_back(x);
  }
  return r;
}

std::vector<RainflowCycle> CountRainflow(const std::vector<double>& history) {
  std::vector<RainflowCycle> cycles;
  std::vector<double> stack;  // reversals not yet counted; stack[0] is the start S
  auto add = [&](double a, double b, double count) {
    cycles.push_back({std::abs(a - b), 0.5 * (a + b), count});
  };
  for (double x : Reversals(history)) {
    stack.push_back(x);
    while (stack.size() >= 3) {
      const std::size_t n = stack.size();
      const double X = std::abs(stack[n - 1] - stack[n - 2]);
      const double Y = std::abs(stack[n - 2] - stack[n - 3]);
      if (X < Y) break;
      if (n == 3) {  // Y contains the start: half a cycle, S moves to Y's second point
        add(stack[0], stack[1], 0.5);
        stack.erase(stack.begin());
      } else {
        add(stack[n - 3], stack[n - 2], 1.0);
        stack.erase(stack.end() - 3, stack.end() - 1);
      }
    }
  }
  for (std::size_t i = 0; i + 1 < stack.size(); ++i) add(stack[i], stack[i + 1], 0.5);
  return cycles;
}

std::vector<RainflowCycle> CountRainflowPeriodic(const std::vector<double>& history) {
  if (history.size() < 2) return {};
  const auto peak = std::max_element(history.begin(), history.end(),
                                     [](double a, double b) { return std::abs(a) < std::abs(b); });
  std::vector<double> rotated(peak, history.end());
  rotated.insert(rotated.end(), history.begin(), peak);
  rotated.push_back(*peak);
  // Started and closed at the absolute extreme, the residue pairs into whole cycles: two
  // half cycles of every range are one cycle of the repeated history.
  std::vector<RainflowCycle> cycles = CountRainflow(rotated);
  return cycles;
}

}  // namespace emb::results
