#include "libemb/beam/tmm_solver.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "libemb/common/error.h"

namespace emb {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

double LambdaOf(double f_hz) { return std::pow(2.0 * std::numbers::pi * f_hz, 2); }
double HzOf(double lambda) { return std::sqrt(std::max(lambda, 0.0)) / (2.0 * std::numbers::pi); }

bool OppositeSigns(double a, double b) { return (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0); }

// Brent's zero finder (Forsythe, Malcolm & Moler's ZEROIN) on [a, b] with f(a), f(b) of
// opposite signs; stops when the bracket is within 4ε|b| (round-off of λ itself).
template <typename F>
double BrentRoot(F&& f, double a, double b, double fa, double fb) {
  double c = a, fc = fa, d = b - a, e = d;
  for (int iter = 0; iter < 200; ++iter) {
    if (OppositeSigns(fb, fc) == false) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * kEps * std::abs(b);
    const double xm = 0.5 * (c - b);
    if (std::abs(xm) <= tol || fb == 0.0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {
        p = 2.0 * xm * s;
        q = 1.0 - s;
      } else {
        const double qq = fa / fc, r = fb / fc;
        p = s * (2.0 * xm * qq * (qq - r) - (b - a) * (r - 1.0));
        q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) q = -q;
      p = std::abs(p);
      if (2.0 * p < 3.0 * xm * q - std::abs(tol * q) && p < std::abs(0.5 * e * q)) {
        e = d;
        d = p / q;
      } else {
        d = e = xm;
      }
    } else {
      d = e = xm;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (xm > 0.0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

// A root of multiplicity k (or one without a sign change) in the tiny bracket [a, b]: the
// k-th smallest singular value of the scaled B(λ) vanishes there and grows linearly away
// from it (a V, unlike det B which only touches zero), so a golden-section search for its
// minimum finds the root to round-off. The scaling is frozen at the midpoint.
double SingularValueMinimum(const TmmChain& chain, double a, double b, int k, TmmResult& r) {
  const TmmChain::Scaling s = chain.CalcScaling(chain.CalcBoundaryMatrix(0.5 * (a + b)));
  auto sigma_k = [&](double lambda) {
    ++r.num_determinant_evaluations;
    const Eigen::MatrixXd Bs = s.row.asDiagonal() * chain.CalcBoundaryMatrix(lambda) *
                               s.col.asDiagonal();
    const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(Bs).singularValues();
    return sv[std::max<Eigen::Index>(sv.size() - k, 0)];
  };
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = sigma_k(x1), f2 = sigma_k(x2);
  for (int it = 0; it < 100 && b - a > 4.0 * kEps * b; ++it) {
    if (f1 <= f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - g * (b - a);
      f1 = sigma_k(x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + g * (b - a);
      f2 = sigma_k(x2);
    }
  }
  return f1 <= f2 ? x1 : x2;
}

struct Interval {
  double a, b;  // λ
  int na, nb;   // counts
  double da, db;  // scaled determinants
};

struct Root {
  double lambda;
  int multiplicity;
  const char* refinement;
};

}  // namespace

const char* Name(TmmStatus status) {
  switch (status) {
    case TmmStatus::kSuccess: return "success";
    case TmmStatus::kNoRoots: return "no roots";
    case TmmStatus::kInconsistent: return "inconsistent";
  }
  return "?";
}

Eigen::VectorXd TmmResult::frequencies_hz() const {
  Eigen::VectorXd f(modes.size());
  for (size_t i = 0; i < modes.size(); ++i) f[i] = modes[i].frequency_hz;
  return f;
}

TmmResult CalcTmmModes(const BeamModel& model, const TmmOptions& options) {
  return CalcTmmModes(TmmChain(model, options.motion), options);
}

TmmResult CalcTmmModes(const TmmChain& chain, const TmmOptions& o) {
  EMB_THROW_IF(!(std::isfinite(o.min_hz) && o.min_hz >= 0.0),
               "TMM band start: expected >= 0 Hz, got " << o.min_hz);
  EMB_THROW_IF(!(std::isfinite(o.max_hz) && o.max_hz > o.min_hz),
               "TMM band end: expected > band start " << o.min_hz << " Hz, got " << o.max_hz);
  EMB_THROW_IF(o.scan_intervals < 1,
               "TMM scan intervals: expected >= 1, got " << o.scan_intervals);
  EMB_THROW_IF(!(o.cluster_tolerance >= 1e-14 && o.cluster_tolerance < 1e-2),
               "TMM cluster tolerance: expected 1e-14 <= tol < 1e-2 (relative), got "
                   << o.cluster_tolerance);
  EMB_THROW_IF(!(std::isfinite(o.zero_frequency_hz) && o.zero_frequency_hz >= 0.0 &&
                 o.zero_frequency_hz < o.max_hz),
               "TMM zero-frequency threshold: expected 0 <= f < band end " << o.max_hz
                                                                            << " Hz, got "
                                                                            << o.zero_frequency_hz);
  EMB_THROW_IF(chain.motion() != o.motion, "TMM: the chain was built for motion '"
                                               << Name(chain.motion()) << "', the options ask for '"
                                               << Name(o.motion) << "'");
  TmmResult r;
  r.motion = o.motion;
  r.min_hz = o.min_hz;
  r.max_hz = o.max_hz;
  r.node_order = chain.node_order();
  auto count = [&](double lambda) {
    ++r.num_count_evaluations;
    return chain.CountEigenvaluesBelow(lambda);
  };
  auto det = [&](double lambda) {
    ++r.num_determinant_evaluations;
    return chain.CalcScaledDeterminant(lambda);
  };

  const double f_lo = std::max(o.min_hz, o.zero_frequency_hz);
  const double lambda_hi = LambdaOf(o.max_hz);
  std::vector<double> grid(o.scan_intervals + 1);
  std::vector<int> counts(grid.size());
  std::vector<double> dets(grid.size());
  for (int j = 0; j <= o.scan_intervals; ++j) {
    const double f = f_lo + (o.max_hz - f_lo) * j / o.scan_intervals;
    grid[j] = j == o.scan_intervals ? lambda_hi : LambdaOf(f);
    counts[j] = count(grid[j]);
    dets[j] = det(grid[j]);
  }
  r.num_below_band = counts.front();
  if (o.min_hz < o.zero_frequency_hz) r.num_zero_frequency_modes = counts.front();
  const int expected = counts.back() - counts.front();
  if (expected == 0) {
    std::ostringstream m;
    m << "no natural frequency in the band [" << f_lo << ", " << o.max_hz << "] Hz (TMM "
      << Name(o.motion) << "): " << counts.front() << " eigenvalues lie below its start and "
      << counts.back() << " below its end";
    r.status = TmmStatus::kNoRoots;
    r.message = m.str();
    return r;
  }

  std::vector<Root> roots;
  std::ostringstream problems;
  std::vector<Interval> todo;
  for (int j = o.scan_intervals - 1; j >= 0; --j)
    todo.push_back({grid[j], grid[j + 1], counts[j], counts[j + 1], dets[j], dets[j + 1]});
  while (!todo.empty()) {
    const Interval iv = todo.back();
    todo.pop_back();
    const int k = iv.nb - iv.na;
    if (k < 0) {
      problems << "count decreases from " << iv.na << " to " << iv.nb << " over ["
               << HzOf(iv.a) << ", " << HzOf(iv.b) << "] Hz; ";
      continue;
    }
    if (k == 0) {
      if (OppositeSigns(iv.da, iv.db))
        problems << "determinant changes sign without a root by count in [" << HzOf(iv.a)
                 << ", " << HzOf(iv.b) << "] Hz; ";
      continue;
    }
    if (iv.da == 0.0 && k == 1) {  // a root exactly at the left end (not counted below a)
      roots.push_back({iv.a, k, "brent"});
      continue;
    }
    if (k == 1 && OppositeSigns(iv.da, iv.db)) {
      // Scaling frozen at the midpoint: the determinant is then a polynomial in λ.
      const TmmChain::Scaling s = chain.CalcScaling(chain.CalcBoundaryMatrix(0.5 * (iv.a + iv.b)));
      auto g = [&](double lambda) {
        ++r.num_determinant_evaluations;
        return chain.CalcScaledDeterminant(lambda, &s);
      };
      const double ga = g(iv.a), gb = g(iv.b);
      if (OppositeSigns(ga, gb)) {
        roots.push_back({BrentRoot(g, iv.a, iv.b, ga, gb), 1, "brent"});
        continue;
      }
    }
    if (iv.b - iv.a <= o.cluster_tolerance * iv.b) {
      roots.push_back({SingularValueMinimum(chain, iv.a, iv.b, k, r), k, "singular-value minimum"});
      continue;
    }
    const double mid = 0.5 * (iv.a + iv.b);
    const int nm = count(mid);
    const double dm = det(mid);
    todo.push_back({mid, iv.b, nm, iv.nb, dm, iv.db});
    todo.push_back({iv.a, mid, iv.na, nm, iv.da, dm});
  }
  std::sort(roots.begin(), roots.end(),
            [](const Root& x, const Root& y) { return x.lambda < y.lambda; });

  // Mode shapes: null vectors of the scaled B, propagated, M-orthonormal (lumped M).
  const Eigen::MatrixXd& M = chain.lumped_system().M;
  for (const Root& root : roots) {
    const Eigen::MatrixXd B = chain.CalcBoundaryMatrix(root.lambda);
    const TmmChain::Scaling s = chain.CalcScaling(B);
    const Eigen::MatrixXd Bs = s.row.asDiagonal() * B * s.col.asDiagonal();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Bs, Eigen::ComputeFullV);
    const int n = static_cast<int>(Bs.cols());
    const int k = std::min(root.multiplicity, n);
    const Eigen::VectorXd& sv = svd.singularValues();
    std::vector<Eigen::VectorXd> shapes;
    for (int i = 0; i < k; ++i) {
      const Eigen::VectorXd a = s.col.asDiagonal() * svd.matrixV().col(n - 1 - i);
      const Eigen::MatrixXd motion = chain.CalcNodeMotions(root.lambda, a);
      Eigen::VectorXd phi = Eigen::Map<const Eigen::VectorXd>(motion.data(), motion.size());
      for (const Eigen::VectorXd& q : shapes) phi -= q.dot(M * phi) * q;
      const double norm2 = phi.dot(M * phi);
      if (norm2 > 0.0) phi /= std::sqrt(norm2);
      shapes.push_back(phi);
    }
    for (int i = 0; i < root.multiplicity; ++i) {
      TmmMode mode;
      mode.lambda = root.lambda;
      mode.frequency_hz = HzOf(root.lambda);
      mode.multiplicity = root.multiplicity;
      mode.refinement = root.refinement;
      mode.boundary_residual = sv[0] > 0.0 ? sv[n - k] / sv[0] : 0.0;
      const Eigen::VectorXd& phi = shapes[std::min(i, k - 1)];
      mode.motion = Eigen::Map<const Eigen::MatrixXd>(phi.data(), kBeamNodeDofs,
                                                      phi.size() / kBeamNodeDofs);
      mode.index = r.num_below_band + static_cast<int>(r.modes.size()) + 1;
      r.modes.push_back(std::move(mode));
    }
  }
  if (static_cast<int>(r.modes.size()) != expected)
    problems << "found " << r.modes.size() << " roots where the count expects " << expected << "; ";
  if (!problems.str().empty()) {
    r.status = TmmStatus::kInconsistent;
    r.message = "TMM " + std::string(Name(o.motion)) + ": " + problems.str();
  }
  return r;
}

}  // namespace emb
