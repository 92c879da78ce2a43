#include "libemb/engine/torsional_damper.h"

#include <cmath>
#include <memory>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/mbs/forces/spring_damper.h"

namespace emb::engine {

namespace {

struct CoaxialRing {
  int body{-1}, marker{-1};
};

// A rigid ring (polar inertia J, diametral J / 2) at the hub marker's initial pose, spinning
// with the hub's body, on a revolute joint `joint` about the hub marker's z axis; its marker
// "<name>_axis" at its centre.
CoaxialRing AddCoaxialRing(mbs::System* sys, const std::string& name, const std::string& joint,
                           double mass, double J, int hub) {
  const mbs::Marker& m = sys->marker(hub);
  // The hub marker's initial pose and velocity from its body's initial data (undeformed).
  Eigen::Vector3d p_W = m.p_BM, v_W = Eigen::Vector3d::Zero(), omega_W = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_WM = m.R_BM;
  if (m.body > 0) {
    const mbs::RigidBody& b = sys->body(m.body);
    p_W = b.p_WB + b.R_WB * m.p_BM;
    R_WM = b.R_WB * m.R_BM;
    omega_W = b.omega_W;
    v_W = b.v_WB + b.omega_W.cross(b.R_WB * m.p_BM);
  }
  const std::string hub_name = m.name;
  mbs::RigidBody ring;
  ring.name = name;
  ring.mass = mass;
  ring.inertia_B = Eigen::Vector3d(0.5 * J, 0.5 * J, J).asDiagonal();
  ring.p_WB = p_W;
  ring.R_WB = R_WM;
  ring.v_WB = v_W;
  ring.omega_W = omega_W;
  CoaxialRing r;
  r.body = sys->AddBody(ring);
  r.marker = sys->AddMarker(name + "_axis", name, Eigen::Vector3d::Zero(),
                            Eigen::Matrix3d::Identity());
  sys->AddJoint(joint, mbs::JointType::kRevolute, name + "_axis", hub_name);
  return r;
}

}  // namespace

TorsionalDamperParts AddTorsionalDamper(mbs::System* sys, const TorsionalDamperSpec& s) {
  const std::string what = "torsional damper '" + s.name + "'";
  EMB_THROW_IF(!(s.ring_mass > 0.0) || !std::isfinite(s.ring_mass),
               what << " ring_mass: expected > 0 kg, got " << s.ring_mass);
  EMB_THROW_IF(!(s.ring_inertia > 0.0) || !std::isfinite(s.ring_inertia),
               what << " ring_inertia: expected > 0 kg m^2, got " << s.ring_inertia);
  EMB_THROW_IF(!(s.stiffness >= 0.0) || !std::isfinite(s.stiffness),
               what << " stiffness: expected >= 0 N m/rad, got " << s.stiffness);
  EMB_THROW_IF(!(s.damping >= 0.0) || !std::isfinite(s.damping),
               what << " damping: expected >= 0 N m s/rad, got " << s.damping);
  EMB_THROW_IF(s.stiffness == 0.0 && s.damping == 0.0 && s.arms.empty(),
               what << ": expected a stiffness, a damping or a rubber arm > 0 (a free ring does "
                       "nothing)");
  std::vector<double> eps;
  for (std::size_t j = 0; j < s.arms.size(); ++j) {
    try {
      // Per arm sqrt(2) tighter: the arms' errors add up to at most sqrt(2) times the
      // largest relative one on |k*| (zener_rubber.h).
      eps.push_back(CalcJunctionInertia(s.arms[j], s.band_hz, s.junction_error / std::sqrt(2.0)));
    } catch (const InputError& e) {
      EMB_THROW(InputError, what << " rubber arm " << j + 1 << ": " << e.what());
    }
  }
  int hub = -1;
  try {
    hub = sys->FindMarker(s.hub_marker);
  } catch (const InputError& e) {
    EMB_THROW(InputError, what << " hub: " << e.what());
  }
  TorsionalDamperParts parts;
  const CoaxialRing ring =
      AddCoaxialRing(sys, s.name + "_ring", s.name + "_bearing", s.ring_mass, s.ring_inertia, hub);
  parts.ring_body = ring.body;
  parts.ring_marker = ring.marker;
  if (s.stiffness > 0.0 || s.damping > 0.0)
    sys->AddForceElement(std::make_shared<mbs::RotationalSpringDamper>(
        s.name, parts.ring_marker, hub, s.stiffness, s.damping, 0.0));
  for (std::size_t j = 0; j < s.arms.size(); ++j) {
    const std::string arm = s.name + "_arm" + std::to_string(j + 1);
    const std::string junction_name = s.name + "_junction" + std::to_string(j + 1);
    const CoaxialRing junction =
        AddCoaxialRing(sys, junction_name, junction_name + "_bearing",
                       s.ring_mass * eps[j] / s.ring_inertia, eps[j], hub);
    const double k = s.arms[j].stiffness, c = k * s.arms[j].relaxation_time;
    sys->AddForceElement(std::make_shared<mbs::RotationalSpringDamper>(
        arm + "_spring", junction.marker, hub, k, 0.0, 0.0));
    sys->AddForceElement(std::make_shared<mbs::RotationalSpringDamper>(
        arm + "_dashpot", parts.ring_marker, junction.marker, 0.0, c, 0.0));
    parts.junction_bodies.push_back(junction.body);
    parts.junction_inertia.push_back(eps[j]);
  }
  return parts;
}

DenHartogTuning TuneDenHartog(double primary_hz, double modal_inertia, double ring_inertia) {
  EMB_THROW_IF(!(primary_hz > 0.0), "Den Hartog tuning: expected a mode frequency > 0 Hz, got "
                                        << primary_hz);
  EMB_THROW_IF(!(modal_inertia > 0.0),
               "Den Hartog tuning: expected a modal inertia > 0 kg m^2, got " << modal_inertia);
  EMB_THROW_IF(!(ring_inertia > 0.0),
               "Den Hartog tuning: expected a ring inertia > 0 kg m^2, got " << ring_inertia);
  DenHartogTuning t;
  const double mu = ring_inertia / modal_inertia;
  t.mass_ratio = mu;
  t.absorber_hz = primary_hz / (1.0 + mu);
  t.damping_ratio = std::sqrt(3.0 * mu / (8.0 * std::pow(1.0 + mu, 3)));
  const double wa = 2.0 * std::numbers::pi * t.absorber_hz;
  t.stiffness = ring_inertia * wa * wa;
  t.damping = 2.0 * t.damping_ratio * ring_inertia * 2.0 * std::numbers::pi * primary_hz;
  t.fixed_point_amplification = std::sqrt(1.0 + 2.0 / mu);
  return t;
}

}  // namespace emb::engine
