#pragma once
/// @file
/// A short (Ocvirk) hydrodynamic journal bearing with half-Sommerfeld (pi-film) cavitation,
/// between a journal marker I and a bearing marker J (bearing axis z_J).
///
/// Kinematics, in J's axes (the bearing plane is x_J y_J):
///   e  = P R_JW (p_WI - p_WJ)                      eccentricity of the journal centre [m]
///   e' = P R_JW (v_WI - v_WJ - omega_J x d)        its rate, seen from the bearing [m/s]
///   w  = z_J . (omega_I - omega_J)                 journal speed relative to the shell
/// (P keeps the x, y components). Short-bearing Reynolds equation (the circumferential
/// pressure flow neglected, L/D <= 1), film h(phi) = c - n(phi) . e, n = (cos phi, sin phi):
///   d/dz (h^3 dp/dz) = 6 mu w dh/dphi + 12 mu dh/dt,   p(+-L/2) = 0,
/// with the velocity relative to half-speed whirl
///   u = e' - (w / 2) z x e         (the only velocity the film sees: dh/dt + (w/2) dh/dphi
///                                   = -n . u),
/// the pressure is p(phi, z) = 6 mu (n . u) (L^2/4 - z^2) / h^3 and its axial integral
///   P(phi) = mu L^3 (n . u) / h^3,
/// positive (film pressure) on the half circle n . u > 0 and set to zero on the other half
/// (half-Sommerfeld / pi-film: with this solution the positive region is exactly a half
/// circle centred on the direction of u; its start angle follows the squeeze and whirl).
/// Film force on the journal (J's axes, in the bearing plane)
///   F = -mu R L^3 int_{n.u > 0} (n . u) n / h^3 dphi,
/// integrated by 64-point Gauss-Legendre over the half circle (nodes fixed relative to the
/// direction of u). Relative error (checked against the closed forms) in the worst case,
/// the minimum film mid-interval (pure squeeze): 2e-9 at eps = 0.95, 5e-7 at 0.97, 1e-3 at
/// 0.99, 0.4 at 0.999; with the minimum film at an end of the interval (steady rotation):
/// < 1e-13 up to 0.99, 3e-7 at 0.999. The force stays smooth and its Jacobian exact for
/// the sum; beyond eps ~0.98 the magnitude is approximate. The integrand vanishes at both ends, so the derivatives of the integral
/// are the integral of the derivatives; the analytic Jacobian is the exact derivative of the
/// quadrature sum. Torque on the journal about z_J:
///   T = -(e x F) . z / 2  -  2 pi mu R^3 L w / (c sqrt(1 - eps^2)),   eps = |e| / c,
/// the pressure-induced shear term (which makes F . e' + T w = F . u <= 0) and the Couette
/// (Petroff) drag over the full circumference. The bearing gets -F at p_WI and -T. The
/// element dissipates -(F . e' + T w) = -F . u + 2 pi mu R^3 L w^2 / (c sqrt(1 - eps^2)) >= 0.
/// Steady load (e' = 0): |F_r| = mu w R L^3 eps^2 / (c^2 (1-eps^2)^2) towards the centre,
/// F_t = pi mu w R L^3 eps / (4 c^2 (1-eps^2)^{3/2}) (Ocvirk).
///
/// Only the bearing plane is modelled: the axial position and the tilt of the journal must
/// be held by the joints (e.g. an in-plane + parallel pair, or a planar joint for a single
/// bearing) or by a separate bushing. Tilt is not checked: the film uses the journal
/// centre's position and z_J.
///
/// Parameters are checked at construction: R, L, c, mu > 0 and finite, c < R, and
/// L / (2R) <= 1 (the short-bearing assumption; longer bearings are refused rather than
/// silently over-predicted). When the journal reaches the shell (eps >= 1) the element
/// throws NumericalError naming itself, eps and the time; a dynamic run then stops with
/// that message (no saturation: a bearing that runs dry is outside the model). Inside a run
/// the element reports it through its context (ForceContext::Fail): the integrator then cuts
/// the step, and a run that cannot get past it ends with the message in its status.
#include <Eigen/Dense>
#include <string>

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/forces/relative_motion.h"

namespace emb::mbs {

struct JournalBearingParameters {
  double radius{0.0};     ///< R, journal radius [m]
  double length{0.0};     ///< L, bearing length [m]
  double clearance{0.0};  ///< c, radial clearance [m]
  double viscosity{0.0};  ///< mu, dynamic viscosity [Pa s]
};

class JournalBearing final : public ForceElement {
 public:
  /// @throws InputError for the parameter checks in the file comment.
  JournalBearing(std::string name, int marker_i, int marker_j, const JournalBearingParameters& p);

  /// The film load in J's axes for eccentricity e, rate e' and relative speed w (no
  /// kinematics): force F (2), torque T about z_J. @throws NumericalError if |e| >= c.
  struct FilmLoad {
    Eigen::Vector2d force;
    double torque{0.0};
  };
  FilmLoad CalcFilmLoad(const Eigen::Vector2d& e, const Eigen::Vector2d& e_dot, double w,
                        double t = 0.0) const;
  const JournalBearingParameters& parameters() const { return p_; }

 protected:
  void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const override;
  void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const override;
  double DoCalcDissipatedPower(const ForceContext& ctx) const override;
  std::vector<int> DoMarkers() const override { return {i_, j_}; }
  bool DoCalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const override;
  bool DoReportsLoad() const override { return true; }
  /// Outputs (channels "<name>.<output>"), as the film bearing's of the same names:
  /// h_min = c - |e| [m], eccentricity_ratio = |e| / c [-], friction_power [W] (the
  /// dissipated power).
  std::vector<ElementOutput> DoOutputs() const override;
  bool DoCalcOutputs(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> out) const override;

 private:
  /// The film load of the relative motion of I in J (relative_motion.h): e = x.head<2>,
  /// e' = x'.head<2>, w = w.z.
  FilmLoad CalcFilmLoad(const RelativeMotion& rel, double t) const;
  /// F(e, u) and, if the pointers are set, dF/de and dF/du (2x2 each).
  Eigen::Vector2d FilmForce(const Eigen::Vector2d& e, const Eigen::Vector2d& u,
                            Eigen::Matrix2d* dF_de, Eigen::Matrix2d* dF_du) const;
  void CheckEccentricity(const Eigen::Vector2d& e, double t) const;
  /// Eccentricity ratio below 1.
  bool Inside(const Eigen::Vector2d& e) const { return e.norm() < p_.clearance; }
  /// The same at the context's state; if not, reported through the context (Fail).
  bool Inside(const ForceContext& ctx, const RelativeMotion& rel) const;
  std::string TouchMessage(const Eigen::Vector2d& e, double t) const;

  int i_, j_;
  JournalBearingParameters p_;
};

}  // namespace emb::mbs
