#pragma once
// A flexible bar (tests/support/flexible_bar.h: 4 modes, 2 % damping) pinned at its x0 end to
// the ground, spinning at 30 rad/s about the pin (y), held at its x1 end by a bushing to the
// ground point "spring_end"; gravity -z. Every flexible term of the GGL DAE is active
// (inertia coupling, constraints and force elements through interface markers). The system
// is not finalized: a test adds its own elements first.

#include <Eigen/Dense>
#include <memory>

#include "libemb/mbs/core/system.h"
#include "libemb/mbs/forces/bushing.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "tests/support/flexible_bar.h"

namespace emb::testing {

struct PinnedBar {
  mbs::System sys;
  int tip{-1};         // the bar's x1 interface marker
  int spring_end{-1};  // the ground point the bushing holds it to
};

inline PinnedBar PinnedSpinningBar() {
  BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 4;
  bar.damping_ratio = 0.02;
  PinnedBar m;
  mbs::System& sys = m.sys;
  sys.SetGravity(Eigen::Vector3d(0, 0, -9.81));
  mbs::PartPlacement placement;
  placement.omega_W = Eigen::Vector3d(0, 30, 0);
  const mbs::FlexiblePart part =
      mbs::AddFlexibleBody(&sys, "bar", FlexibleBar(bar), "bar", {}, placement);
  const Eigen::Matrix3d pin_axes = Axes(Eigen::Vector3d::UnitY());
  mbs::AddInterfaceMarker(&sys, part, "root", "x0", pin_axes);
  m.tip = mbs::AddInterfaceMarker(&sys, part, "tip", "x1");
  sys.AddMarker("pivot", "ground", Eigen::Vector3d(0, 0.02, 0.015), pin_axes);
  m.spring_end = sys.AddMarker("spring_end", "ground", Eigen::Vector3d(0.62, 0.02, 0.015),
                               Eigen::Matrix3d::Identity());
  sys.AddJoint("pin", mbs::JointType::kRevolute, "root", "pivot");
  Eigen::Matrix<double, 6, 6> K = Eigen::Matrix<double, 6, 6>::Zero();
  K.diagonal() << 1.0e5, 2.0e5, 3.0e5, 10, 20, 30;
  sys.AddForceElement(
      std::make_shared<mbs::Bushing>("tip_mount", m.tip, m.spring_end, K, 1.0e-3 * K));
  return m;
}

}  // namespace emb::testing
