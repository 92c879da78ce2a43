#pragma once
/// @file
/// Evaluation of all scalar constraint equations of a System (seed eq. 1.24, second part):
/// values Phi(q, t), the Jacobian C = dPhi/d[delta p, delta pi] (m x nv), the velocity
/// term C v, the quadratic term Cdot v and the explicit time derivatives, so that
///   velocity level:      C v + Phi_t = 0,
///   acceleration level:  C vdot = gamma = -(Cdot v) - Phi_tt.
/// Cost O(m) (plus O(m nv) to zero the dense Jacobian).

#include <Eigen/Dense>
#include <vector>

#include "libemb/mbs/kinematics.h"

namespace emb::mbs {

class System;

/// Continuous (unwrapped) values of the angle kernels, one slot each: the mutable part of
/// a run. A slot starts unset; its first value is taken on the branch nearest to the
/// equation's target (f(t) for a motion) and later values within +-pi of the previous one.
class ConstraintWorkspace {
 public:
  explicit ConstraintWorkspace(const System& system);
  /// The continuous angle for raw atan2 value `raw` [rad].
  double Unwrap(int slot, double raw, double hint);
  /// Forgets all slots (e.g. before a new assembly).
  void Reset();

 private:
  std::vector<double> angle_;
};

/// Values of all equations at one configuration.
struct ConstraintEval {
  Eigen::VectorXd phi;        ///< Phi(q, t), m
  Eigen::MatrixXd jacobian;   ///< C, m x nv
  Eigen::VectorXd quadratic;  ///< Cdot v, m
  Eigen::VectorXd phi_t;      ///< dPhi/dt, m
  Eigen::VectorXd phi_tt;     ///< d2Phi/dt2, m
  /// gamma = -(Cdot v) - Phi_tt (acceleration right-hand side).
  Eigen::VectorXd gamma() const { return -quadratic - phi_tt; }
};

/// Evaluates all equations at body kinematics `bodies` and time t.
ConstraintEval CalcConstraints(const System& system, const std::vector<BodyKinematics>& bodies,
                               double t, ConstraintWorkspace* workspace);

/// The equation with the largest |Phi| and its value (for "assembly failed at ..." reports).
struct WorstEquation {
  int equation{-1};
  double residual{0.0};
};
WorstEquation FindWorstEquation(const Eigen::VectorXd& phi);

}  // namespace emb::mbs
