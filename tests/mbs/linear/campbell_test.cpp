// Campbell diagrams (issue 17) on a Jeffcott-like rotor with a closed form: a rigid disc
// (polar inertia Ip, diametral Id) on an elastic mount (a bushing) to a hub driven at speed
// Omega about x. Its tilt whirls at
//   Id w^2 -+ Ip Omega w - k_tilt = 0:  w_fwd,bwd = (+-Ip Omega + sqrt((Ip Omega)^2 + 4 Id k_tilt)) / (2 Id)
// while its torsion sqrt(k_tors / Ip), axial sqrt(k_ax / m) and lateral sqrt(k_lat / m)
// frequencies do not depend on the speed. The forward whirl rises through the torsion and
// lateral frequencies (genuine crossings: the motions are uncoupled), which MAC tracking must
// follow without swapping, and the classification must name each mode.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/linear/campbell.h"
#include "libemb/mbs/linear/mode_tracking.h"
#include "libemb/mbs/forces/bushing.h"

namespace emb {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

// The rotor (SI): a thin disc, Ip = 2 Id.
constexpr double kMass = 10.0;            // [kg]
constexpr double kIp = 0.2, kId = 0.1;    // [kg m^2]
constexpr double kTiltHz = 50.0;          // sqrt(k_tilt / Id) / 2 pi at rest
constexpr double kTorsionHz = 120.0;      // sqrt(k_tors / Ip) / 2 pi
constexpr double kAxialHz = 30.0;         // sqrt(k_ax / m) / 2 pi
constexpr double kLateralHz = 80.0;       // sqrt(k_lat / m) / 2 pi

double Stiffness(double inertia, double hz) { return inertia * std::pow(2 * kPi * hz, 2); }

// Marker axes with z along the spin axis (world x).
Matrix3d SpinAxes() {
  Matrix3d R;
  R.col(2) = Vector3d::UnitX();
  R.col(0) = Vector3d::UnitY();
  R.col(1) = R.col(2).cross(R.col(0));
  return R;
}

mbs::System Rotor(double rpm) {
  const double Omega = 2 * kPi * rpm / 60.0;
  mbs::System sys;
  mbs::RigidBody hub;
  hub.name = "hub";
  hub.mass = 1.0;
  hub.inertia_B = 0.01 * Matrix3d::Identity();
  hub.omega_W = Vector3d(Omega, 0, 0);
  sys.AddBody(hub);
  mbs::RigidBody disc;
  disc.name = "disc";
  disc.mass = kMass;
  disc.inertia_B = Vector3d(kIp, kId, kId).asDiagonal();
  disc.omega_W = Vector3d(Omega, 0, 0);
  sys.AddBody(disc);
  sys.AddMarker("hub_axis", "hub", Vector3d::Zero(), SpinAxes());
  sys.AddMarker("frame_axis", "ground", Vector3d::Zero(), SpinAxes());
  sys.AddMarker("disc_centre", "disc", Vector3d::Zero(), SpinAxes());
  sys.AddJoint("hub_bearing", mbs::JointType::kRevolute, "hub_axis", "frame_axis");
  sys.AddMotion("drive", "hub_bearing", mbs::JointCoordinate::kRotation,
                mbs::TimeFunction::Polynomial({0.0, Omega}));
  // Bushing axes = the hub marker's: x, y lateral, z axial; rotations likewise.
  Eigen::Matrix<double, 6, 1> k;
  k << Stiffness(kMass, kLateralHz), Stiffness(kMass, kLateralHz), Stiffness(kMass, kAxialHz),
      Stiffness(kId, kTiltHz), Stiffness(kId, kTiltHz), Stiffness(kIp, kTorsionHz);
  sys.AddForceElement(std::make_shared<mbs::Bushing>(
      "mount", sys.FindMarker("disc_centre"), sys.FindMarker("hub_axis"),
      Eigen::Matrix<double, 6, 6>(k.asDiagonal()), Eigen::Matrix<double, 6, 6>::Zero()));
  sys.Finalize();
  return sys;
}

// Closed-form tilt whirl [Hz] at `rpm`: +1 forward, -1 backward.
double WhirlHz(double rpm, int sense) {
  const double Omega = 2 * kPi * rpm / 60.0, k = Stiffness(kId, kTiltHz);
  const double root = std::sqrt(std::pow(kIp * Omega, 2) + 4 * kId * k);
  return (sense * kIp * Omega + root) / (2 * kId) / (2 * kPi);
}

mbs::OperatingPointModes ModesAt(double rpm, bool stationary = true) {
  return mbs::CalcOperatingPointModes(Rotor(rpm), mbs::AnalysisSettings{}, rpm, "disc", 500.0,
                                      stationary);
}

// Dense eigen-solves of a 6-coordinate model: round-off.
constexpr double kFrequencyTolerance = 1e-8;

TEST(Campbell, GyroscopicSplitOfTheTiltFollowsTheClosedForm) {
  for (double rpm : {500.0, 3000.0, 6000.0}) {
    const mbs::OperatingPointModes m = ModesAt(rpm);
    const Eigen::VectorXd& f = m.point.modes.frequencies_hz;
    ASSERT_EQ(f.size(), 6) << rpm << " rpm";  // 2 lateral, axial, torsion, 2 tilt whirls
    std::vector<double> expected = {kLateralHz, kLateralHz, kAxialHz, kTorsionHz,
                                    WhirlHz(rpm, +1), WhirlHz(rpm, -1)};
    std::sort(expected.begin(), expected.end());
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(f[k] / expected[k], 1.0, kFrequencyTolerance) << rpm << " rpm, mode " << k + 1;
    EXPECT_NEAR(m.point.modes.decay.cwiseAbs().maxCoeff(), 0.0, 1e-6 * f.maxCoeff())
        << "undamped: no decay";
  }
}

TEST(Campbell, TheFrozenBodyFrameLinearisationMissesTheSplit) {
  // Without the frame term the gyroscopic coefficient is (Id - Ip) Omega instead of
  // Ip Omega: at 6000 rpm the forward whirl is off by far more than any tolerance (the
  // reason for the stationary-frame form).
  const mbs::OperatingPointModes m = ModesAt(6000.0, /*stationary=*/false);
  const double forward = WhirlHz(6000.0, +1);
  double nearest = 1e300;
  for (Eigen::Index k = 0; k < m.point.modes.frequencies_hz.size(); ++k)
    nearest = std::min(nearest, std::abs(m.point.modes.frequencies_hz[k] - forward));
  EXPECT_GT(nearest / forward, 0.1);
}

TEST(Campbell, ModesAreClassifiedByTheirEnergy) {
  const mbs::OperatingPointModes m = ModesAt(3000.0);
  int torsion = 0, axial = 0, bending = 0, forward = 0, backward = 0;
  for (std::size_t k = 0; k < m.point.splits.size(); ++k) {
    const mbs::ModeSplit& s = m.point.splits[k];
    const double f = m.point.modes.frequencies_hz[static_cast<Eigen::Index>(k)];
    // Uncoupled motions: each mode is pure, up to round-off.
    constexpr double kPure = 1e-8;
    EXPECT_GT(std::max({s.torsion, s.bending, s.axial}), 1.0 - kPure) << f << " Hz";
    EXPECT_NEAR(s.body_energy, 1.0, kPure) << "the disc carries all the kinetic energy";
    if (std::abs(f - kTorsionHz) < 1e-6 * f) {
      ++torsion;
      EXPECT_EQ(s.kind, mbs::ModeClass::kTorsion);
    }
    if (std::abs(f - kAxialHz) < 1e-6 * f) {
      ++axial;
      EXPECT_EQ(s.kind, mbs::ModeClass::kAxial);
    }
    if (s.kind == mbs::ModeClass::kBending) ++bending;
    if (std::abs(f - WhirlHz(3000.0, +1)) < 1e-6 * f) {
      ++forward;
      EXPECT_EQ(s.whirl, mbs::Whirl::kForward);
    }
    if (std::abs(f - WhirlHz(3000.0, -1)) < 1e-6 * f) {
      ++backward;
      EXPECT_EQ(s.whirl, mbs::Whirl::kBackward);
    }
  }
  EXPECT_EQ(torsion, 1);
  EXPECT_EQ(axial, 1);
  EXPECT_EQ(bending, 4);  // two lateral, two tilt whirls
  EXPECT_EQ(forward, 1);
  EXPECT_EQ(backward, 1);
}

TEST(Campbell, MacTrackingFollowsTheForwardWhirlThroughItsCrossings) {
  // 500 .. 6000 rpm: the forward whirl rises from ~52 Hz to ~200 Hz, crossing the lateral
  // (80 Hz) and torsion (120 Hz) lines; sorted by frequency its index would change twice.
  std::vector<mbs::CampbellPoint> points;
  for (double rpm = 500.0; rpm <= 6000.0; rpm += 250.0) points.push_back(ModesAt(rpm).point);
  const mbs::CampbellDiagram d = mbs::TrackCampbell(points, 500.0, 0.5);
  ASSERT_EQ(d.modes.size(), 6u);
  EXPECT_EQ(d.num_lost, 0);
  int forward_modes = 0;
  for (const mbs::TrackedMode& t : d.modes) {
    const double f0 = t.hz.front();
    const bool is_forward = std::abs(f0 - WhirlHz(500.0, +1)) < 1e-6 * f0;
    const bool is_torsion = std::abs(f0 - kTorsionHz) < 1e-6 * f0;
    for (std::size_t k = 0; k < d.rpm.size(); ++k) {
      ASSERT_TRUE(std::isfinite(t.hz[k])) << "mode " << t.index << " lost at " << d.rpm[k];
      if (is_forward) {
        EXPECT_NEAR(t.hz[k] / WhirlHz(d.rpm[k], +1), 1.0, kFrequencyTolerance) << d.rpm[k];
      }
      if (is_torsion) {
        EXPECT_NEAR(t.hz[k] / kTorsionHz, 1.0, kFrequencyTolerance) << d.rpm[k];
      }
    }
    if (is_forward) {
      ++forward_modes;
      EXPECT_EQ(t.kind, mbs::ModeClass::kBending);
      EXPECT_EQ(t.whirl, mbs::Whirl::kForward);
    }
  }
  EXPECT_EQ(forward_modes, 1);

  // Critical speeds. Torsion is flat: order k crosses it at exactly 60 f / k. The forward
  // whirl meets order 3 where (9 Id - 3 Ip) Omega^2 = k_tilt (w = 3 Omega); linear
  // interpolation on a 250 rpm grid of a curve with this curvature is good to ~0.5 %.
  constexpr double kInterpolation = 5e-3;
  const std::vector<mbs::Crossing> c = mbs::FindCrossings(d, {2.0, 3.0});
  int torsion_2 = 0, forward_3 = 0;
  const double forward_3_rpm =
      60.0 / (2 * kPi) * std::sqrt(Stiffness(kId, kTiltHz) / (9 * kId - 3 * kIp));
  for (const mbs::Crossing& x : c) {
    EXPECT_NEAR(x.mode_hz, x.order * x.rpm / 60.0, 1e-9 * x.mode_hz);
    if (x.kind == mbs::ModeClass::kTorsion && x.order == 2.0) {
      ++torsion_2;
      EXPECT_NEAR(x.rpm, 60.0 * kTorsionHz / 2.0, 1e-6);
    }
    if (x.whirl == mbs::Whirl::kForward && x.order == 3.0) {
      ++forward_3;
      EXPECT_NEAR(x.rpm / forward_3_rpm, 1.0, kInterpolation);
    }
  }
  EXPECT_EQ(torsion_2, 1);
  EXPECT_EQ(forward_3, 1);
}

TEST(ModeTracking, MacAndGreedyMatchingRecoverAPermutation) {
  const Eigen::MatrixXd M = Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal();
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Identity(3, 3);
  Eigen::MatrixXcd B(3, 3);
  B.col(0) = A.col(2) * std::complex<double>(0.0, 2.0);  // phase and scale do not matter
  B.col(1) = A.col(0) + 0.1 * A.col(1);
  B.col(2) = A.col(1);
  const Eigen::MatrixXd mac = mbs::CalcMac(A, B, M);
  EXPECT_NEAR(mac(2, 0), 1.0, 1e-14);
  EXPECT_NEAR(mac(0, 2), 0.0, 1e-14);
  // a = e1, b = e1 + 0.1 e2 with M = diag(1, 2, 3): 1 / (1 + 0.02).
  EXPECT_NEAR(mac(0, 1), 1.0 / 1.02, 1e-14);
  EXPECT_EQ(mbs::MatchModes(mac, 0.5), (std::vector<int>{1, 2, 0}));
  EXPECT_EQ(mbs::MatchModes(mac, 0.999), (std::vector<int>{-1, 2, 0}));
}

TEST(Campbell, BadInputIsNamed) {
  EXPECT_THROW(mbs::TrackCampbell({}, 100.0, 0.5), InputError);
  std::vector<mbs::CampbellPoint> two(2);
  two[0].rpm = 2000.0, two[1].rpm = 1000.0;
  EXPECT_THROW(mbs::TrackCampbell(two, 100.0, 0.5), InputError);
  EXPECT_THROW(mbs::CalcOperatingPointModes(Rotor(1000.0), mbs::AnalysisSettings{}, 1000.0,
                                            "no_such_body", 500.0),
               InputError);
}

}  // namespace
}  // namespace emb
