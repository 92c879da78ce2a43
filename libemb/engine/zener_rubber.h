#pragma once
/// @file
/// Frequency-dependent rubber for the torsional vibration damper (issue 17): a standard
/// linear solid / generalised Maxwell model and its realisation in a multibody model with
/// light junction rings.
///
/// Rubber law (relative angle theta = theta_ring - theta_hub, torque on the ring -T):
///   k*(w) = k_inf + i w c + sum_j k_j i w tau_j / (1 + i w tau_j),   tau_j = c_j / k_j,
/// a static spring k_inf [N m/rad] and a dashpot c [N m s/rad] in parallel (Kelvin-Voigt)
/// with Maxwell arms, each a spring k_j [N m/rad] in series with a dashpot c_j [N m s/rad].
/// Storage stiffness Re k*, loss stiffness Im k*, loss factor eta = Im k* / Re k*.
/// One arm (c = 0) is the Zener / standard linear solid: with x = w tau, r = k_1 / k_inf,
///   eta(x) = r x / (1 + (1 + r) x^2),
/// largest at x* = 1 / sqrt(1 + r), where eta_max = r / (2 sqrt(1 + r)) and
///   Re k*(x*) = k_inf 2 (1 + r) / (2 + r),   |k*(x*)| = Re k*(x*) sqrt(1 + eta_max^2).
/// The dynamic-to-static stiffness ratio |k*| / k_inf rises from 1 (w -> 0) to 1 + r.
///
/// Typical crank-nose TVD rubbers (EPDM, NR/BR blends, HNBR): loss factor 0.1 .. 0.25 at the
/// tuning frequency (a few hundred Hz), dynamic-to-static stiffness ratio 1.2 .. 1.6. A single
/// Zener arm has a narrow loss peak (about a decade wide); a real elastomer's loss factor is
/// flatter, which several arms with spread relaxation times reproduce.
///
/// Junction rings. The multibody force elements have no internal state, so the junction of
/// arm j (between its spring and its dashpot) is a rigid ring of polar inertia eps_j on its own
/// revolute joint about the hub axis: spring k_j hub -> junction, dashpot c_j junction -> ring.
/// With the hub angle h, ring angle g and junction angle u, harmonic e^{i w t}:
///   (k_j + i w c_j - eps_j w^2) u = k_j h + i w c_j g,
/// and the arm's dynamic stiffness matrix on (h, g) (torques = -D (h, g)) is, with
/// Delta = k_j + i w c_j - eps_j w^2,
///   D_hh = k_j (i w c_j - eps_j w^2) / Delta,   D_gg = i w c_j (k_j - eps_j w^2) / Delta,
///   D_hg = D_gh = -i w c_j k_j / Delta,
/// while the ideal Maxwell arm (eps_j = 0) has D_hh = D_gg = -D_hg = D0 = i w c_j k_j /
/// (k_j + i w c_j). With a = eps_j w^2 / k_j, b = eps_j w / c_j and x = w tau_j (so a = b x),
/// the exact relative errors are
///   D_hg / (-D0) - 1 = a / (1 + i x - a),
///   D_gg / D0 - 1    = -i a x / (1 + i x - a),
///   D_hh / D0 - 1    = i b / (1 + i x - a),
/// all three bounded by  e_j(w) = max(a, b) / (1 - a)  (|1 + i x - a| >= 1 - a, a x /
/// |1 + i x - a| <= a), which grows with w. Choosing
///   eps_j = delta' min(k_j / w_max^2, c_j / w_max),   delta' = delta / (1 + delta),
/// gives max(a, b) <= delta' and e_j <= delta'/(1 - delta') = delta for every w <= w_max =
/// 2 pi f_max: the junction's undamped frequency sqrt(k_j / eps_j) >= w_max / sqrt(delta')
/// and its fast pole c_j / eps_j >= w_max / delta' lie far above the band. The whole rubber's
/// k*(w) (each arm's ring-side D_gg) is then within sqrt(2) delta of the ideal: every term of
/// k* has non-negative real and imaginary parts, so sum_j |D0_j| <= Re k* + Im k* <=
/// sqrt(2) |k*|. AddTorsionalDamper uses per-arm delta = junction_error / sqrt(2), so
/// junction_error bounds the error of the whole k*(w) (and every arm's matrix entry) up to
/// f_max. The junction's mass rides on the hub (D_hh ~ -eps_j w^2 at low frequency): it is
/// part of that bound.

#include <complex>
#include <vector>

namespace emb::engine {

/// A Maxwell arm: spring k [N m/rad] in series with a dashpot c = k tau [N m s/rad].
struct MaxwellArm {
  double stiffness{0.0};        ///< k_j [N m/rad] > 0
  double relaxation_time{0.0};  ///< tau_j [s] > 0
};

/// k_inf + sum of Maxwell arms (+ the damper's parallel dashpot, kept apart in the spec).
struct ZenerRubber {
  double static_stiffness{0.0};  ///< k_inf [N m/rad] >= 0
  std::vector<MaxwellArm> arms;
};

/// k*(w) = k_inf + i w c + sum_j k_j i w tau_j / (1 + i w tau_j) [N m/rad] at w [rad/s];
/// `damping` is a parallel dashpot c [N m s/rad].
std::complex<double> CalcComplexStiffness(const ZenerRubber& rubber, double omega,
                                          double damping = 0.0);

/// Im k* / Re k* at w [rad/s].
double CalcLossFactor(const ZenerRubber& rubber, double omega, double damping = 0.0);

/// The one-arm Zener whose loss factor peaks at f [Hz] with height eta and whose |k*(2 pi f)|
/// is `dynamic_stiffness` [N m/rad] (derivation in the file comment):
///   r = k_1 / k_inf = 2 eta (eta + sqrt(1 + eta^2))   (solves eta = r / (2 sqrt(1 + r))),
///   k_inf = |k*| (2 + r) / (2 (1 + r) sqrt(1 + eta^2)),   k_1 = r k_inf,
///   tau = 1 / (2 pi f sqrt(1 + r)).
/// @throws InputError unless dynamic_stiffness > 0, f > 0 and 0 < eta <= kMaxZenerLossFactor.
ZenerRubber FitZenerAtLossPeak(double dynamic_stiffness, double loss_factor, double hz);

/// One Zener arm carries loss factors up to this (r = 4.83, |k*|/k_inf up to 5.8 at the
/// peak); elastomers rarely exceed it and a larger one asks for a different model.
inline constexpr double kMaxZenerLossFactor = 1.0;

/// The junction inertia eps = delta/(1+delta) min(k / w_max^2, c / w_max) [kg m^2] that keeps
/// the arm's relative error e(w) <= delta for w <= w_max = 2 pi band_hz (file comment).
/// @throws InputError unless the arm's k, tau > 0 and band_hz, delta > 0, delta < 1.
double CalcJunctionInertia(const MaxwellArm& arm, double band_hz, double delta);

/// The exact relative errors of the arm realised with junction inertia eps [kg m^2] at
/// w [rad/s] against the ideal Maxwell arm (file comment): {hub-ring coupling, ring side,
/// hub side}.
struct JunctionArmError {
  std::complex<double> coupling, ring, hub;
  double Max() const;  ///< the largest modulus
};
JunctionArmError CalcJunctionArmError(const MaxwellArm& arm, double junction_inertia,
                                      double omega);

/// The bound max(a, b) / (1 - a) of the file comment at w [rad/s] (infinite for a >= 1).
double CalcJunctionArmErrorBound(const MaxwellArm& arm, double junction_inertia, double omega);

}  // namespace emb::engine
