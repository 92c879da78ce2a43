#pragma once
/// @file
/// Complex modes of a model linearised about a steady motion (Campbell diagrams, issue 17).
///
/// CalcLinearizedModel gives M dv' + G dv + K dx = 0 in the perturbation coordinates of
/// ApplyDisplacement, whose rotations dpi_B are in each body's own (spinning) frame, with
/// dpi' = dv frozen. About a spin Omega_B that frozen kinematics is not exact
/// (d/dt dpi_B = domega_B - Omega_B x dpi_B), and the exact equations are time-varying in
/// body axes. In world-fixed rotation coordinates dtheta_W = R_WB dpi_B, domega_W =
/// R_WB domega_B the kinematics is exact (dtheta_W' = domega_W) and the rate of the
/// transformation adds Omega_W x domega_W to the angular acceleration; transformed back at
/// the instant (a constant similarity, eigenvalues unchanged) that is
///   M dv' + (G - M W) dv + K dx = 0,   W = blockdiag(Skew(omega_B)) on every moving
/// body's angular-velocity rows (zero on translations and modal rates).
/// For a rigid rotor, symmetric about its spin axis on supports symmetric about it, this is
/// the classical stationary-frame rotor model (Id theta'' +- Ip Omega theta' + k theta = 0):
/// forward and backward whirl split with speed. A flexible body's modal coordinates stay in
/// its floating frame (its bending is seen from the rotating body; torsion and axial motion
/// are the same in both frames).
///
/// The modes are the eigenvectors of the first-order form x' = A x, x = [y; y'],
/// A = [0 I; -Mz^-1 Kz  -Mz^-1 Gz] on null(C) (Mz = Z^T M Z ...), with Im s > 0.

#include <Eigen/Dense>

#include "libemb/mbs/dae/linearization.h"

namespace emb::mbs {

class System;
class ConstraintWorkspace;

/// The oscillatory modes of a linearised model, ascending in frequency.
struct RotatingModes {
  Eigen::VectorXd frequencies_hz;  ///< |Im s| / 2 pi [Hz]
  Eigen::VectorXd decay;           ///< -Re s [1/s]
  /// nv x k velocity phasors dv = Z s y (complex), normalised to phi^H M phi = 1.
  Eigen::MatrixXcd shapes;
  Eigen::MatrixXd mass;  ///< M (nv x nv) at the state, for mass-weighted MAC
  int num_free{0};       ///< dimension of null(C)
};

/// W of the file comment (nv x nv): Skew(omega_B) on each moving body's angular-velocity
/// rows and columns at velocity v.
Eigen::MatrixXd CalcFrameRotationRate(const System& system, const Eigen::VectorXd& q,
                                      const Eigen::VectorXd& v);

/// The modes with frequency <= fmax_hz (fmax_hz <= 0: all) of `model` (CalcLinearizedModel
/// at (q, v)) with the gyroscopic frame term -M W (`stationary_frame`; false keeps the
/// frozen body-frame kinematics of CalcLinearModes). Cost O(nv^3).
/// @throws InputError if the model has massless (quasi-static) coordinates;
/// NumericalError if Z^T M Z is not positive definite or the eigen-solve fails.
RotatingModes CalcRotatingModes(const System& system, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const LinearizedModel& model,
                                double fmax_hz, bool stationary_frame = true);

/// The modes with frequency <= fmax_hz of Mr y'' + Gr y' + Kr y = 0 in independent
/// coordinates y (n x n each, Mr symmetric positive definite), mapped to velocity phasors
/// phi = T s y (T: nv x n, v = T y') and normalised to phi^H M phi = 1 (M: nv x nv; `mass`
/// of the result). CalcRotatingModes is this with T = Z = null(C), Mr = Z^T M Z, ...
/// @throws NumericalError as CalcRotatingModes.
RotatingModes CalcReducedRotatingModes(const Eigen::MatrixXd& Mr, const Eigen::MatrixXd& Gr,
                                       const Eigen::MatrixXd& Kr, const Eigen::MatrixXd& T,
                                       const Eigen::MatrixXd& M, double fmax_hz);

}  // namespace emb::mbs
