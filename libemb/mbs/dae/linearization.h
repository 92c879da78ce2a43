#pragma once
/// @file
/// Small vibrations of a constrained model about an equilibrium or a steady motion (seed eq.
/// 1.24 linearised): with M the mass matrix, K = -df/dx (forces, flexible bodies' elastic,
/// centrifugal and geometric terms, minus the multipliers' second derivatives),
/// G = -df/dv (dampers, gyroscopic and Coriolis terms) and C the constraint Jacobian at
/// (q, v), the motions that keep C dx = 0 are dx = Z y with Z an orthonormal basis of
/// null(C), and
///   Z^T M Z y'' + Z^T G Z y' + Z^T K Z y = 0.
/// With v = 0 and no dampers this is the symmetric problem Z^T K Z y = omega^2 Z^T M Z y;
/// otherwise the eigenvalues s of the first-order form give f = |Im s| / 2 pi (the changes of
/// Z and of the multipliers along a steady motion are not linearised). Used to check that a
/// flexible body vibrates at its body file's frequencies inside the DAE and for the
/// Southwell stiffening of a spinning one.

#include <Eigen/Dense>
#include <vector>

#include "libemb/mbs/core/kinematics.h"

namespace emb::mbs {

class System;
class ConstraintWorkspace;

/// df/dx - sum_k lambda_k d(C_k^T)/dx (nv x nv) at (q, v) (v empty: zero) in
/// x = [delta p, delta pi, eta]: the force elements' analytic stiffness and the constraints'
/// second derivatives weighted by lambda; the columns of flexible bodies' coordinates are
/// central differences of f - C^T lambda (see GglDae::FlexibleColumns for why).
/// `vdot` (may be empty) gives the frame accelerations for flexible bodies' translational
/// geometric stiffness (dynamics.h).
Eigen::MatrixXd CalcTangentStiffness(const System& system, const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& v, const Eigen::VectorXd& lambda,
                                     double t, ConstraintWorkspace* workspace,
                                     const Eigen::VectorXd& vdot = {});

/// The linearised model on null(C) in v-space: M y'' + G y' + K y = 0 with dx = Z y
/// (see the file comment); M, K, G are nv x nv, Z is nv x num_free (orthonormal columns).
struct LinearizedModel {
  Eigen::MatrixXd M, K, G, Z;
};

/// M, K = -df/dx (CalcTangentStiffness), G = -df/dv and Z = null(C) at (q, v) (v empty:
/// zero) with multipliers `lambda` and accelerations `vdot` (may be empty). Cost O(nv^3).
LinearizedModel CalcLinearizedModel(const System& system, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& v, double t,
                                    const Eigen::VectorXd& lambda, ConstraintWorkspace* workspace,
                                    const Eigen::VectorXd& vdot = {});

/// True if a flexible body has massless (quasi-static) coordinates: M is then singular.
bool HasQuasiStaticCoordinates(const System& system);

struct LinearModes {
  /// Ascending. Symmetric case: negative for unstable directions (-|f|). First-order case:
  /// the damped frequencies |Im s| / 2 pi of the oscillatory pairs, and `decay` = -Re s.
  Eigen::VectorXd frequencies_hz;
  Eigen::VectorXd decay;   ///< [1/s], first-order case only
  Eigen::MatrixXd shapes;  ///< nv x k, in v-space (symmetric case only)
  int num_free{0};         ///< dimension of null(C)
};

/// Frequencies of the model linearised at (q, v) (v empty: zero) with multipliers `lambda`
/// (zero: unloaded) and accelerations `vdot` (may be empty; SolveAccelerations gives both for
/// a steady motion); `undamped` drops G (dampers, gyroscopic terms) for the undamped natural
/// frequencies and mode shapes. Cost O(nv^3). @throws NumericalError if Z^T M Z is not
/// positive definite or an eigen-solve fails.
LinearModes CalcLinearModes(const System& system, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v, double t, const Eigen::VectorXd& lambda,
                            ConstraintWorkspace* workspace, bool undamped = false,
                            const Eigen::VectorXd& vdot = {});

}  // namespace emb::mbs
