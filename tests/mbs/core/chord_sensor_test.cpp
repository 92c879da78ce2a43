// The deflection-relative-to-chord sensor (mbs/core/chord_sensor.h) against closed forms of
// rigid geometry, its degenerate chord and its bad input (its scene form: the scene's
// sensor_reader_test.cpp).

#include "libemb/mbs/core/chord_sensor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "libemb/common/error.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"
#include "tests/support/input_error.h"

namespace emb {
namespace {

using Eigen::Vector3d;

// Round-off of the few products and a square root on O(1) m coordinates.
constexpr double kRoundOff = 1e-14;
constexpr double kLength = 0.8;  // chord length [m]

// The five channels of a chord sensor `probe` of `sys` at its initial state.
Eigen::VectorXd Channels(const mbs::System& sys, int probe) {
  const auto bodies = mbs::CalcBodyKinematics(sys, sys.InitialPositions(), sys.InitialVelocities());
  Eigen::VectorXd values(5);
  sys.probes()[static_cast<std::size_t>(probe)]->Eval(
      sys, bodies, Eigen::VectorXd::Zero(sys.layout().nv()), values);
  return values;
}

mbs::RigidBody Rod(const Vector3d& p_WB, const Eigen::Matrix3d& R_WB) {
  mbs::RigidBody b;
  b.name = "rod";
  b.mass = 1.0;
  b.inertia_B = Eigen::Vector3d(1e-4, 0.05, 0.05).asDiagonal();
  b.p_WB = p_WB;
  b.R_WB = R_WB;
  return b;
}

// A point carried by the body at (a, h, k) from chord end A in the body's axes, the chord
// A -> B along the body's x: the deflection in A's axes (the body's) is (0, h, k), its norm
// hypot(h, k) and s = a / L, whatever the body's pose.
TEST(ChordSensor, PointOnTheBodyReadsItsBodyOffsetInAnyPose) {
  constexpr double a = 0.3, h = 0.02, k = -0.015;  // [m]
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Matrix3d R = mbs::RotationFromEuler313(3 * u(rng), 1.5 + 1.4 * u(rng), 3 * u(rng));
    mbs::System sys;
    sys.AddBody(Rod(Vector3d(u(rng), u(rng), u(rng)), R));
    const Vector3d p_BA(-0.4, 0.01, 0.0);
    sys.AddMarker("A", "rod", p_BA, Eigen::Matrix3d::Identity());
    sys.AddMarker("B", "rod", p_BA + Vector3d(kLength, 0, 0), Eigen::Matrix3d::Identity());
    sys.AddMarker("P", "rod", p_BA + Vector3d(a, h, k), Eigen::Matrix3d::Identity());
    sys.AddProbe(std::make_shared<mbs::ChordSensor>(sys, "bend", sys.FindMarker("P"),
                                                    sys.FindMarker("A"), sys.FindMarker("B")));
    sys.SetGravity(Vector3d::Zero());
    sys.Finalize();
    const Eigen::VectorXd c = Channels(sys, 0);
    EXPECT_NEAR(c[0], 0.0, kRoundOff) << trial;
    EXPECT_NEAR(c[1], h, kRoundOff) << trial;
    EXPECT_NEAR(c[2], k, kRoundOff) << trial;
    EXPECT_NEAR(c[3], std::hypot(h, k), kRoundOff) << trial;
    EXPECT_NEAR(c[4], a / kLength, kRoundOff) << trial;
  }
}

// The chord on a body turned by theta about world z with end A at the world origin, the
// point on the ground at (x0, y0, z0): the line is through 0 along (cos, sin, 0), so the
// deflection is (0, -x0 sin + y0 cos, z0) in A's axes (the body's, x along the chord) and
// s = (x0 cos + y0 sin) / L.
TEST(ChordSensor, GroundPointAgainstATurnedChord) {
  constexpr double x0 = 0.5, y0 = 0.1, z0 = -0.03;  // [m]
  for (const double theta : {0.0, 0.4, 2.0, -2.9}) {
    mbs::System sys;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, Vector3d::UnitZ()).toRotationMatrix();
    sys.AddBody(Rod(R * Vector3d(kLength / 2, 0, 0), R));
    sys.AddMarker("A", "rod", Vector3d(-kLength / 2, 0, 0), Eigen::Matrix3d::Identity());
    sys.AddMarker("B", "rod", Vector3d(kLength / 2, 0, 0), Eigen::Matrix3d::Identity());
    sys.AddMarker("P", "ground", Vector3d(x0, y0, z0), Eigen::Matrix3d::Identity());
    sys.AddProbe(std::make_shared<mbs::ChordSensor>(sys, "bend", sys.FindMarker("P"),
                                                    sys.FindMarker("A"), sys.FindMarker("B")));
    sys.Finalize();
    const Eigen::VectorXd c = Channels(sys, 0);
    const double dy = -x0 * std::sin(theta) + y0 * std::cos(theta);
    EXPECT_NEAR(c[0], 0.0, kRoundOff) << theta;
    EXPECT_NEAR(c[1], dy, kRoundOff) << theta;
    EXPECT_NEAR(c[2], z0, kRoundOff) << theta;
    EXPECT_NEAR(c[3], std::hypot(dy, z0), kRoundOff) << theta;
    EXPECT_NEAR(c[4], (x0 * std::cos(theta) + y0 * std::sin(theta)) / kLength, kRoundOff) << theta;
  }
}

TEST(ChordSensor, ZeroLengthChordGivesNaN) {
  mbs::System sys;
  sys.AddBody(Rod(Vector3d::Zero(), Eigen::Matrix3d::Identity()));
  sys.AddMarker("A", "rod", Vector3d(0.1, 0, 0), Eigen::Matrix3d::Identity());
  sys.AddMarker("B", "rod", Vector3d(0.1, 0, 0), Eigen::Matrix3d::Identity());
  sys.AddMarker("P", "rod", Vector3d(0, 0.1, 0), Eigen::Matrix3d::Identity());
  sys.AddProbe(std::make_shared<mbs::ChordSensor>(sys, "bend", 2, 0, 1));
  sys.Finalize();
  EXPECT_TRUE(Channels(sys, 0).array().isNaN().all());
}

TEST(ChordSensor, ThreeDifferentMarkersAreRequired) {
  mbs::System sys;
  sys.AddBody(Rod(Vector3d::Zero(), Eigen::Matrix3d::Identity()));
  sys.AddMarker("A", "rod", Vector3d(0.1, 0, 0), Eigen::Matrix3d::Identity());
  sys.AddMarker("B", "rod", Vector3d(0.3, 0, 0), Eigen::Matrix3d::Identity());
  EXPECT_TRUE(
      test::ContainsAll(test::InputErrorMessage([&] { mbs::ChordSensor(sys, "bend", 0, 0, 1); }),
                        {"chord sensor 'bend'", "three different markers", "'A'"}));
  EXPECT_THROW(mbs::ChordSensor(sys, "bend", 0, 1, 7), InputError);
}

}  // namespace
}  // namespace emb
