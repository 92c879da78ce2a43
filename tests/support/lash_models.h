#pragma once
// Two discs on revolute joints about world z (gear 1 at the origin, gear 2 beside it) whose
// rotation angles a_1, a_2 are joined by a lash on x = a_1 - r a_2 (driveline/lash.h), and a
// block on a translational joint between end stops. The effective inertia of x is
// m = 1 / (1/J_1 + r^2/J_2), and J_1 w_1 + (J_2/r) w_2 is conserved by the mesh force.

#include <algorithm>
#include <memory>
#include <vector>

#include "libemb/driveline/lash.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mbs/forces/applied_load.h"

namespace emb::driveline::testing {

struct TwoDiscs {
  double J1{0.02}, J2{0.05};        // [kg m^2] about the axes
  double ratio{2.0};                // r [-]
  double omega1{5.0}, omega2{0.0};  // initial speeds [rad/s]
  double torque1{0.0};              // constant torque on disc 1 [N m]
  double effective_inertia() const { return 1.0 / (1.0 / J1 + ratio * ratio / J2); }
  double closing_speed() const { return omega1 - ratio * omega2; }
};

inline mbs::RigidBody Disc(const std::string& name, double J, const Eigen::Vector3d& p,
                           double omega) {
  mbs::RigidBody b;
  b.name = name;
  b.mass = 1.0;
  b.inertia_B = Eigen::Vector3d(0.5 * J, 0.5 * J, J).asDiagonal();
  b.p_WB = p;
  b.omega_W = Eigen::Vector3d(0, 0, omega);
  return b;
}

// Not finalized when `finalize` is false (to add more elements).
inline mbs::System MakeTwoDiscs(const TwoDiscs& d, const LashParameters& lash,
                                bool finalize = true) {
  mbs::System s;
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  s.AddBody(Disc("gear1", d.J1, Eigen::Vector3d::Zero(), d.omega1));
  s.AddBody(Disc("gear2", d.J2, Eigen::Vector3d(0.1, 0, 0), d.omega2));
  s.AddMarker("hub1", "gear1", Eigen::Vector3d::Zero(), I);
  s.AddMarker("hub2", "gear2", Eigen::Vector3d::Zero(), I);
  s.AddMarker("bearing1", "ground", Eigen::Vector3d::Zero(), I);
  s.AddMarker("bearing2", "ground", Eigen::Vector3d(0.1, 0, 0), I);
  s.AddJoint("shaft1", mbs::JointType::kRevolute, "hub1", "bearing1");
  s.AddJoint("shaft2", mbs::JointType::kRevolute, "hub2", "bearing2");
  std::vector<CoordinateTerm> terms = {
      JointCoordinateTerm(s, "shaft1", mbs::JointCoordinate::kRotation, 1.0, "lash 'mesh'"),
      JointCoordinateTerm(s, "shaft2", mbs::JointCoordinate::kRotation, -d.ratio, "lash 'mesh'")};
  s.AddForceElement(std::make_shared<Lash>("mesh", terms, lash));
  if (d.torque1 != 0.0)
    s.AddForceElement(std::make_shared<mbs::AppliedLoad>(
        "drive", mbs::AppliedLoad::Kind::kTorque, s.FindMarker("hub1"), Eigen::Vector3d::UnitZ(),
        mbs::AppliedLoad::Frame::kWorld, mbs::TimeFunction::Constant(d.torque1)));
  if (finalize) s.Finalize();
  return s;
}

inline mbs::AnalysisSettings DynamicSettings(double t_end, double output_step, double rtol) {
  mbs::AnalysisSettings st;
  st.type = mbs::AnalysisType::kDynamic;
  st.t_end = t_end;
  st.output_step = output_step;
  st.ida.rtol = rtol;
  st.ida.atol = 1e-3 * rtol;
  return st;
}

// The contacts of the pair between its stops with no other force, in closed form: the first
// onset after half the lash `width` at the closing speed v; then each contact lasts
// `contact_duration(v)` and leaves the stop `dwell` of flight away (Kelvin-Voigt's tension
// cut-off leaves it penetrated), and the flight across the lash at e v ends in the next onset,
// on the other stop. The onsets up to t_end, their closing speeds, and the first onset after
// t_end (the margin of the count: a run's onsets move by its timing error).
struct ClosedFormContacts {
  std::vector<double> onset, speed;  // [s], [rad/s or m/s]
  double next_onset{0.0};            // [s], the first after t_end
  // The distance of t_end from the nearest closed-form event it separates [s].
  double CountMargin(double t_end) const {
    return std::min(next_onset - t_end, onset.empty() ? t_end : t_end - onset.back());
  }
};
template <class Duration>
ClosedFormContacts FreeFlightContacts(double width, double v, double e, double dwell,
                                      Duration contact_duration, double t_end) {
  ClosedFormContacts c;
  double t = 0.5 * width / v;
  while (t <= t_end) {
    c.onset.push_back(t);
    c.speed.push_back(v);
    t += contact_duration(v) + dwell + width / (e * v);
    v *= e;
  }
  c.next_onset = t;
  return c;
}

}  // namespace emb::driveline::testing
