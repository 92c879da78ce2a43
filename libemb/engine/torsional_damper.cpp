#include "libemb/engine/torsional_damper.h"

#include <cmath>
#include <memory>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/mbs/forces/spring_damper.h"

namespace emb::engine {

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
  EMB_THROW_IF(s.stiffness == 0.0 && s.damping == 0.0,
               what << ": expected a stiffness or a damping > 0 (a free ring does nothing)");
  int hub = -1;
  try {
    hub = sys->FindMarker(s.hub_marker);
  } catch (const InputError& e) {
    EMB_THROW(InputError, what << " hub: " << e.what());
  }
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
  mbs::RigidBody ring;
  ring.name = s.name + "_ring";
  ring.mass = s.ring_mass;
  ring.inertia_B = Eigen::Vector3d(0.5 * s.ring_inertia, 0.5 * s.ring_inertia, s.ring_inertia)
                       .asDiagonal();
  ring.p_WB = p_W;
  ring.R_WB = R_WM;
  ring.v_WB = v_W;
  ring.omega_W = omega_W;
  TorsionalDamperParts parts;
  parts.ring_body = sys->AddBody(ring);
  parts.ring_marker =
      sys->AddMarker(s.name + "_ring_axis", ring.name, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  sys->AddJoint(s.name + "_bearing", mbs::JointType::kRevolute, s.name + "_ring_axis", s.hub_marker);
  sys->AddForceElement(std::make_shared<mbs::RotationalSpringDamper>(
      s.name, parts.ring_marker, hub, s.stiffness, s.damping, 0.0));
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
