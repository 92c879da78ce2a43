#pragma once
/// @file
/// Poses and velocities of bodies and markers evaluated from the generalised coordinates
/// and velocities (see notation.h). The body list includes the ground at index 0.

#include <Eigen/Dense>
#include <vector>

namespace emb::mbs {

class System;

/// Pose and velocity of one body B.
struct BodyKinematics {
  Eigen::Vector3d p_WB{Eigen::Vector3d::Zero()};
  Eigen::Matrix3d R_WB{Eigen::Matrix3d::Identity()};
  Eigen::Vector3d v_WB{Eigen::Vector3d::Zero()};
  Eigen::Vector3d omega_W{Eigen::Vector3d::Zero()};
  Eigen::Vector3d omega_B{Eigen::Vector3d::Zero()};
  Eigen::VectorXd eta, eta_dot;  ///< modal coordinates and rates (empty on rigid bodies)
};

/// Pose and velocity of one marker M on body B, plus what its Jacobian rows need.
///
/// On a flexible body the marker frame moves with the deformation (system.h Marker):
///   s_B = p_BM + Phi_M eta,  R_BM = Exp(psi) R_BM0,  psi = Psi_M eta.
/// Everything downstream (constraint kernels, force elements) then treats the marker as
/// fixed on a *virtual rigid body* with the body's origin and orientation and the marker
/// frame's angular velocity omega_W (= the body's plus R J_l(psi) Psi_M eta'). A virtual
/// displacement or velocity [dp, dpi] of that virtual body is [dp_WB, dpi_B] + E d(eta) with
///   E = [R Phi_M + [s_W x] R J_l Psi_M;  J_l Psi_M]   (6 x ne),
/// so a Jacobian row d of a kernel has the eta columns d E, and a wrench's generalised force
/// f6 = [F; n_B] on the virtual body adds E^T f6 to the modal rows. `extra` completes the
/// velocity-product (Cdot v) terms: a kernel's g'' = d (vdot_B + E eta'') + d extra +
/// its rigid quadratic term evaluated with these kinematics (the J_l-rate term is dropped; it
/// is O(|psi| |psi'|^2)).
struct MarkerKinematics {
  int body{0};           ///< body index (0 = ground)
  Eigen::Vector3d s_B;   ///< p_BM in B [m]
  Eigen::Matrix3d R_BM;  ///< marker axes in B
  Eigen::Vector3d s_W;   ///< R_WB s_B [m]
  Eigen::Vector3d p_WM;  ///< [m]
  Eigen::Matrix3d R_WM;  ///< marker axes in W
  Eigen::Matrix3d R_WB;
  Eigen::Vector3d v_WM;     ///< [m/s]
  Eigen::Vector3d omega_W;  ///< of the marker frame (of the body if rigid) [rad/s]
  Eigen::MatrixXd E;        ///< 6 x ne on a flexible body, empty otherwise
  Eigen::Matrix<double, 6, 1> extra{Eigen::Matrix<double, 6, 1>::Zero()};
  bool flexible() const { return E.size() > 0; }
};

/// The velocity [v', omega'_B] of the virtual rigid body that carries marker M (the body's
/// [v_WB, omega_B] on a rigid body): the kernel Jacobian rows apply to it.
Eigen::Matrix<double, 6, 1> VirtualBodyVelocity(const MarkerKinematics& M);

/// All bodies at (q, v). `v` may be empty (zero velocities).
/// @pre q.size() == 7 * num_moving_bodies; v empty or 6 * num_moving_bodies.
std::vector<BodyKinematics> CalcBodyKinematics(const System& system, const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& v);

/// Marker `marker` from the body kinematics.
MarkerKinematics CalcMarkerKinematics(const System& system,
                                      const std::vector<BodyKinematics>& bodies, int marker);

}  // namespace emb::mbs
