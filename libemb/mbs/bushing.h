#pragma once
/// @file
/// A 6x6 linear bushing between markers I and J (seed eq. 1.26 uses such a matrix for an
/// Eulerian beam; here it stands in for journal bearings and mounts).

#include <Eigen/Dense>

#include "libemb/mbs/force_element.h"

namespace emb::mbs {

/// Relative displacement of I from J in J's axes, x = [R_WJ^T (p_WI - p_WJ); theta] with
/// theta the rotation vector of R_JI = R_WJ^T R_WI (small rotations), and its rate
/// xdot = [R_WJ^T (v_WI - v_WJ - omega_J x d); R_WJ^T (omega_I - omega_J)].
/// The load on I, in J's axes: [F; T] = -K x - D xdot (force at the origin of I, moment);
/// J gets the equal and opposite load at the same point.
/// Energy x^T K x / 2 (exact for the translational part, small-angle for rotations).
/// K [N/m | N/rad ...] and D are 6x6, expressed in J; K must be symmetric PSD.
class Bushing final : public ForceElement {
 public:
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  /// @throws InputError if K is not symmetric positive semi-definite or D has negative
  /// eigenvalues of its symmetric part.
  Bushing(std::string name, int marker_i, int marker_j, const Matrix6d& stiffness,
          const Matrix6d& damping);

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  double DoCalcPotentialEnergy(const ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }

 private:
  void Calc(const ForceContext& ctx, Vector6d* x, Vector6d* xdot) const;
  int i_, j_;
  Matrix6d k_, d_;
};

}  // namespace emb::mbs
