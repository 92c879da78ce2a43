// The cycle-averaged linearisation of a Campbell diagram (cycle_average.h, issue 17) on a
// slider-crank with a closed form: a rigid crank (polar inertia Jc, balanced) on a revolute
// bearing, tied to a hub driven at Omega by a torsional spring k; a rigid rod (mass mr,
// inertia Ir about its centre of mass at a from the big end, length l) and a piston (mp) in a
// bore along z. One degree of freedom, the crank's twist phi against the hub, with the
// equivalent inertia of the exact slider-crank kinematics
//   J(theta) = Jc + mp s'(theta)^2 + mr |x_cm'(theta)|^2 + Ir beta'(theta)^2
// (s the piston's height, x_cm the rod's centre of mass, beta its angle; ' = d/dtheta). The
// averaged system's frequency is sqrt(k / <J>) / 2 pi, <J> the mean over a revolution
// (= Jc + mp r^2 (1/2 + lambda^2/8 + ...) + ..., lambda = r / l), computed here by quadrature
// of the exact kinematics; the frozen linearisation at top dead centre sees J(0) = Jc + Ir
// (r / l)^2 + mr (r (l - a) / l)^2 (the piston does not move).

#include "libemb/mbs/linear/cycle_average.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/mbs/linear/campbell.h"
#include "libemb/mbs/forces/bushing.h"

namespace emb {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

constexpr double kJc = 0.05;              // [kg m^2] crank (and flywheel) about x
constexpr double kR = 0.05, kL = 0.15;    // [m] crank radius, rod length (lambda = 1/3)
constexpr double kMp = 2.0;               // [kg] piston
constexpr double kMr = 1.0, kA = kL / 3;  // [kg] rod, [m] its centre of mass from the big end
constexpr double kIr = 4e-3;              // [kg m^2] rod about its centre of mass (x)
constexpr double kTorsion = 2e4;          // [N m / rad] crank to hub

// Marker axes (columns in W) with z along `z` and x along `x` (unit, orthogonal).
Matrix3d Axes(const Vector3d& z, const Vector3d& x) {
  Matrix3d R;
  R << x, z.cross(x), z;
  return R;
}
const Matrix3d kAxisX = Axes(Vector3d::UnitX(), Vector3d::UnitY());  // crank axis
const Matrix3d kAxisZ = Axes(Vector3d::UnitZ(), Vector3d::UnitX());  // bore

mbs::RigidBody Body(const std::string& name, double mass, const Vector3d& inertia,
                    const Vector3d& p, const Vector3d& v, double omega_x) {
  mbs::RigidBody b;
  b.name = name;
  b.mass = mass;
  b.inertia_B = inertia.asDiagonal();
  b.p_WB = p;
  b.v_WB = v;
  b.omega_W = Vector3d(omega_x, 0, 0);
  return b;
}

// The slider-crank at top dead centre (pin at +z), running at `rpm` about +x.
mbs::System SliderCrank(double rpm) {
  const double W = 2 * kPi * rpm / 60.0;
  mbs::System sys;
  sys.SetGravity(Vector3d::Zero());
  sys.AddBody(Body("hub", 1.0, Vector3d(0.01, 0.01, 0.01), Vector3d::Zero(), Vector3d::Zero(), W));
  sys.AddBody(Body("crank", 5.0, Vector3d(kJc, 0.03, 0.03), Vector3d::Zero(), Vector3d::Zero(), W));
  // At TDC the pin moves at -W r along y, the piston is at rest, the rod turns at -W r / l.
  const double w_rod = -W * kR / kL;
  sys.AddBody(Body("rod", kMr, Vector3d(kIr, kIr, 1e-4), Vector3d(0, 0, kR + kA),
                   Vector3d(0, -W * kR * (1 - kA / kL), 0), w_rod));
  sys.AddBody(Body("piston", kMp, Vector3d(2e-3, 2e-3, 2e-3), Vector3d(0, 0, kR + kL),
                   Vector3d::Zero(), 0.0));
  sys.AddMarker("hub_axis", "hub", Vector3d::Zero(), kAxisX);
  sys.AddMarker("frame_axis", "ground", Vector3d::Zero(), kAxisX);
  sys.AddMarker("crank_axis", "crank", Vector3d::Zero(), kAxisX);
  sys.AddMarker("crank_pin", "crank", Vector3d(0, 0, kR), kAxisX);
  sys.AddMarker("rod_big", "rod", Vector3d(0, 0, -kA), kAxisX);
  sys.AddMarker("rod_small", "rod", Vector3d(0, 0, kL - kA), kAxisX);
  sys.AddMarker("piston_pin", "piston", Vector3d::Zero(), kAxisX);
  sys.AddMarker("piston_axis", "piston", Vector3d::Zero(), kAxisZ);
  sys.AddMarker("bore", "ground", Vector3d::Zero(), kAxisZ);
  sys.AddJoint("hub_bearing", mbs::JointType::kRevolute, "hub_axis", "frame_axis");
  sys.AddMotion("drive", "hub_bearing", mbs::JointCoordinate::kRotation,
                mbs::TimeFunction::Polynomial({0.0, W}));
  sys.AddJoint("main_bearing", mbs::JointType::kRevolute, "crank_axis", "frame_axis");
  sys.AddJoint("big_end", mbs::JointType::kInLine, "crank_pin", "rod_big");
  sys.AddJoint("wrist_pin", mbs::JointType::kRevolute, "rod_small", "piston_pin");
  sys.AddJoint("bore_slide", mbs::JointType::kTranslational, "piston_axis", "bore");
  Eigen::Matrix<double, 6, 6> k = Eigen::Matrix<double, 6, 6>::Zero();
  k(5, 5) = kTorsion;  // the bushing's rotation about its z (the crank axis)
  sys.AddForceElement(std::make_shared<mbs::Bushing>("torsion_spring", sys.FindMarker("crank_axis"),
                                                     sys.FindMarker("hub_axis"), k,
                                                     Eigen::Matrix<double, 6, 6>::Zero()));
  sys.Finalize();
  return sys;
}

// J(theta) of the file comment from the exact kinematics (central differences, step 1e-6 rad:
// error ~1e-12 relative).
double EquivalentInertia(double theta) {
  struct Pose {
    double s, ycm, zcm, beta;
  };
  auto pose = [](double th) {
    const double py = -kR * std::sin(th), pz = kR * std::cos(th);
    const double s = pz + std::sqrt(kL * kL - py * py);  // piston height (y = 0)
    return Pose{s, py + kA / kL * (0 - py), pz + kA / kL * (s - pz), std::atan2(-py, s - pz)};
  };
  constexpr double h = 1e-6;
  const Pose a = pose(theta + h), b = pose(theta - h);
  const double ds = (a.s - b.s) / (2 * h), dy = (a.ycm - b.ycm) / (2 * h);
  const double dz = (a.zcm - b.zcm) / (2 * h), db = (a.beta - b.beta) / (2 * h);
  return kJc + kMp * ds * ds + kMr * (dy * dy + dz * dz) + kIr * db * db;
}

// The mean of J over a revolution: the trapezoidal rule on a periodic smooth function
// converges geometrically; 4000 points are exact to round-off.
double MeanInertia() {
  constexpr int n = 4000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += EquivalentInertia(2 * kPi * i / n);
  return sum / n;
}

double Hz(double inertia) { return std::sqrt(kTorsion / inertia) / (2 * kPi); }

mbs::OperatingPointModes ModesAt(double rpm, mbs::Linearisation lin, int angles) {
  mbs::OperatingPointOptions o;
  o.linearisation = lin;
  o.num_angles = angles;
  return mbs::CalcOperatingPointModes(SliderCrank(rpm), mbs::AnalysisSettings{}, rpm, "crank",
                                      1000.0, o);
}

double TorsionHz(double rpm, mbs::Linearisation lin, int angles) {
  const mbs::OperatingPointModes m = ModesAt(rpm, lin, angles);
  EXPECT_EQ(m.point.modes.frequencies_hz.size(), 1) << rpm << " rpm: one degree of freedom";
  return m.point.modes.frequencies_hz.size() ? m.point.modes.frequencies_hz[0] : 0.0;
}

constexpr auto kAverage = mbs::Linearisation::kCycleAverage;
constexpr auto kFrozen = mbs::Linearisation::kFrozen;

// Slow (60 rpm: the inertia forces Omega^2 mp r ~ 0.2 N do not stiffen the 2e4 N m/rad
// spring): the averaged model's frequency is sqrt(k / <J>) up to what remains of the speed's
// effects, which scale with Omega^2 and are 2.6e-4 at 3000 rpm (Omega / omega = 0.52), i.e.
// 1e-7 here; and the quadrature's aliasing (harmonic 32, lambda^30 ~ 1e-14).
constexpr double kSlowTolerance = 1e-6;
// At 3000 rpm the averaged model is the mean-inertia answer to this: the part of the periodic
// inertia forces that the averaging keeps (the T' terms of cycle_average.cpp) cancels to
// 2.6e-4 (measured; without them the average of the frozen models is 1.2 % high).
constexpr double kFastTolerance = 1e-3;

TEST(CycleAverage, SlowSliderCrankHasTheMeanInertia) {
  const double averaged = TorsionHz(60.0, kAverage, 32);
  EXPECT_NEAR(averaged / Hz(MeanInertia()), 1.0, kSlowTolerance);
  // The frozen linearisation at top dead centre: the piston adds nothing, the frequency is
  // 3 % higher (and its own closed form: J(0) with the same O(Omega^2) remainder, 1.2e-5).
  const double frozen = TorsionHz(60.0, kFrozen, 1);
  EXPECT_NEAR(frozen / Hz(EquivalentInertia(0.0)), 1.0, 1e-4);
  EXPECT_GT(frozen / averaged - 1.0, 0.02);
}

TEST(CycleAverage, FastSliderCrankHasTheMeanInertia) {
  const mbs::OperatingPointModes m = ModesAt(3000.0, kAverage, 16);
  ASSERT_EQ(m.point.modes.frequencies_hz.size(), 1);
  const double f = m.point.modes.frequencies_hz[0];
  EXPECT_NEAR(f / Hz(MeanInertia()), 1.0, kFastTolerance);
  // The frozen models of the 16 angles bracket it: their spread is the periodic part.
  ASSERT_EQ(m.point.hz_angle_min.size(), 1);
  EXPECT_LT(m.point.hz_angle_min[0], f);
  EXPECT_GT(m.point.hz_angle_max[0], f);
  EXPECT_GT((m.point.hz_angle_max[0] - m.point.hz_angle_min[0]) / f, 0.05)
      << "J varies by ~11 % over the revolution";
  EXPECT_GT(TorsionHz(3000.0, kFrozen, 1) / f - 1.0, 0.05);
}

// The Campbell default's criterion (campbell.h): < 0.1 % change when the angles double.
constexpr double kAngleConvergence = 1e-3;

TEST(CycleAverage, ConvergesInTheNumberOfAngles) {
  // The equivalent inertia's harmonics fall like lambda^n: 4 angles are 1e-3 off, 8 are 4e-6
  // off, 16 and 32 agree to round-off (measured: 96.1935, 96.2892, 96.28957, 96.28957 Hz).
  const double f4 = TorsionHz(3000.0, kAverage, 4), f8 = TorsionHz(3000.0, kAverage, 8);
  const double f16 = TorsionHz(3000.0, kAverage, 16), f32 = TorsionHz(3000.0, kAverage, 32);
  EXPECT_LT(std::abs(f16 / f32 - 1.0), kAngleConvergence);
  EXPECT_LT(std::abs(f8 / f16 - 1.0), kAngleConvergence);
  EXPECT_LT(std::abs(f16 / f32 - 1.0), std::abs(f4 / f16 - 1.0)) << "converging";
}

// One angle is the frozen model in other coordinates (v = T y, a similarity): the same
// eigenvalues to round-off of the dense eigen-solves.
constexpr double kSameModelTolerance = 1e-10;

TEST(CycleAverage, OneAngleIsTheFrozenLinearisation) {
  for (double rpm : {60.0, 3000.0}) {
    const mbs::OperatingPointModes a = ModesAt(rpm, kAverage, 1);
    const mbs::OperatingPointModes b = ModesAt(rpm, kFrozen, 1);
    ASSERT_EQ(a.point.modes.frequencies_hz.size(), b.point.modes.frequencies_hz.size());
    for (Eigen::Index j = 0; j < a.point.modes.frequencies_hz.size(); ++j)
      EXPECT_NEAR(a.point.modes.frequencies_hz[j] / b.point.modes.frequencies_hz[j], 1.0,
                  kSameModelTolerance)
          << rpm << " rpm";
    EXPECT_EQ(b.point.hz_angle_min.size(), 0) << "the frozen linearisation has no spread";
  }
}

TEST(CycleAverage, NamesAndBadInput) {
  EXPECT_EQ(mbs::ParseLinearisation("frozen"), kFrozen);
  EXPECT_EQ(mbs::ParseLinearisation("cycle-average"), kAverage);
  EXPECT_STREQ(mbs::Name(kAverage), "cycle-average");
  EXPECT_THROW(mbs::ParseLinearisation("floquet"), InputError);
  EXPECT_THROW(ModesAt(3000.0, kAverage, 0), InputError);
}

}  // namespace
}  // namespace emb
