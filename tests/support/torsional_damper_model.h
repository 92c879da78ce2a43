#pragma once
// Test fixture shared by the torsional damper tests: a primary inertia J1 on a shaft k1
// (revolute joint to ground, rotational spring) with a damper (AddTorsionalDamper) on it, its
// linearised harmonic response and the two-DOF closed form of a Kelvin-Voigt ring.

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include "libemb/engine/torsional_damper.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/linearization.h"
#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/forces/applied_load.h"
#include "libemb/mbs/forces/spring_damper.h"

namespace emb::tvd_test {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Complex = std::complex<double>;
constexpr double kPi = std::numbers::pi;

constexpr double kJ1 = 0.05;       // primary inertia [kg m^2]
constexpr double kF1 = 400.0;      // primary natural frequency without damper [Hz]
constexpr double kTorque = 1.0;    // [N m]
inline const double kK1 = kJ1 * std::pow(2 * kPi * kF1, 2);

struct Model {
  mbs::System sys;
  int primary{-1};
};

// `torque` (may be empty): a torque about z on the primary, T(t) [N m].
inline Model Primary(const engine::TorsionalDamperSpec& tvd,
              const std::optional<mbs::TimeFunction>& torque = std::nullopt) {
  Model m;
  mbs::RigidBody p;
  p.name = "primary";
  p.mass = 5.0;
  p.inertia_B = Vector3d(kJ1 / 2, kJ1 / 2, kJ1).asDiagonal();
  m.primary = m.sys.AddBody(p);
  m.sys.AddMarker("primary_axis", "primary", Vector3d::Zero(), Matrix3d::Identity());
  m.sys.AddMarker("frame", "ground", Vector3d::Zero(), Matrix3d::Identity());
  m.sys.AddJoint("bearing", mbs::JointType::kRevolute, "primary_axis", "frame");
  m.sys.AddForceElement(std::make_shared<mbs::RotationalSpringDamper>(
      "shaft", m.sys.FindMarker("primary_axis"), m.sys.FindMarker("frame"), kK1, 0.0, 0.0));
  engine::AddTorsionalDamper(&m.sys, tvd);
  if (torque)
    m.sys.AddForceElement(std::make_shared<mbs::AppliedLoad>(
        "drive", mbs::AppliedLoad::Kind::kTorque, m.sys.FindMarker("primary_axis"),
        Vector3d::UnitZ(), mbs::AppliedLoad::Frame::kWorld, *torque));
  m.sys.Finalize();
  return m;
}

inline engine::TorsionalDamperSpec Ring(double J2, double k2, double c) {
  engine::TorsionalDamperSpec s;
  s.name = "tvd";
  s.hub_marker = "primary_axis";
  s.ring_mass = 1.0;
  s.ring_inertia = J2;
  s.stiffness = k2;
  s.damping = c;
  return s;
}

// |theta1| / (T / k1) from the linearised multibody model (linearised once, at rest).
class ModelResponse {
 public:
  explicit ModelResponse(const Model& m) : rz_(m.sys.layout().angular_velocity(m.primary) + 2) {
    mbs::ConstraintWorkspace ws(m.sys);
    lin_ = mbs::CalcLinearizedModel(m.sys, m.sys.InitialPositions(), Eigen::VectorXd(), 0.0,
                                    Eigen::VectorXd::Zero(m.sys.num_equations()), &ws);
  }
  /// theta1 [rad] under T = kTorque.
  Complex PrimaryAngle(double w) const {
    Eigen::VectorXcd F = Eigen::VectorXcd::Zero(lin_.M.rows());
    F[rz_] = kTorque;
    const Eigen::MatrixXcd Z = lin_.Z.cast<Complex>();
    const Eigen::MatrixXcd A = Z.adjoint() *
                               (lin_.K.cast<Complex>() - w * w * lin_.M.cast<Complex>() +
                                Complex(0.0, w) * lin_.G.cast<Complex>()) *
                               Z;
    const Eigen::VectorXcd x = Z * A.partialPivLu().solve(Z.adjoint() * F);
    return x[rz_];
  }
  double Amplification(double w) const { return std::abs(PrimaryAngle(w)) / (kTorque / kK1); }

 private:
  int rz_;
  mbs::LinearizedModel lin_;
};

inline double ModelAmplification(const Model& m, double w) { return ModelResponse(m).Amplification(w); }

inline double ClosedFormAmplification(double J2, double k2, double c, double w) {
  const Complex a(k2 - J2 * w * w, w * c), b(k2, w * c);
  // k1 + k2 - J1 w^2 + i w c = (k1 - J1 w^2) + b.
  const Complex D = (Complex(kK1 - kJ1 * w * w) + b) * a - b * b;
  return std::abs(a / D) * kK1;
}

/// The primary's steady amplitude [rad] under kTorque sin(2 pi f t) from rest: IDA (rtol 1e-9)
/// for 60 periods, the half peak-to-peak of the last 5 sampled at 200 points a period.
struct SteadyRun {
  bool ok{false};
  std::string message;
  double amplitude{0.0};  ///< [rad]
  long steps{0}, residual_evals{0}, jacobian_evals{0};
};
inline SteadyRun RunToSteadyState(const engine::TorsionalDamperSpec& spec, double f) {
  const double w = 2 * kPi * f;
  const Model m = Primary(spec, mbs::TimeFunction::Harmonic(kTorque, w, 0.0, 0.0));
  mbs::AnalysisSettings s;
  s.t_end = 60.0 / f;
  s.output_step = 1.0 / (f * 200.0);
  s.ida.rtol = 1e-9;
  s.ida.atol = 1e-13;
  const mbs::PreparedRun run = mbs::PrepareRun(m.sys, s);
  const int bearing = run.system.FindElement("bearing");
  double lo = 1e300, hi = -1e300;
  const mbs::RunResult r = mbs::RunAnalysis(run, s, [&](const mbs::Sample& x) {
    if (x.t < s.t_end - 5.0 / f) return;
    lo = std::min(lo, x.joints(bearing, 0));
    hi = std::max(hi, x.joints(bearing, 0));
  });
  return {r.ok(), r.message, 0.5 * (hi - lo), r.ida_stats.steps, r.ida_stats.residual_evals,
          r.ida_stats.jacobian_evals};
}

}  // namespace emb::tvd_test
