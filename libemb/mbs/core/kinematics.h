#pragma once
/// @file
/// Poses and velocities of bodies and markers evaluated from the generalised coordinates
/// and velocities (see notation.h). The body list includes the ground at index 0.

#include <Eigen/Dense>
#include <vector>

#include "libemb/common/scratch_matrices.h"

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
/// Everything downstream (constraint kernels, force elements) sees a marker as fixed on a
/// *virtual rigid body* (origin p_WB = p_WM - s_W, axes R_WB) and differentiates with respect
/// to that body's virtual displacement [dp, dpi] (notation.h). On a rigid body the virtual
/// body is the body itself. On a flexible body the marker frame moves with the deformation
/// (system.h Marker):
///   s = p_BM + Phi eta,  R_BM(eta) = Exp(psi) R_BM0,  psi = Psi eta   (in the body frame B),
/// and the virtual body is the marker frame itself (s_B = 0, R_BM = I, s_W = 0, R_WB = R_WM,
/// omega_W the marker frame's angular velocity). Its virtual displacement and velocity
/// [dp_WM (W), dpi_M (M)] follow from the body's coordinates x_b = [dp_WB, dpi_B, d eta] by
/// the marker map
///   map = [ I   -R [s x]   R Phi
///           0    R_BM^T    R_BM^T J_l(psi) Psi ]      (6 x (6 + ne), R = R_WB of the body),
/// so a kernel's Jacobian row d (w.r.t. the marker frame) is d map on the body's columns, and a
/// generalised force g = [F (W); moment about the marker in M] becomes map^T g. The map
/// depends on the state; its derivatives close the chain rule exactly:
///   map_rate = d(map V)/dx_b at fixed V (6 x (6+ne), V = [v_WB, omega_B, eta'] of the body)
///     = [0  -R [u x]  R [omega_B x] Phi;  0  0  R_BM^T ([a x] J_l Psi + dJ_l(psi)[Psi eta'] Psi)],
///       u = omega_B x s + Phi eta',  a = omega_B + J_l Psi eta';
///   Curvature(g) = d(map^T g)/dx_b at fixed g ((6+ne)^2, CalcMarkerCurvature);
/// and extra = map_rate V is the velocity-product term of the marker frame's acceleration:
/// a kernel's g'' = d (map Vdot + extra) + its quadratic term in the marker frame.
struct Marker;
struct MarkerKinematics {
  int body{0};           ///< body index (0 = ground)
  Eigen::Vector3d s_B;   ///< marker origin from the virtual body origin, in its axes [m]
  Eigen::Matrix3d R_BM;  ///< marker axes in the virtual body's axes
  Eigen::Vector3d s_W;   ///< R_WB s_B [m]
  Eigen::Vector3d p_WM;  ///< [m]
  Eigen::Matrix3d R_WM;  ///< marker axes in W
  Eigen::Matrix3d R_WB;  ///< axes of the virtual body (the body if rigid, the marker if not)
  Eigen::Vector3d v_WM;     ///< [m/s]
  Eigen::Vector3d omega_W;  ///< of the marker frame (of the body if rigid) [rad/s]
  /// Flexible bodies only (empty otherwise): the marker map and its rate (see above).
  Eigen::MatrixXd map, map_rate;
  Eigen::Matrix<double, 6, 1> extra{Eigen::Matrix<double, 6, 1>::Zero()};
  /// Flexible bodies: what Curvature needs.
  const Marker* marker{nullptr};
  Eigen::Matrix3d R_body{Eigen::Matrix3d::Identity()};  ///< R_WB of the flexible body
  Eigen::Vector3d s_body{Eigen::Vector3d::Zero()};      ///< s = p_BM + Phi eta, in its B
  Eigen::Matrix3d R_body_marker{Eigen::Matrix3d::Identity()};  ///< R_BM(eta)
  Eigen::Vector3d psi{Eigen::Vector3d::Zero()};
  Eigen::Matrix3d Jl{Eigen::Matrix3d::Identity()};  ///< J_l(psi)
  bool flexible() const { return map.size() > 0; }
};

/// d(map^T g)/dx_b at fixed g = [F (W); m (M axes)] for a marker on a flexible body
/// ((6 + ne)^2, rows and columns [dp_WB, dpi_B, d eta]): with f_B = R^T F, n = R_BM m,
///   rows dpi:  [s x][f_B x] (cols dpi),  -[f_B x] Phi - [n x] J_l Psi (cols eta)
///   rows eta:  Phi^T [f_B x] (cols dpi),  Psi^T (dJ_l^T(psi)[n] - J_l^T [n x] J_l) Psi (cols eta).
/// The second-derivative term of the chain rule through the marker map (the first is
/// map^T (dg/dx_M) map). @pre M.flexible(). Cost O(ne^2).
Eigen::MatrixXd CalcMarkerCurvature(const MarkerKinematics& M,
                                    const Eigen::Matrix<double, 6, 1>& g);
/// Adds CalcMarkerCurvature(M, g) to K ((6+ne)^2), its temporaries in `scratch` (buffers 4
/// and up): no allocation once the sizes have been seen.
void AddMarkerCurvature(const MarkerKinematics& M, const Eigen::Matrix<double, 6, 1>& g,
                        Eigen::Ref<Eigen::MatrixXd> K, ScratchMatrices* scratch);

/// The velocity [v', omega'_B] of the virtual rigid body that carries marker M (the body's
/// [v_WB, omega_B] on a rigid body): the kernel Jacobian rows apply to it.
Eigen::Matrix<double, 6, 1> VirtualBodyVelocity(const MarkerKinematics& M);

/// All bodies at (q, v). `v` may be empty (zero velocities).
/// @pre q.size() == 7 * num_moving_bodies; v empty or 6 * num_moving_bodies.
std::vector<BodyKinematics> CalcBodyKinematics(const System& system, const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& v);
/// The same into `bodies`, reusing its storage (no allocation once sized).
void CalcBodyKinematics(const System& system, const Eigen::Ref<const Eigen::VectorXd>& q,
                        const Eigen::Ref<const Eigen::VectorXd>& v,
                        std::vector<BodyKinematics>* bodies);

/// Marker `marker` from the body kinematics.
MarkerKinematics CalcMarkerKinematics(const System& system,
                                      const std::vector<BodyKinematics>& bodies, int marker);
/// The same into `out`, reusing its storage (its maps are not reallocated).
void CalcMarkerKinematics(const System& system, const std::vector<BodyKinematics>& bodies,
                          int marker, MarkerKinematics* out);
/// Every marker of `system` (index = marker index) into `markers`, reusing its storage: the
/// kinematics that constraints, force elements and sensors read at one state, computed once.
void CalcAllMarkerKinematics(const System& system, const std::vector<BodyKinematics>& bodies,
                             std::vector<MarkerKinematics>* markers);

}  // namespace emb::mbs
