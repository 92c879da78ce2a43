#pragma once
/// @file
/// Motion of a marker I relative to a marker J, in J's axes, and the wrench pair such an
/// element applies: the common preamble and ending of the two-marker force elements that
/// measure I in J (the bushing, the journal bearing).
///
/// With d = p_WI − p_WJ (W) and R_JW = R_WJᵀ:
///   x  = R_JW d                                  position of I in J's axes [m]
///   x' = R_JW y,  y = v_WI − v_WJ − ω_J × d     its rate seen from J [m/s]
///   w  = R_JW (ω_I − ω_J)                        relative angular velocity in J [rad/s]
/// (the time derivative of R_JW a for a world vector a is R_JW (a' − ω_J × a)).
/// Derivatives in the local slots of force_jacobian.h (I in slot 0, J in slot 1; φ_J the
/// virtual rotation of J's body in W), using d(R_JW a) = R_JW (da + [a×] dφ_J):
///   dx/dX  = R_JW (dd + [d×] dφ_J),                     dd = dp_WI − dp_WJ
///   dx'/dX = R_JW (dy + [y×] dφ_J),   dy = dv_WI − dv_WJ + [d×] dω_J − [ω_J×] dd
///   dx'/dV = R_JW (dv_WI − dv_WJ + [d×] dω_J)
///   dw/dX  = R_JW (dω_I − dω_J + [(ω_I − ω_J)×] dφ_J),  dw/dV = R_JW (dω_I − dω_J).

#include <Eigen/Dense>

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/state_layout.h"
#include "libemb/mbs/forces/force_jacobian.h"

namespace emb::mbs {

/// Markers I and J of a two-marker element at the state of a force context: the context's
/// shared kinematics, or evaluated into the pair's own storage. Not copyable (I and J may
/// refer into it).
class MarkerPair {
 public:
  MarkerPair(const ForceContext& ctx, int marker_i, int marker_j)
      : I(ctx.Marker(marker_i, &own_[0])), J(ctx.Marker(marker_j, &own_[1])) {}
  MarkerPair(const MarkerPair&) = delete;
  MarkerPair& operator=(const MarkerPair&) = delete;

 private:
  MarkerKinematics own_[2];

 public:
  const MarkerKinematics& I;
  const MarkerKinematics& J;
};

/// Their derivatives in the local slots 0 (I) and 1 (J) of force_jacobian.h.
struct MarkerPairDerivatives {
  MarkerDerivatives dI, dJ;
};
MarkerPairDerivatives DifferentiateMarkerPair(const MarkerPair& markers);

struct RelativeMotion {
  Eigen::Vector3d d_W;          ///< p_WI − p_WJ [m]
  Eigen::Vector3d y_W;          ///< v_WI − v_WJ − ω_J × d [m/s]
  Eigen::Matrix3d R_JW;         ///< J's axes from W
  Eigen::Vector3d x, x_dot, w;  ///< in J's axes (file comment)
};
RelativeMotion CalcRelativeMotion(const MarkerKinematics& I, const MarkerKinematics& J);
inline RelativeMotion CalcRelativeMotion(const MarkerPair& m) {
  return CalcRelativeMotion(m.I, m.J);
}

/// d(x, x', w)/d(X, V) in the two local slots (3 × 12 each).
struct RelativeMotionDerivatives {
  SlotRows<3> x_x, x_dot_x, x_dot_v, w_x, w_v;
};
RelativeMotionDerivatives DifferentiateRelativeMotion(const RelativeMotion& rel,
                                                      const MarkerKinematics& I,
                                                      const MarkerKinematics& J,
                                                      const MarkerDerivatives& dI,
                                                      const MarkerDerivatives& dJ);

/// Adds F_W, T_W on I's body and −F_W, −T_W on J's body, both at p_WI, to f.
void AddWrenchPair(const StateLayout& layout, const MarkerKinematics& I, const MarkerKinematics& J,
                   const Eigen::Vector3d& F_W, const Eigen::Vector3d& T_W,
                   Eigen::Ref<Eigen::VectorXd> f);

/// The derivatives of AddWrenchPair's generalised forces given dF, dT (3 × 12) with respect
/// to the local X and V, scattered to `sink`: the arm of I's load is s_WI on I's body and
/// p_WI − p_WJbody on J's (WrenchStiffness, WrenchDamping).
void ScatterWrenchPairJacobian(const MarkerKinematics& I, const MarkerKinematics& J,
                               const MarkerDerivatives& dI, const MarkerDerivatives& dJ,
                               const Eigen::Vector3d& F, const Eigen::Vector3d& T,
                               const SlotRows<3>& dF_x, const SlotRows<3>& dT_x,
                               const SlotRows<3>& dF_v, const SlotRows<3>& dT_v,
                               ForceJacobianSink* sink);

}  // namespace emb::mbs
