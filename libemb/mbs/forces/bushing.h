#pragma once
/// @file
/// A 6x6 linear bushing between markers I and J (seed eq. 1.26 uses such a matrix for an
/// Eulerian beam; here it stands in for journal bearings and mounts).

#include <Eigen/Dense>

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/forces/relative_motion.h"

namespace emb::mbs {

/// Relative displacement of I from J in J's axes, xi = [x; theta]:
///   x = R_JW d - x0, d = p_WI - p_WJ (x0: where I sits in J's axes when the bushing is
///       unloaded, the free offset; 0 by default, L e_x for a beam of length L),
///   theta = the rotation vector of R_JI = R_JW R_WI, from its quaternion (|theta| <= pi,
///           exact for large rotations, RotationVectorFromQuaternion),
/// and its rate xi' = [R_JW (d' - omega_J x d); J_l^{-1}(theta) R_JW (omega_I - omega_J)]
/// (theta' through the inverse left Jacobian of SO(3), rotation.h). The energy is
/// V = xi^T K xi / 2 and the dissipation function xi'^T D xi' / 2; the load is their
/// work-conjugate: with m = -(K xi + D xi') = [m_x; m_r] (J's axes),
///   force on I at p_WI:  F = R_WJ m_x,   couple on I: T = R_WJ J_l^{-T}(theta) m_r,
/// and J gets -F at the same point p_WI and -T. The J_l^{-T} factor makes the moment the
/// exact gradient of V under finite rotations (for K_rot = k I it is the plain -k theta);
/// the power of the load is -xi'^T (K xi + D xi'), so energy is conserved to the
/// integrator's tolerance for D = 0, whatever the rotation. Dissipated power xi'^T D xi'.
/// K [N/m, N/rad, coupling N and N m] and D [N s/m ...] are 6x6, expressed in J; K must be
/// symmetric PSD. Precondition: |theta| < pi (a bushing that turns half a revolution is
/// not a bushing; at pi the rotation vector flips).
class Bushing : public ForceElement {
 public:
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  /// @throws InputError if K is not symmetric positive semi-definite or D has negative
  /// eigenvalues of its symmetric part.
  Bushing(std::string name, int marker_i, int marker_j, const Matrix6d& stiffness,
          const Matrix6d& damping, const Eigen::Vector3d& free_offset = Eigen::Vector3d::Zero());

  /// K in J's axes.
  const Matrix6d& stiffness() const { return k_; }

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const override;
  double DoCalcPotentialEnergy(const ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }
  /// I: the force at p_WI, and a moment only with rotational (or coupling) stiffness or
  /// damping; J: both (the force acts at p_WI, off J's origin).
  unsigned DoMarkerLoads(int marker) const override;
  bool DoCalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const override;
  bool DoReportsLoad() const override { return true; }

 private:
  struct State {
    RelativeMotion rel;  ///< x, x', w of I in J
    Vector6d xi, xi_dot;
    Eigen::Matrix3d inv_jacobian;  ///< J_l^{-1}(theta)
  };
  State Calc(const MarkerKinematics& I, const MarkerKinematics& J) const;
  int i_, j_;
  Matrix6d k_, d_;
  Eigen::Vector3d x0_;
};

}  // namespace emb::mbs
