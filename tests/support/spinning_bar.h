#pragma once
/// @file
/// A flexible bar (flexible_bar.h) clamped at its x0 interface to a hub that a motion spins
/// at a constant Omega about the world z axis through the bar's root, with a sensor
/// `tip_in_hub` (marker `tip` at interface x1 relative to the hub). Used by the centrifugal
/// stiffening (Southwell) and quasi-static start tests.

#include <Eigen/Dense>

#include "libemb/mbs/core/system.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "tests/support/flexible_bar.h"

namespace emb::testing {

/// The 0.6 x 0.04 x 0.03 m steel bar of these tests: root RBE2 (x0, the only support in the
/// stiffening load cases) and tip RBE3 (x1), 2 fixed-interface modes (8 elastic
/// coordinates), 2 % modal damping.
inline BarSpec SpinningBarSpec() {
  BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 2;
  bar.damping_ratio = 0.02;
  bar.stiffening_supports = {"x0"};
  return bar;
}

/// Options with the geometric stiffening on.
inline mbs::FlexibleBodyOptions StiffenedOptions() {
  mbs::FlexibleBodyOptions options;
  options.geometric_stiffening = mbs::GeometricStiffening::kOn;
  return options;
}

/// `bar` needs interfaces x0 and x1; eta0 (optional) are its initial modal coordinates. The
/// hub turns about the axis through the centre of the bar's root face; gravity g_W.
inline mbs::System SpinningBar(const BarSpec& bar, double omega,
                               const mbs::FlexibleBodyOptions& options,
                               const Eigen::VectorXd& eta0 = {},
                               const Eigen::Vector3d& g_W = Eigen::Vector3d::Zero()) {
  const Eigen::Vector3d spin(0, 0, omega), hub_point(0, bar.width / 2, bar.height / 2);
  mbs::System sys;
  sys.SetGravity(g_W);
  mbs::RigidBody hub;
  hub.name = "hub";
  hub.mass = 1.0;
  hub.inertia_B = 0.01 * Eigen::Matrix3d::Identity();
  hub.p_WB = hub_point;
  hub.omega_W = spin;
  sys.AddBody(hub);
  mbs::PartPlacement placement;
  placement.omega_W = spin;
  const mbs::FlexiblePart part =
      mbs::AddFlexibleBody(&sys, "bar", FlexibleBar(bar), "bar", options, placement, eta0);
  mbs::AddInterfaceMarker(&sys, part, "root", "x0");
  mbs::AddInterfaceMarker(&sys, part, "tip", "x1");
  sys.AddMarker("hub_face", "hub", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  sys.AddMarker("axis", "ground", hub_point, Eigen::Matrix3d::Identity());
  sys.AddJoint("clamp", mbs::JointType::kFixed, "root", "hub_face");
  sys.AddJoint("spin", mbs::JointType::kRevolute, "hub_face", "axis");
  sys.AddMotion("drive", "spin", mbs::JointCoordinate::kRotation,
                mbs::TimeFunction::Polynomial({0.0, omega}));
  sys.AddSensor("tip_in_hub", "tip", "hub_face");
  sys.Finalize();
  return sys;
}

}  // namespace emb::testing
