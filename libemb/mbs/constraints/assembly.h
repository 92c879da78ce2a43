#pragma once
/// @file
/// Consistent initial conditions for the constrained equations (1.24):
///  1. position assembly: Newton on Phi(q, t) = 0 with minimum-norm steps
///     delta = -C^+ Phi in [delta p, delta pi] (rank-deficient C allowed), quaternions
///     updated multiplicatively, so |e| = 1 throughout;
///  2. velocity projection: the v closest to the user's v0 in the kinetic-energy metric with
///     C v + Phi_t = 0:  [M C^T; C 0] [v; mu] = [M v0; -Phi_t];
///  3. accelerations and multipliers from
///     [M C^T; C 0] [vdot; lambda] = [f(q, v, t); gamma]   (gamma = -(Cdot v) - Phi_tt).
/// Failures are a status with the residual and the equation (joint) that did not close.

#include <Eigen/Dense>
#include <string>

#include "libemb/mbs/constraints/constraint_eval.h"

namespace emb::mbs {

class System;

struct AssemblyOptions {
  /// Converged when max |Phi| <= tolerance (metres for position equations, radians for
  /// orientation ones).
  double tolerance{1e-10};
  int max_iterations{50};
};

struct AssemblyResult {
  bool converged{false};
  Eigen::VectorXd q;
  int iterations{0};
  double residual{0.0};    ///< max |Phi| at the end
  int worst_equation{-1};  ///< index of max |Phi| (when not converged)
  std::string worst_name;  ///< System::EquationName of it
  std::string message;
};

/// Position assembly from q0 at time t. Cost O(iterations * m * nv * min(m, nv)).
AssemblyResult AssemblePositions(const System& system, const Eigen::VectorXd& q0, double t,
                                 ConstraintWorkspace* workspace,
                                 const AssemblyOptions& options = {});

struct VelocityProjection {
  Eigen::VectorXd v;
  /// sqrt((v - v0)^T M (v - v0) / (v0^T M v0)) or the absolute M-norm when v0 = 0 [-].
  double relative_change{0.0};
  double velocity_residual{0.0};  ///< max |C v + Phi_t| after projection
};

/// Velocity projection at an assembled q. @throws NumericalError if the KKT matrix is
/// singular (redundant constraints left in the model).
VelocityProjection ProjectVelocities(const System& system, const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& v0, double t,
                                     ConstraintWorkspace* workspace);

struct AccelerationSolution {
  Eigen::VectorXd vdot;    ///< nv
  Eigen::VectorXd lambda;  ///< m, the Lagrange multipliers of (1.24) (N or N m)
};

/// Accelerations and multipliers at (q, v, t). @throws NumericalError if singular.
AccelerationSolution SolveAccelerations(const System& system, const Eigen::VectorXd& q,
                                        const Eigen::VectorXd& v, double t,
                                        ConstraintWorkspace* workspace);

/// Applies a Newton step dx = [delta p, delta pi] per body to q (quaternions rotated).
Eigen::VectorXd ApplyDisplacement(const System& system, const Eigen::VectorXd& q,
                                  const Eigen::VectorXd& dx);

}  // namespace emb::mbs
