#pragma once
/// @file
/// The interface the analyses drive an integrator through: advance to an output time, read
/// the state, restart after a discontinuity, read the counters. IdaSolver (variable-order
/// BDF) and GeneralizedAlphaSolver (second order, numerically damped) implement it.

#include <Eigen/Dense>
#include <vector>

#include "libemb/integrators/integrator_report.h"
#include "libemb/integrators/linear_solver_kind.h"

namespace emb {

class DaeIntegrator {
 public:
  virtual ~DaeIntegrator() = default;
  /// Integrates to exactly t_out. On failure y() and yp() are the last accepted values and
  /// the report says where and why (a status, never an exception for numerical trouble).
  virtual IntegratorReport AdvanceTo(double t_out) = 0;
  /// Restarts from new consistent values at t0.
  virtual void Reinitialize(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) = 0;
  virtual double t() const = 0;
  virtual const Eigen::VectorXd& y() const = 0;
  virtual const Eigen::VectorXd& yp() const = 0;
  virtual IntegratorStats stats() const = 0;
  /// The linear solver in use (kAuto resolved).
  virtual LinearSolverKind linear_solver() const = 0;
  /// Structural non-zeros of the iteration matrix.
  virtual long jacobian_nonzeros() const = 0;
  /// The components that limited the step size most often (StepLimiter), most frequent
  /// first, at most `max_count`: what to look at when a run takes many small steps.
  virtual std::vector<StepLimiter> StepLimiters(int max_count) const = 0;
};

}  // namespace emb
