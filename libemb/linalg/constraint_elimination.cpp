#include "libemb/linalg/constraint_elimination.h"

#include <algorithm>
#include <cmath>

#include "libemb/common/error.h"

namespace emb {
namespace {

using Terms = std::vector<std::pair<int, double>>;

// Scatter accumulator over n unknowns: value and gross magnitude (Σ|contribution|) per
// unknown, with the list of unknowns touched, reset after each use.
class Accumulator {
 public:
  explicit Accumulator(int n) : value_(n, 0.0), gross_(n, 0.0), seen_(n, 0) {}
  void Add(int j, double a) {
    if (!seen_[j]) {
      seen_[j] = 1;
      touched_.push_back(j);
    }
    value_[j] += a;
    gross_[j] += std::abs(a);
  }
  /// Terms whose value is above tolerance × their gross magnitude; resets.
  Terms Collect(double tolerance, double* max_gross) {
    Terms out;
    *max_gross = 0.0;
    std::sort(touched_.begin(), touched_.end());
    for (int j : touched_) {
      *max_gross = std::max(*max_gross, gross_[j]);
      if (std::abs(value_[j]) > tolerance * gross_[j]) out.emplace_back(j, value_[j]);
      value_[j] = gross_[j] = 0.0;
      seen_[j] = 0;
    }
    touched_.clear();
    return out;
  }

 private:
  std::vector<double> value_, gross_;
  std::vector<char> seen_;
  std::vector<int> touched_;
};

}  // namespace

ConstraintElimination EliminateConstraints(int n, const std::vector<LinearConstraint>& rows,
                                           double tolerance) {
  std::vector<int> slave_index(n, -1);  // unknown → index into expr
  std::vector<int> slave_unknown;       // creation order
  std::vector<Terms> expr;              // slave = Σ terms (in unknowns that were masters then)
  Accumulator acc(n);
  ConstraintElimination out;
  // Adds a·x_j with every slave replaced by its expression (recursively: an expression only
  // names unknowns that were masters when it was made, some of which became slaves since).
  std::vector<std::pair<int, double>> stack;
  auto add_substituted = [&](int j, double a) {
    stack.emplace_back(j, a);
    while (!stack.empty()) {
      const auto [k, b] = stack.back();
      stack.pop_back();
      if (slave_index[k] < 0) {
        acc.Add(k, b);
        continue;
      }
      for (const auto& [l, c] : expr[slave_index[k]]) stack.emplace_back(l, b * c);
    }
  };
  for (size_t r = 0; r < rows.size(); ++r) {
    for (const auto& [j, a] : rows[r].terms) {
      EMB_THROW_IF(j < 0 || j >= n, "constraint row " << r << ": expected unknowns in [0, " << n
                                                      << "), got " << j);
      EMB_THROW_IF(!std::isfinite(a), "constraint row " << r << ": coefficient of unknown " << j
                                                        << " is not finite");
      add_substituted(j, a);
    }
    double max_gross = 0.0;
    const Terms t = acc.Collect(tolerance, &max_gross);
    double amax = 0.0;
    int pivot = -1;
    for (const auto& [j, a] : t)
      if (std::abs(a) > amax) amax = std::abs(a), pivot = j;
    if (pivot < 0 || !(amax > tolerance * max_gross)) {
      out.dependent_rows.push_back(static_cast<int>(r));
      continue;
    }
    for (const auto& [j, a] : t)
      if (j == rows[r].preferred_slave && std::abs(a) >= kPreferredPivotRatio * amax) pivot = j;
    double ap = 0.0;
    for (const auto& [j, a] : t)
      if (j == pivot) ap = a;
    Terms e;
    e.reserve(t.size() - 1);
    for (const auto& [j, a] : t)
      if (j != pivot) e.emplace_back(j, -a / ap);
    slave_index[pivot] = static_cast<int>(expr.size());
    slave_unknown.push_back(pivot);
    expr.push_back(std::move(e));
  }
  // Final expressions in masters only: a slave's expression names only later slaves, so
  // resolving from the last one back needs each substitution once.
  std::vector<Terms> resolved(expr.size());
  for (int s = static_cast<int>(expr.size()) - 1; s >= 0; --s) {
    for (const auto& [j, a] : expr[s]) {
      if (slave_index[j] < 0) {
        acc.Add(j, a);
      } else {
        EMB_CHECK(slave_index[j] > s);
        for (const auto& [l, c] : resolved[slave_index[j]]) acc.Add(l, a * c);
      }
    }
    double unused = 0.0;
    resolved[s] = acc.Collect(0.0, &unused);  // keep exact cancellations out only
  }
  std::vector<int> column(n, -1);
  for (int j = 0; j < n; ++j) {
    if (slave_index[j] >= 0) {
      out.slaves.push_back(j);
    } else {
      column[j] = static_cast<int>(out.masters.size());
      out.masters.push_back(j);
    }
  }
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(out.masters.size());
  for (size_t k = 0; k < out.masters.size(); ++k)
    trip.emplace_back(out.masters[k], static_cast<int>(k), 1.0);
  for (size_t s = 0; s < resolved.size(); ++s)
    for (const auto& [j, a] : resolved[s]) trip.emplace_back(slave_unknown[s], column[j], a);
  out.T.resize(n, static_cast<int>(out.masters.size()));
  out.T.setFromTriplets(trip.begin(), trip.end());
  return out;
}

}  // namespace emb
