// The driveline force elements as elements: their analytic stiffness and damping against
// central differences (lash in contact under both laws, the open lash's squeeze film, a
// translational stop, the clutch damper in both stages) at tilted, spinning states; the
// squeeze film's closed form (the speed left when the stop is reached); a translational end
// stop's restitution; the clutch damper's static two-stage deflection; and bad input named.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/driveline/clutch_damper.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "tests/support/force_jacobian_check.h"
#include "tests/support/lash_models.h"

namespace emb::driveline {
namespace {

// Central differences with h = 1e-6 on O(1) coordinates: truncation ~1e-12 x the third
// derivative, round-off ~1e-16/1e-6 of the force; 1e-6 of the largest entry covers both for
// the contact stiffnesses here.
constexpr double kDerivativeTolerance = 1e-6;

Eigen::Matrix3d Tilted(double about_z, double tilt) {
  return (Eigen::AngleAxisd(about_z, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(tilt, Eigen::Vector3d(1, 2, 0).normalized()))
      .toRotationMatrix();
}

// Every force element of `sys` at the bodies' (tilted, spinning) initial state.
void ExpectJacobiansMatch(const mbs::System& sys, const std::string& what) {
  const mbs::StateLayout& L = sys.layout();
  const Eigen::VectorXd q = sys.InitialPositions(), v = sys.InitialVelocities();
  mbs::ConstraintWorkspace ws(sys);  // events inactive: the state the configuration implies
  for (std::size_t k = 0; k < sys.force_elements().size(); ++k) {
    const mbs::ForceElement& fe = *sys.force_elements()[k];
    const int slot = sys.force_angle_slot(static_cast<int>(k));
    const auto bodies = mbs::CalcBodyKinematics(sys, q, v);
    mbs::DenseForceJacobian analytic(L);
    fe.AddForceJacobian({&sys, &bodies, 0.0, &ws, slot}, &analytic);
    const mbs::testing::NumericForceJacobian fd =
        mbs::testing::CentralDifferenceJacobian(sys, static_cast<int>(k), q, v, 0.0, 1e-6, &ws);
    const double scale =
        std::max({1.0, fd.stiffness.cwiseAbs().maxCoeff(), fd.damping.cwiseAbs().maxCoeff()});
    EXPECT_LT((analytic.stiffness() - fd.stiffness).cwiseAbs().maxCoeff(),
              kDerivativeTolerance * scale)
        << what << ": " << fe.name() << " stiffness, scale " << scale;
    EXPECT_LT((analytic.damping() - fd.damping).cwiseAbs().maxCoeff(), kDerivativeTolerance * scale)
        << what << ": " << fe.name() << " damping, scale " << scale;
  }
}

// Two tilted, spinning discs whose lash coordinate x ~ 0.4 - 2 (-0.1) = 0.6 rad sits inside
// the stops or 0.05 rad past one of them.
mbs::System TiltedDiscs(const LashParameters& p) {
  testing::TwoDiscs d;
  mbs::System s = testing::MakeTwoDiscs(d, p, false);
  mbs::System out;
  // Rebuild with poses and 3-D angular velocities (the element does not need the joints).
  std::vector<mbs::RigidBody> bodies = {s.body(1), s.body(2)};
  bodies[0].R_WB = Tilted(0.4, 0.02);
  bodies[1].R_WB = Tilted(-0.1, -0.015);
  bodies[0].omega_W = Eigen::Vector3d(0.3, -0.2, 5.0);
  bodies[1].omega_W = Eigen::Vector3d(-0.1, 0.25, -1.0);
  bodies[0].v_WB = Eigen::Vector3d(0.01, 0.02, 0.0);
  for (const auto& b : bodies) out.AddBody(b);
  for (int m = 0; m < static_cast<int>(s.markers().size()); ++m) {
    const mbs::Marker& mk = s.marker(m);
    out.AddMarker(mk.name, s.body(mk.body).name, mk.p_BM, mk.R_BM);
  }
  out.AddJoint("shaft1", mbs::JointType::kRevolute, "hub1", "bearing1");
  out.AddJoint("shaft2", mbs::JointType::kRevolute, "hub2", "bearing2");
  std::vector<CoordinateTerm> terms = {
      JointCoordinateTerm(out, "shaft1", mbs::JointCoordinate::kRotation, 1.0, "lash"),
      JointCoordinateTerm(out, "shaft2", mbs::JointCoordinate::kRotation, -d.ratio, "lash")};
  out.AddForceElement(std::make_shared<Lash>("mesh", terms, p));
  ClutchDamperParameters c;
  c.stiffness_1 = 150.0;
  c.stiffness_2 = 1500.0;
  c.knee_angle = 0.2;
  c.damping = 0.5;
  c.hysteresis_torque = 8.0;
  c.hysteresis_speed = 2.0;
  out.AddForceElement(std::make_shared<ClutchDamper>("clutch", terms[0], c));  // 2nd stage
  c.knee_angle = 0.6;
  out.AddForceElement(std::make_shared<ClutchDamper>("clutch_idle", terms[0], c));  // 1st
  out.Finalize();
  return out;
}

TEST(LashElement, JacobiansMatchCentralDifferences) {
  for (ContactLawKind kind : {ContactLawKind::kKelvinVoigt, ContactLawKind::kHuntCrossley}) {
    for (int side : {+1, -1}) {
      LashParameters p;
      p.contact.kind = kind;
      p.contact.stiffness = kind == ContactLawKind::kHuntCrossley ? 3e4 : 2e3;
      p.contact.exponent = kind == ContactLawKind::kHuntCrossley ? 1.5 : 1.0;
      p.contact.restitution = 0.6;
      p.contact.effective_mass = 0.01;
      // 0.05 rad into the stop of `side`.
      p.lower = side > 0 ? 0.0 : 0.65;
      p.upper = side > 0 ? 0.55 : 1.0;
      ExpectJacobiansMatch(TiltedDiscs(p),
                           std::string(Name(kind)) + " side " + std::to_string(side));
    }
  }
  // Open, approaching the upper stop (x' = 5 - 2 (-1) > 0) through a squeeze film.
  LashParameters p;
  p.contact.stiffness = 1e4;
  p.lower = 0.0;
  p.upper = 0.61;
  p.squeeze_film = SqueezeFilmParameters{0.05, 0.02, 0.01, 0.03, 1e-6};
  ExpectJacobiansMatch(TiltedDiscs(p), "squeeze film");
}

// A block of mass m on a translational joint along world x, between end stops at
// x = -a and x = +a of a lash on that joint's translation; initial speed v0 along +x.
mbs::System SlidingBlock(double m, double v0, const LashParameters& p) {
  mbs::System s;
  mbs::RigidBody b;
  b.name = "yoke";
  b.mass = m;
  b.inertia_B = 0.01 * Eigen::Matrix3d::Identity();
  b.v_WB = Eigen::Vector3d(v0, 0, 0);
  s.AddBody(b);
  Eigen::Matrix3d z_along_x;
  z_along_x << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  s.AddMarker("spline_hub", "ground", Eigen::Vector3d::Zero(), z_along_x);
  s.AddMarker("spline_sleeve", "yoke", Eigen::Vector3d::Zero(), z_along_x);
  s.AddJoint("spline", mbs::JointType::kTranslational, "spline_sleeve", "spline_hub");
  s.AddForceElement(std::make_shared<Lash>(
      "end_stops",
      std::vector<CoordinateTerm>{JointCoordinateTerm(
          s, "spline", mbs::JointCoordinate::kTranslation, 1.0, "lash 'end_stops'")},
      p));
  s.Finalize();
  return s;
}

TEST(LashElement, TranslationalStopRestitutionAndSqueezeFilmClosedForm) {
  const double m = 1.0, v0 = 1.0, gap = 1e-3;  // [kg], [m/s], [m]
  LashParameters p;
  p.lower = -gap;
  p.upper = gap;
  p.contact.kind = ContactLawKind::kHuntCrossley;
  p.contact.stiffness = 1e9;  // [N/m^1.5]
  p.contact.exponent = 1.5;
  p.contact.restitution = 0.8;
  const mbs::AnalysisSettings st = testing::DynamicSettings(3e-3, 1e-4, 1e-10);
  {
    const mbs::System s = SlidingBlock(m, v0, p);
    const mbs::PreparedRun run = mbs::PrepareRun(s, st);
    const mbs::RunResult r = mbs::RunAnalysis(run, st, [](const mbs::Sample&) {});
    ASSERT_TRUE(r.ok()) << r.message;
    ASSERT_GE(r.events.contacts.size(), 1u);
    EXPECT_NEAR(r.events.contacts[0].t_onset, gap / v0, 1e-10 * gap / v0);
    EXPECT_NEAR(r.events.contacts[0].rebound_velocity, 0.8 * v0, 1e-7);
  }
  // The squeeze film of eq. (A1.5) alone while open: m dv = C h^(-3/2) dh (h falling), so
  // v(h) = v0 - (2 C / m)(h^(-1/2) - h_0^(-1/2)), C = 3 pi b eta r^(3/2) / sqrt 2; the stop
  // closes at h = h_min with that speed.
  SqueezeFilmParameters f;
  f.viscosity = 2.0;  // [Pa s]
  f.width = 0.02;     // [m]
  f.radius = 0.01;    // [m]
  f.lever = 1.0;
  f.min_film = 1e-6;  // [m]
  p.squeeze_film = f;
  const double C =
      3.0 * std::numbers::pi * f.width * f.viscosity / std::sqrt(2.0) * std::pow(f.radius, 1.5);
  const double v_contact =
      v0 - 2.0 * C / m * (1.0 / std::sqrt(f.min_film) - 1.0 / std::sqrt(gap + f.min_film));
  ASSERT_GT(v_contact, 0.2 * v0);
  ASSERT_LT(v_contact, 0.8 * v0);
  const mbs::System s = SlidingBlock(m, v0, p);
  const mbs::RunResult r = mbs::RunAnalysis(mbs::PrepareRun(s, st), st, [](const mbs::Sample&) {});
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GE(r.events.contacts.size(), 1u);
  EXPECT_NEAR(r.events.contacts[0].impact_velocity, v_contact, 1e-6 * v0);
}

TEST(LashElement, ClutchDamperStaticDeflectionInBothStages) {
  // Disc 1 held by the damper to the ground (through its joint angle), loaded by a torque:
  // theta = T/k1 below the knee, theta_k + (T - k1 theta_k)/k2 beyond, about the free angle
  // a_0 (signed, issue 36: a negative a_0 is the unloaded spring on the other side of the
  // joint's zero, and the characteristic moves with it).
  const double k1 = 150.0, k2 = 1500.0, knee = 0.05;
  for (const double a0 : {0.0, -0.3})
  for (double T : {5.0, 60.0}) {
    testing::TwoDiscs d;
    d.omega1 = 0.0;
    d.torque1 = T;
    LashParameters p;
    p.contact.stiffness = 1e4;
    p.lower = -10.0;
    p.upper = 10.0;
    mbs::System s = testing::MakeTwoDiscs(d, p, false);
    ClutchDamperParameters c;
    c.stiffness_1 = k1;
    c.stiffness_2 = k2;
    c.knee_angle = knee;
    c.hysteresis_torque = 3.0;
    c.free_angle = a0;
    s.AddForceElement(std::make_shared<ClutchDamper>(
        "clutch", JointCoordinateTerm(s, "shaft1", mbs::JointCoordinate::kRotation, 1.0, "c"), c));
    s.Finalize();
    mbs::AnalysisSettings st;
    st.type = mbs::AnalysisType::kStatic;
    mbs::Sample out;
    const mbs::RunResult r =
        mbs::RunAnalysis(mbs::PrepareRun(s, st), st, [&](const mbs::Sample& smp) { out = smp; });
    ASSERT_TRUE(r.ok()) << r.message;
    const double theta = 2.0 * std::atan2(out.q[6], out.q[3]);
    const double expected = a0 + (T / k1 <= knee ? T / k1 : knee + (T - k1 * knee) / k2);
    EXPECT_NEAR(theta, expected, 1e-9) << "T " << T << ", a0 " << a0;
  }
}

template <class F>
void ExpectInputError(F f, const std::string& w1, const std::string& w2) {
  try {
    f();
    FAIL() << "expected an InputError with " << w1 << ", " << w2;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(w1), std::string::npos) << m;
    EXPECT_NE(m.find(w2), std::string::npos) << m;
  }
}

TEST(LashElement, BadInputIsNamed) {
  testing::TwoDiscs d;
  LashParameters p;
  p.contact.stiffness = 1e4;
  p.lower = 0.01;
  p.upper = -0.01;  // a negative lash
  ExpectInputError([&] { testing::MakeTwoDiscs(d, p); }, "lash 'mesh'", "lash");
  p.upper = 0.02;
  p.contact.restitution = 1.5;
  ExpectInputError([&] { testing::MakeTwoDiscs(d, p); }, "lash 'mesh'", "restitution");
  p.contact.restitution = 0.5;
  // A gear ratio of 0 (x would not see joint2), and joint2 the same coordinate as joint1 (x
  // would be (1 - ratio) g1).
  d.ratio = 0.0;
  ExpectInputError([&] { testing::MakeTwoDiscs(d, p); }, "lash 'mesh'", "non-zero");
  d.ratio = 2.0;
  ExpectInputError(
      [&] {
        mbs::System s = testing::MakeTwoDiscs(d, p, false);
        const CoordinateTerm g = JointCoordinateTerm(s, "shaft1", mbs::JointCoordinate::kRotation,
                                                     1.0, "lash 'twice'");
        CoordinateTerm h = g;
        h.coeff = -2.0;
        Lash("twice", {g, h}, p);
      },
      "lash 'twice'", "same coordinate");
  // A rotation of a translational joint: the joint has no such coordinate.
  ExpectInputError(
      [&] {
        LashParameters q = p;
        SlidingBlock(1.0, 0.0, q);  // fine: translation
        mbs::System s = SlidingBlock(1.0, 0.0, q);
        (void)JointCoordinateTerm(s, "spline", mbs::JointCoordinate::kRotation, 1.0,
                                  "lash 'spline_twist'");
      },
      "lash 'spline_twist'", "rotation");
  ExpectInputError(
      [&] {
        mbs::System s = SlidingBlock(1.0, 0.0, p);
        (void)JointCoordinateTerm(s, "splin", mbs::JointCoordinate::kTranslation, 1.0,
                                  "lash 'stops'");
      },
      "lash 'stops'", "spline");
  ClutchDamperParameters c;
  c.stiffness_1 = 100.0;
  c.knee_angle = -0.1;
  ExpectInputError(
      [&] {
        mbs::System s = SlidingBlock(1.0, 0.0, p);
        ClutchDamper("disc",
                     JointCoordinateTerm(s, "spline", mbs::JointCoordinate::kTranslation, 1.0, "c"),
                     c);
      },
      "clutch damper 'disc'", "rotation");
}

}  // namespace
}  // namespace emb::driveline
