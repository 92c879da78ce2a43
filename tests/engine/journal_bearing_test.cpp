// Short (Ocvirk) journal bearing with a pi-film: the steady-load closed forms (radial and
// tangential force, attitude angle), the pure-squeeze closed form, invariance under a common
// spin of journal and shell, non-negative dissipation equal to minus the power of the loads,
// analytic Jacobian against central differences, parameter checks and the touching-shell
// error.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "libemb/common/error.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/engine/journal_bearing.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "tests/support/force_jacobian_check.h"
#include "tests/support/posed_bodies.h"

namespace emb::mbs {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

// A main bearing of a passenger-car engine: D = 55 mm, L = 24 mm, c = 30 um, SAE 10W-40 hot.
JournalBearingParameters Main() { return {0.0275, 0.024, 30e-6, 0.01}; }

// 64-point Gauss on a half circle (journal_bearing.h): steady rotation puts the minimum
// film at an end of the interval (< 1e-13 up to eps = 0.99); pure squeeze puts it in the
// middle (worst case, < 1e-13 at 0.85, the largest squeeze eps here). 1e-9 leaves margin.
constexpr double kQuadratureTolerance = 1e-9;

// int_{-pi/2}^{pi/2} cos^2 / (1 - eps cos)^3 dphi = J0''(eps)/2 with
// J0 = int 1/(1 - eps cos) = 4 atan(sqrt((1+eps)/(1-eps))) / sqrt(1-eps^2); valid for |eps| < 1.
double SqueezeIntegral(double eps) {
  const double s = 1.0 - eps * eps;
  return (2.0 * (1.0 + 2.0 * eps * eps) * std::atan(std::sqrt((1.0 + eps) / (1.0 - eps))) +
          3.0 * eps * std::sqrt(s)) /
         std::pow(s, 2.5);
}

TEST(JournalBearing, SteadyLoadMatchesOcvirk) {
  const JournalBearingParameters p = Main();
  const JournalBearing b("main_1", 0, 1, p);
  const double w = 314.159;  // 3000 rpm
  const double mu = p.viscosity, R = p.radius, L = p.length, c = p.clearance;
  for (double eps : {0.05, 0.3, 0.6, 0.8, 0.9, 0.95}) {
    // Eccentricity along x; the same at 40 degrees (the film is isotropic).
    for (double angle : {0.0, 0.7}) {
      const Eigen::Rotation2Dd rot(angle);
      const Vector2d e = rot * Vector2d(eps * c, 0.0);
      const auto load = b.CalcFilmLoad(e, Vector2d::Zero(), w);
      const Vector2d F = rot.inverse() * load.force;
      const double s = 1.0 - eps * eps;
      const double Fr = mu * w * R * std::pow(L, 3) * eps * eps / (c * c * s * s);
      const double Ft = kPi * mu * w * R * std::pow(L, 3) * eps / (4 * c * c * std::pow(s, 1.5));
      EXPECT_NEAR(F.x(), -Fr, kQuadratureTolerance * Fr) << eps;
      EXPECT_NEAR(F.y(), Ft, kQuadratureTolerance * Ft) << eps;
      // Attitude angle tan(phi) = pi sqrt(1 - eps^2) / (4 eps) between load and line of centres.
      EXPECT_NEAR(std::atan2(F.y(), -F.x()), std::atan(kPi * std::sqrt(s) / (4 * eps)), 1e-9);
      // Torque: pressure-induced -(e x F)/2 plus Petroff drag.
      const double petroff = 2 * kPi * mu * R * R * R * L * w / (c * std::sqrt(s));
      EXPECT_NEAR(load.torque, -0.5 * eps * c * Ft - petroff, 1e-9 * petroff) << eps;
    }
  }
}

TEST(JournalBearing, PureSqueezeMatchesClosedForm) {
  const JournalBearingParameters p = Main();
  const JournalBearing b("main_1", 0, 1, p);
  const double scale = p.viscosity * p.radius * std::pow(p.length, 3) / std::pow(p.clearance, 3);
  for (double eps : {0.0, 0.4, 0.85}) {
    for (double e_dot : {0.01, -0.01}) {  // towards the wall (film squeezed there) and away
      const auto load = b.CalcFilmLoad(Vector2d(eps * p.clearance, 0), Vector2d(e_dot, 0), 0.0);
      // Moving away, the pressure builds on the far side where h = c (1 + eps cos).
      const double expected = -scale * e_dot * SqueezeIntegral(e_dot > 0 ? eps : -eps);
      EXPECT_NEAR(load.force.x(), expected, kQuadratureTolerance * std::abs(expected)) << eps;
      EXPECT_NEAR(load.force.y(), 0.0, kQuadratureTolerance * std::abs(expected)) << eps;
    }
  }
}

// Journal "pin" in a shell "eye", both free bodies (no joints), at given poses and rates.
using testing::Pose;
System PinInEye(const JournalBearingParameters& jp, const Pose& eye, const Pose& pin) {
  System s;
  testing::AddPosedBodies(&s, {{"eye", eye}, {"pin", pin}});
  // Markers off the CMs so that the arms matter.
  const Vector3d s_eye(0.01, -0.02, 0.005), s_pin(-0.015, 0.01, 0.02);
  s.AddMarker("shell", "eye", s_eye, RotationFromEuler313(0.2, 0.1, -0.3));
  s.AddMarker("journal", "pin", s_pin, Eigen::Matrix3d::Identity());
  s.AddForceElement(std::make_shared<JournalBearing>("big_end", s.FindMarker("journal"),
                                                     s.FindMarker("shell"), jp));
  s.Finalize();
  return s;
}

// Places the pin so that the journal marker sits at eccentricity e (in the shell's axes)
// from the shell marker.
Pose PinAt(const Pose& eye, const Vector2d& e_J, const Eigen::Matrix3d& R_pin) {
  const Eigen::Matrix3d R_shell = eye.R * RotationFromEuler313(0.2, 0.1, -0.3);
  const Vector3d p_shell = eye.p + eye.R * Vector3d(0.01, -0.02, 0.005);
  Pose pin;
  pin.R = R_pin;
  pin.p = p_shell + R_shell * Vector3d(e_J.x(), e_J.y(), 0.0) - R_pin * Vector3d(-0.015, 0.01, 0.02);
  return pin;
}

Eigen::VectorXd Forces(const System& s) {
  const auto bodies = CalcBodyKinematics(s, s.InitialPositions(), s.InitialVelocities());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(s.layout().nv());
  s.force_elements()[0]->AddForces({&s, &bodies, 0.0, nullptr, -1}, f);
  return f;
}

TEST(JournalBearing, CommonSpinIsTheSameAsTwiceTheJournalSpeed) {
  // Shell and journal both spinning at w about the bearing axis with the journal centre at
  // rest in the world: the film sees journal + shell speed 2w (Reynolds: U1 + U2).
  const JournalBearingParameters p = Main();
  Pose eye;
  eye.p = Vector3d(0.1, 0.2, -0.05);
  eye.R = RotationFromEuler313(0.5, 0.4, 0.3);
  const Vector3d axis = eye.R * RotationFromEuler313(0.2, 0.1, -0.3).col(2);
  const double w = 200.0;
  const Vector2d e(0.4 * p.clearance, -0.3 * p.clearance);
  // The eye spins about the shell marker's origin: v_eye = w x (p_eye - p_shell).
  const Vector3d p_shell = eye.p + eye.R * Vector3d(0.01, -0.02, 0.005);
  auto spin_about_shell = [&](Pose pose, double rate) {
    pose.w = rate * axis;
    pose.v = pose.w.cross(pose.p - p_shell);
    return pose;
  };
  Pose pin = PinAt(eye, e, Eigen::Matrix3d::Identity());
  // The journal spins about its own centre, which stays put.
  const Vector3d p_journal = pin.p + Vector3d(-0.015, 0.01, 0.02);
  auto journal_spin = [&](double rate) {
    Pose q = pin;
    q.w = rate * axis;
    q.v = q.w.cross(q.p - p_journal);
    return q;
  };
  const Eigen::VectorXd both = Forces(PinInEye(p, spin_about_shell(eye, w), journal_spin(w)));
  const Eigen::VectorXd journal_only =
      Forces(PinInEye(p, spin_about_shell(eye, 0.0), journal_spin(2 * w)));
  // The film force on the pin (world), the same in both; round-off of the 64-term sums.
  const Vector3d F1 = both.segment<3>(6), F2 = journal_only.segment<3>(6);
  EXPECT_GT(F1.norm(), 1.0);
  EXPECT_LT((F1 - F2).norm(), 1e-9 * F1.norm());
}

TEST(JournalBearing, DissipationIsNonNegativeAndMinusThePowerOfTheLoads) {
  const JournalBearingParameters p{0.05, 0.05, 0.02, 0.5};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  auto vec = [&](double s) { return Vector3d(s * U(rng), s * U(rng), s * U(rng)); };
  for (int trial = 0; trial < 20; ++trial) {
    Pose eye;
    eye.p = vec(0.2);
    eye.R = RotationFromEuler313(U(rng), U(rng), U(rng));
    eye.v = vec(0.3);
    eye.w = vec(20.0);
    const Vector2d e = 0.9 * std::abs(U(rng)) * p.clearance * Vector2d(U(rng), U(rng)).normalized();
    Pose pin = PinAt(eye, e, RotationFromEuler313(U(rng), U(rng), U(rng)));
    pin.v = vec(0.3);
    pin.w = vec(20.0);
    const System s = PinInEye(p, eye, pin);
    const auto bodies = CalcBodyKinematics(s, s.InitialPositions(), s.InitialVelocities());
    const ForceContext ctx{&s, &bodies, 0.0, nullptr, -1};
    const double dissipated = s.force_elements()[0]->CalcDissipatedPower(ctx);
    const double power = Forces(s).dot(s.InitialVelocities());
    EXPECT_GE(dissipated, 0.0) << trial;
    // The loads are F in the bearing plane and a couple about z_J, so their power is
    // F . e' + T w whatever the tilt: the dissipation is exactly its negative.
    EXPECT_NEAR(dissipated, -power, 1e-12 * std::max(1.0, std::abs(power))) << trial;
    // The outputs: h_min = c - |e|, |e| / c and the dissipated power (round-off of the
    // kinematics: 1e-15 of the positions' scale).
    Eigen::VectorXd out(3);
    ASSERT_TRUE(s.force_elements()[0]->CalcOutputs(ctx, out));
    EXPECT_NEAR(out[0], p.clearance - e.norm(), 1e-14);
    EXPECT_NEAR(out[1], e.norm() / p.clearance, 1e-12);
    EXPECT_EQ(out[2], dissipated);
  }
}

// See force_element_test.cpp; the film forces here are ~1e2..1e4 N on a 20 mm clearance,
// h = 1e-6 m is 5e-5 of it.
constexpr double kDerivativeTolerance = 1e-7;

TEST(JournalBearing, JacobianMatchesCentralDifferences) {
  const JournalBearingParameters p{0.05, 0.05, 0.02, 0.5};
  Pose eye;
  eye.p = Vector3d(0.1, -0.05, 0.02);
  eye.R = RotationFromEuler313(0.4, 0.3, -0.2);
  eye.v = Vector3d(0.05, -0.02, 0.03);
  eye.w = Vector3d(0.5, -1.0, 3.0);
  for (const Vector2d& e : {Vector2d(0.006, -0.004), Vector2d(-0.011, 0.003)}) {
    Pose pin = PinAt(eye, e, RotationFromEuler313(-0.3, 0.2, 0.5));
    pin.v = Vector3d(-0.04, 0.06, 0.01);
    pin.w = Vector3d(0.3, 0.2, 40.0);
    const System s = PinInEye(p, eye, pin);
    const Eigen::VectorXd q = s.InitialPositions(), v = s.InitialVelocities();
    const auto bodies = CalcBodyKinematics(s, q, v);
    DenseForceJacobian analytic(s.layout());
    s.force_elements()[0]->AddForceJacobian({&s, &bodies, 0.0, nullptr, -1}, &analytic);
    const auto fd = testing::CentralDifferenceJacobian(s, 0, q, v, 0.0, 1e-6, nullptr);
    const double scale = std::max(fd.stiffness.cwiseAbs().maxCoeff(), fd.damping.cwiseAbs().maxCoeff());
    EXPECT_GT(scale, 1.0);
    EXPECT_LT((analytic.stiffness() - fd.stiffness).cwiseAbs().maxCoeff(), kDerivativeTolerance * scale);
    EXPECT_LT((analytic.damping() - fd.damping).cwiseAbs().maxCoeff(), kDerivativeTolerance * scale);
  }
}

TEST(JournalBearing, RejectsBadParameters) {
  const JournalBearingParameters good = Main();
  auto expect_error = [&](JournalBearingParameters p, const std::string& word) {
    try {
      JournalBearing("main_3", 0, 1, p);
      FAIL() << "expected an InputError about " << word;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("'main_3'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  auto with = [&](double JournalBearingParameters::*field, double value) {
    JournalBearingParameters p = good;
    p.*field = value;
    return p;
  };
  expect_error(with(&JournalBearingParameters::radius, 0.0), "radius");
  expect_error(with(&JournalBearingParameters::length, -1.0), "length");
  expect_error(with(&JournalBearingParameters::clearance, std::nan("")), "clearance");
  expect_error(with(&JournalBearingParameters::viscosity, 0.0), "viscosity");
  expect_error(with(&JournalBearingParameters::clearance, 0.03), "clearance smaller");
  expect_error(with(&JournalBearingParameters::length, 0.06), "L/D");
}

TEST(JournalBearing, TouchingTheShellIsANumericalErrorNamingTheBearing) {
  const JournalBearing b("main_2", 0, 1, Main());
  try {
    b.CalcFilmLoad(Vector2d(30e-6, 1e-7), Vector2d::Zero(), 300.0, 0.25);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'main_2'"), std::string::npos) << m;
    EXPECT_NE(m.find("touches the shell"), std::string::npos) << m;
    EXPECT_NE(m.find("t = 0.25"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace emb::mbs
