#pragma once
/// @file
/// Translational and rotational spring-dampers between two markers I and J.

#include "libemb/mbs/force_element.h"

namespace emb::mbs {

/// Linear spring-damper along the line between the origins of markers I and J:
///   d = p_WI - p_WJ, L = |d|, u = d / L, L' = u . (v_WI - v_WJ),
///   tension F = k (L - L0) + c L',  force on I: -F u, on J: +F u,
///   energy k (L - L0)^2 / 2, dissipated power c L'^2.
/// k [N/m], c [N s/m], L0 [m]. Undefined at L = 0 (the force direction); it returns no force
/// there.
class TranslationalSpringDamper final : public ForceElement {
 public:
  TranslationalSpringDamper(std::string name, int marker_i, int marker_j, double stiffness,
                            double damping, double free_length);

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  double DoCalcPotentialEnergy(const ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }

 private:
  struct State {
    double length, rate;
    Eigen::Vector3d u;
  };
  State Calc(const ForceContext& ctx) const;
  int i_, j_;
  double k_, c_, l0_;
};

/// Torsional spring-damper about z_J acting on the relative rotation angle a of x_I about
/// z_J (the revolute joint angle, followed continuously across turns through a workspace
/// slot when the context has one, otherwise wrapped to (-pi, pi]):
///   T = -k (a - a0) - c a',  moment T z_J on I's body and -T z_J on J's body,
///   energy k (a - a0)^2 / 2.
/// k [N m/rad], c [N m s/rad]. Meant for markers whose z axes stay aligned (revolute joint).
class RotationalSpringDamper final : public ForceElement {
 public:
  RotationalSpringDamper(std::string name, int marker_i, int marker_j, double stiffness,
                         double damping, double free_angle);

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  double DoCalcPotentialEnergy(const ForceContext& ctx) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }
  int DoNumAngleSlots() const override { return 1; }

 private:
  void Calc(const ForceContext& ctx, double* angle, double* rate) const;
  int i_, j_;
  double k_, c_, a0_;
};

}  // namespace emb::mbs
