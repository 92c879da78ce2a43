#pragma once
/// @file
/// Torsional vibration damper (TVD) on a crank nose (issue 17): an inertia ring on a rubber
/// spring, or a viscous (Houdaille) ring with no spring.
///
/// Model: a rigid ring body (mass m_r [kg], polar inertia J_r [kg m^2] about the hub axis,
/// diametral J_r / 2) centred on the hub marker, held on the hub by a revolute joint about the
/// hub marker's z axis, and loaded by a rotational spring-damper on the relative angle
/// theta = theta_ring - theta_hub (forces/spring_damper.h):
///   T_on_ring = -k theta - c theta',  k [N m/rad], c [N m s/rad]
/// (Kelvin-Voigt rubber: stiffness and damping constant in frequency; k = 0 is the viscous
/// ring). The ring starts spinning with the hub (its body's initial angular velocity).
/// Frequency-dependent rubber (zener_rubber.h): Maxwell arms in parallel with k and c, so
///   k*(w) = k + i w c + sum_j k_j i w tau_j / (1 + i w tau_j)
/// (k = static_stiffness, one arm and c = 0: the Zener / standard linear solid), each arm
/// realised with a light junction ring "<name>_junction<j>" (1-based) of polar inertia eps_j on
/// its own revolute joint "<name>_junction<j>_bearing" about the hub axis, the spring
/// "<name>_arm<j>_spring" (k_j, hub -> junction) and the dashpot "<name>_arm<j>_dashpot"
/// (c_j = k_j tau_j, junction -> ring); eps_j from CalcJunctionInertia so that k*(w) of the
/// model is within junction_error of the ideal up to band_hz (derivation in zener_rubber.h).
/// Its mass is ring_mass eps_j / J_r (the ring's radius of gyration).
///
/// Typical values, a 1.6-2.0 l inline-4 (the inline-4 scene's crank, first installed torsion
/// ~ 400-600 Hz): ring J_r 2e-3 .. 1e-2 kg m^2 (mass 1-3 kg), mass ratio mu = J_r / J_modal
/// 0.05 .. 0.3, rubber k tuned to f_n / (1 + mu): ~ 1e4 .. 1e5 N m/rad, damping ratio
/// 0.05 .. 0.15 (natural rubber ~ 0.05, damped elastomers ~ 0.1). TuneDenHartog gives k, c.

#include <string>
#include <vector>

#include "libemb/engine/zener_rubber.h"
#include "libemb/mbs/core/system.h"

namespace emb::engine {

struct TorsionalDamperSpec {
  std::string name;        ///< the spring-damper's name; the ring is "<name>_ring"
  std::string hub_marker;  ///< marker on the crank nose, z = crank axis
  double ring_mass{0.0};     ///< [kg] > 0
  double ring_inertia{0.0};  ///< polar, about the axis [kg m^2] > 0
  double stiffness{0.0};     ///< [N m/rad] >= 0
  double damping{0.0};       ///< [N m s/rad] >= 0
  std::vector<MaxwellArm> arms;  ///< Maxwell arms in parallel (frequency-dependent rubber)
  /// Highest frequency of interest [Hz]: the arms' junction rings are chosen so that k*(w)
  /// is within junction_error of the ideal rubber up to here. 5000 Hz is twice `emb
  /// campbell`'s default band and far above the engine orders' content.
  double band_hz{5000.0};
  double junction_error{1e-3};  ///< bound on |k*_model / k*_ideal - 1| up to band_hz, (0, 1)
};

/// What AddTorsionalDamper added.
struct TorsionalDamperParts {
  int ring_body{-1};
  int ring_marker{-1};
  std::vector<int> junction_bodies;        ///< one per arm
  std::vector<double> junction_inertia;    ///< eps_j [kg m^2], one per arm
};

/// Adds the ring body "<name>_ring" (at the hub marker's initial pose, spinning with the hub's
/// body), its marker "<name>_ring_axis", the revolute joint "<name>_bearing", the
/// spring-damper "<name>" (when k or c > 0) and per Maxwell arm its junction ring, joint and
/// two elements (file comment) to an unfinalized system.
/// @throws InputError naming the damper for a negative or zero ring mass or inertia, negative
/// stiffness or damping, k, c zero and no arm, an arm's stiffness or relaxation time not > 0
/// (naming the arm), band_hz not > 0, junction_error outside (0, 1), or an unknown hub marker
/// (did-you-mean).
TorsionalDamperParts AddTorsionalDamper(mbs::System* system, const TorsionalDamperSpec& spec);

/// Den Hartog's optimum absorber on a primary mode of frequency f_n [Hz] and modal inertia
/// J_n [kg m^2] at the damper (J_n = 1 / theta_hub^2 for a mass-normalised mode), mu = J_r / J_n:
///   f_a = f_n / (1 + mu),   zeta = c / (2 J_r omega_n) = sqrt(3 mu / (8 (1 + mu)^3)),
///   k = J_r (2 pi f_a)^2,   c = 2 zeta J_r (2 pi f_n),
/// which puts the two fixed points of the primary's response at equal height
/// |theta / theta_static| = sqrt(1 + 2 / mu) and makes them (nearly) the maxima.
struct DenHartogTuning {
  double mass_ratio{0.0};    ///< mu
  double absorber_hz{0.0};   ///< f_a
  double damping_ratio{0.0}; ///< zeta
  double stiffness{0.0};     ///< k [N m/rad]
  double damping{0.0};       ///< c [N m s/rad]
  double fixed_point_amplification{0.0};  ///< sqrt(1 + 2 / mu)
};
/// @throws InputError unless f_n, J_n, J_r > 0.
DenHartogTuning TuneDenHartog(double primary_hz, double modal_inertia, double ring_inertia);

}  // namespace emb::engine
