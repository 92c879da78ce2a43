// The finite-width Reynolds bearing as a force element (film_bearing.h):
//  - the kinematics' chain rule (e, gamma and their rates, the journal speed) against central
//    differences of the markers' motion;
//  - without film states (Swift-Stieber): the force Jacobian, total derivatives through the
//    film solve's adjoint, against central differences;
//  - with film states (JFO): the GGL iteration matrix, film rows and columns included,
//    against central differences of the residual;
//  - a spinning rotor under its weight, on a planar joint, settles where the film carries
//    the weight (checked by the film solver alone at the final position), with and without
//    film states; the pair of loads is internal (the shell is the ground here);
//  - the journal driven into the shell is a failed run naming the bearing and the time.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/engine/film_bearing.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/tribology/film_solver.h"
#include "tests/support/force_jacobian_check.h"
#include "tests/support/posed_bodies.h"

namespace emb::mbs {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using tribology::CavitationModel;
constexpr double kPi = std::numbers::pi;

// A passenger-car main bearing (R = 30 mm, L = 20 mm, c = 30 um, mu = 8.6 mPa s) on a coarse
// grid: the element's algebra does not depend on the grid's resolution.
tribology::ReynoldsBearingParameters Main(CavitationModel model, int n = 24, int nz = 6) {
  tribology::ReynoldsBearingParameters p;
  p.radius = 0.03;
  p.length = 0.02;
  p.clearance = 30e-6;
  p.grid = {n, nz};
  p.lubricant.viscosity = 0.0086;
  p.cavitation = model;
  return p;
}

// Main with a hole in the journal (the journal angle's chain rule enters the forces).
tribology::ReynoldsBearingParameters FedMain(CavitationModel model, int n = 24, int nz = 6) {
  tribology::ReynoldsBearingParameters p = Main(model, n, nz);
  p.journal_oil_holes.push_back({1.0, 1e-3, 5e-3, 3e5});
  return p;
}
constexpr double kOmega = 3000.0 * 2.0 * kPi / 60.0;

using testing::Pose;

// Markers off the bodies' centres so that every arm matters.
const Vector3d kShellOffset(0.01, -0.02, 0.005), kJournalOffset(-0.015, 0.01, 0.02);
const Eigen::Matrix3d kShellAxes = RotationFromEuler313(0.2, 0.1, -0.3);

// Journal "pin" in shell "eye", both free bodies; the pin's journal marker at eccentricity e
// (shell axes) with tilt (gamma_x, gamma_y), the pin turning at `spin` about the bore axis.
System PinInEye(const tribology::ReynoldsBearingParameters& bp, const Vector2d& e,
                const Vector2d& gamma, const Pose& eye, double spin, const Vector3d& pin_v) {
  const Eigen::Matrix3d R_shell = eye.R * kShellAxes;
  const Vector3d p_shell = eye.p + eye.R * kShellOffset;
  // Journal axis (gamma_x, gamma_y, 1) in the shell's axes: turn by gamma_x about y_S, then by
  // -gamma_y about x_S (small angles; the element reads the exact a_xy / a_z).
  const Eigen::Matrix3d R_journal =
      R_shell * (Eigen::AngleAxisd(-gamma.y(), Vector3d::UnitX()) *
                 Eigen::AngleAxisd(gamma.x(), Vector3d::UnitY()))
                    .toRotationMatrix();
  Pose pin;
  pin.R = R_journal;
  pin.p = p_shell + R_shell * Vector3d(e.x(), e.y(), 0.0) - R_journal * kJournalOffset;
  pin.w = eye.w + spin * R_journal.col(2) + Vector3d(0.3, -0.2, 0.1);
  pin.v = pin_v;
  System s;
  testing::AddPosedBodies(&s, {{"eye", eye}, {"pin", pin}});
  s.AddMarker("shell", "eye", kShellOffset, kShellAxes);
  s.AddMarker("journal", "pin", kJournalOffset, Eigen::Matrix3d::Identity());
  s.AddForceElement(std::make_shared<FilmBearing>("big_end", s.FindMarker("journal"),
                                                  s.FindMarker("shell"), bp));
  s.Finalize();
  return s;
}

Pose MovingEye() {
  Pose eye;
  eye.p = Vector3d(0.1, -0.05, 0.02);
  eye.R = RotationFromEuler313(0.4, 0.3, -0.2);
  eye.v = Vector3d(0.05, -0.02, 0.03);
  eye.w = Vector3d(0.5, -1.0, 3.0);
  return eye;
}

TEST(FilmBearing, KinematicsChainRuleMatchesCentralDifferences) {
  const System s = PinInEye(Main(CavitationModel::kReynolds), Vector2d(8e-6, -5e-6),
                            Vector2d(4e-4, -2.5e-4), MovingEye(), kOmega,
                            Vector3d(-0.004, 0.006, 0.001));
  const Eigen::VectorXd q = s.InitialPositions(), v = s.InitialVelocities();
  const StateLayout& L = s.layout();
  auto motion = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv, bool derivatives) {
    const auto bodies = CalcBodyKinematics(s, qq, vv);
    std::vector<MarkerKinematics> markers;
    CalcAllMarkerKinematics(s, bodies, &markers);
    FilmBearing::Motion m;
    EXPECT_TRUE(CalcFilmBearingMotion(markers[s.FindMarker("journal")],
                                      markers[s.FindMarker("shell")], derivatives, &m));
    return m;
  };
  auto stack = [](const FilmBearing::Motion& m) {
    Eigen::Matrix<double, 11, 1> y;
    y << m.kin.eccentricity, m.kin.tilt, m.kin.journal_angle, m.kin.eccentricity_rate,
        m.kin.tilt_rate, m.kin.journal_speed, m.kin.shell_speed;
    return y;
  };
  const FilmBearing::Motion m = motion(q, v, true);
  EXPECT_NEAR(m.kin.eccentricity.x(), 8e-6, 1e-15);
  EXPECT_NEAR(m.kin.tilt.y(), -2.5e-4, 1e-9);  // small-angle construction: O(gamma^2)
  // Both bodies are rigid with markers on them: slot 0 = the pin's [dp, dpi], slot 1 the eye's
  // (body order eye = 1, pin = 2 in the layout's velocity numbering).
  const int pin = L.velocity(s.FindBody("pin")), eye = L.velocity(s.FindBody("eye"));
  const double h = 1e-7;
  for (int j = 0; j < 12; ++j) {
    const int col = j < 6 ? pin + j : eye + j - 6;
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(L.nv());
    dx[col] = h;
    const Eigen::Matrix<double, 11, 1> dq =
        (stack(motion(ApplyDisplacement(s, q, dx), v, false)) -
         stack(motion(ApplyDisplacement(s, q, -dx), v, false))) / (2 * h);
    const Eigen::Matrix<double, 11, 1> dv =
        (stack(motion(q, v + dx, false)) - stack(motion(q, v - dx, false))) / (2 * h);
    Eigen::Matrix<double, 11, 1> aq, av;
    aq << m.position_x.col(j), m.velocity_x.col(j);
    av << Eigen::Matrix<double, 5, 1>::Zero(), m.velocity_v.col(j);
    // Entries of order 1 (rates by angles: ~300 rad/s); h = 1e-7 gives truncation ~1e-14 x
    // third derivatives and cancellation ~1e-9 absolute.
    constexpr double kChainRuleTolerance = 1e-6;
    EXPECT_LT((aq - dq).cwiseAbs().maxCoeff(), kChainRuleTolerance * std::max(1.0, dq.cwiseAbs().maxCoeff()))
        << "column " << j << "\n" << aq.transpose() << "\n" << dq.transpose();
    EXPECT_LT((av - dv).cwiseAbs().maxCoeff(), kChainRuleTolerance * std::max(1.0, dv.cwiseAbs().maxCoeff()))
        << "column " << j << "\n" << av.transpose() << "\n" << dv.transpose();
  }
}

TEST(FilmBearing, ForceJacobianWithoutStatesMatchesCentralDifferences) {
  for (const Vector2d& e : {Vector2d(9e-6, -12e-6), Vector2d(-15e-6, 4e-6)}) {
    const System s = PinInEye(FedMain(CavitationModel::kReynolds), e, Vector2d(3e-4, -2e-4),
                              MovingEye(), kOmega, Vector3d(-0.004, 0.006, 0.001));
    ASSERT_EQ(s.num_force_states(), 0);
    const Eigen::VectorXd q = s.InitialPositions(), v = s.InitialVelocities();
    const auto bodies = CalcBodyKinematics(s, q, v);
    DenseForceJacobian analytic(s.layout());
    s.force_elements()[0]->AddForceJacobian({&s, &bodies, 0.0, nullptr, -1}, &analytic);
    // Steps of 1e-9 m (3e-5 of the clearance) and 1e-9 rad: the film is re-solved to round-off
    // at each, so the differences hold ~1e-7 relative; a change of the cavitation boundary
    // inside a step would show as a far larger error.
    const auto fd = testing::CentralDifferenceJacobian(s, 0, q, v, 0.0, 1e-9, nullptr);
    const double scale_k = fd.stiffness.cwiseAbs().maxCoeff();
    const double scale_d = fd.damping.cwiseAbs().maxCoeff();
    EXPECT_GT(scale_k, 1e6);  // N/m: a film, not a zero
    constexpr double kDerivativeTolerance = 1e-5;
    EXPECT_LT((analytic.stiffness() - fd.stiffness).cwiseAbs().maxCoeff(), kDerivativeTolerance * scale_k);
    EXPECT_LT((analytic.damping() - fd.damping).cwiseAbs().maxCoeff(), kDerivativeTolerance * scale_d);
  }
}

TEST(FilmBearing, IterationMatrixWithFilmStatesMatchesCentralDifferences) {
  const System s = PinInEye(FedMain(CavitationModel::kMassConserving, 16, 4), Vector2d(9e-6, -12e-6),
                            Vector2d(3e-4, -2e-4), MovingEye(), kOmega,
                            Vector3d(-0.004, 0.006, 0.001));
  const int n = 16 * 3;
  ASSERT_EQ(s.num_force_states(), n);
  const GglDae dae(s);
  AnalysisSettings settings;
  const PreparedRun run = PrepareRun(s, settings);
  ThrowIfNotReady(run, "film bearing test");
  const AccelerationSolution acc = SolveAccelerations(s, run.q0, run.v0, 0.0, &dae.workspace());
  Eigen::VectorXd y, yp;
  dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &y, &yp);
  const GglLayout& G = dae.ggl_layout();
  ASSERT_EQ(G.nz(), n);
  // The quasi-static film start: a zero film residual with u' = 0.
  Eigen::VectorXd r(dae.size());
  ASSERT_TRUE(dae.CalcResidual(0.0, y, yp, r));
  const double flow_scale = r.segment(G.z(), n).cwiseAbs().maxCoeff();
  int cavitated = 0;
  for (int k = 0; k < n; ++k) cavitated += y[G.z() + k] < 0.0;
  EXPECT_GT(cavitated, 0) << "the film has no cavity: the fill-fraction columns go untested";
  EXPECT_LT(flow_scale, 1e-12) << "m^3/s";  // round-off of flows ~1e-6 m^3/s
  // Off the solution: the film states and rates moved, the bodies moved within the clearance.
  for (int k = 0; k < n; ++k) {
    double& u = y[G.z() + k];
    u += 0.05 * std::sin(1.0 + k) * (u < 0.0 ? -u : 1.0);  // no state crosses u = 0
    yp[G.z() + k] += 200.0 * std::cos(2.0 + k);
  }
  for (int i = 0; i < G.v(); ++i) yp[i] += 1e-4 * std::sin(3.0 + i);
  const double cj = 3456.0, t = 0.001;
  Eigen::MatrixXd J(dae.size(), dae.size());
  ASSERT_TRUE(dae.CalcJacobian(t, cj, y, yp, J));
  // Steps per column by the unknown's scale (positions 1e-10 m, rotations and u 1e-8, rates
  // 1e-6): the differences of each column are compared as changes per step, row by row.
  const int N = dae.size();
  Eigen::VectorXd step = Eigen::VectorXd::Constant(N, 1e-6);
  for (int i = 0; i < G.nq(); ++i) step[G.q() + i] = 1e-9;
  for (int k = 0; k < n; ++k) step[G.z() + k] = 1e-8;
  Eigen::MatrixXd dJ(N, N), aJ(N, N);
  for (int j = 0; j < N; ++j) {
    Eigen::VectorXd y1 = y, y2 = y, yp1 = yp, yp2 = yp, r1(N), r2(N);
    y1[j] += step[j];
    y2[j] -= step[j];
    yp1[j] += cj * step[j];
    yp2[j] -= cj * step[j];
    ASSERT_TRUE(dae.CalcResidual(t, y1, yp1, r1));
    ASSERT_TRUE(dae.CalcResidual(t, y2, yp2, r2));
    dJ.col(j) = (r1 - r2) / 2.0;
    aJ.col(j) = J.col(j) * step[j];
  }
  // Changes per step, relative to the row's largest: truncation (second order in the step)
  // and the film's round-off both below 1e-6 of it.
  constexpr double kIterationMatrixTolerance = 1e-5;
  for (int i = 0; i < N; ++i) {
    const double scale = dJ.row(i).cwiseAbs().maxCoeff();
    if (scale == 0.0) continue;
    Eigen::Index col = 0;
    const double err = (aJ.row(i) - dJ.row(i)).cwiseAbs().maxCoeff(&col);
    EXPECT_LT(err, kIterationMatrixTolerance * scale)
        << "row " << dae.ComponentName(i) << ", column " << dae.ComponentName(col) << ": "
        << aJ(i, col) << " vs " << dJ(i, col);
  }
}

// A rotor of 100 kg (981 N: Sommerfeld number ~0.3) spinning at 3000 rpm in the main bearing,
// held in the bearing plane by a planar joint to the ground (which carries the shell).
System Rotor(const tribology::ReynoldsBearingParameters& bp, const Vector2d& e0) {
  System s;
  RigidBody b;
  b.name = "rotor";
  b.mass = 100.0;
  b.inertia_B = Vector3d(6.0, 6.0, 10.0).asDiagonal();  // large polar inertia: the friction
  b.p_WB = Vector3d(e0.x(), e0.y(), 0.0);                // torque hardly slows it
  b.omega_W = Vector3d(0.0, 0.0, kOmega);
  s.AddBody(b);
  s.AddMarker("journal", "rotor", Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddMarker("bore", "ground", Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddJoint("plane", JointType::kPlanar, "journal", "bore");
  s.AddForceElement(std::make_shared<FilmBearing>("main", s.FindMarker("journal"),
                                                  s.FindMarker("bore"), bp));
  s.SetGravity(Vector3d(0.0, -9.81, 0.0));
  s.Finalize();
  return s;
}

// The two ways a film is in a run: quasi-static (Swift-Stieber) or as states (JFO).
std::string ModelName(const ::testing::TestParamInfo<CavitationModel>& info) {
  return info.param == CavitationModel::kReynolds ? "SwiftStieber" : "JfoStates";
}

class FilmBearingRotor : public ::testing::TestWithParam<CavitationModel> {};

TEST_P(FilmBearingRotor, SettlesWhereTheFilmCarriesTheWeight) {
  // An oil hole (6 mm, 0.3 MPa) on the unloaded side: without a supply the mass-conserving
  // film drains through its edges and the journal sinks towards the shell (as it should).
  // With film states this run crosses film rupture and reformation; with an incompressible
  // full film (film_dae.h, kappa = 0) its corrector cycled there until the step was 1e-10 s.
  tribology::ReynoldsBearingParameters bp = Main(GetParam());
  bp.oil_holes.push_back({kPi / 2, 0.0, 6e-3, 0.3e6});
  const System s = Rotor(bp, Vector2d(0.0, -5e-6));
  AnalysisSettings settings;
  settings.type = AnalysisType::kDynamic;
  settings.t_end = 0.15;  // the whirl decays in ~20 ms (squeeze damping)
  settings.output_step = 0.005;
  settings.ida.rtol = 1e-7;
  const PreparedRun run = PrepareRun(s, settings);
  ThrowIfNotReady(run, "rotor");
  const int b = s.FindBody("rotor");
  Vector2d e = Vector2d::Zero(), e_prev = Vector2d::Zero();
  const RunResult result = RunAnalysis(run, settings, [&](const Sample& smp) {
    e_prev = e;
    e = smp.q.segment<2>(s.layout().position(b));
  });
  ASSERT_TRUE(result.ok()) << result.message;
  const double c = bp.clearance;
  EXPECT_GT(e.norm(), 0.2 * c);  // the film carries 981 N at a real eccentricity
  EXPECT_LT(e.norm(), 0.8 * c);
  EXPECT_LT((e - e_prev).norm(), 1e-4 * c) << "not settled";
  // The film alone at that position (steady, no squeeze): its force balances the weight.
  tribology::ReynoldsBearing bearing("check", bp);
  tribology::FilmSolver solver(bearing);
  tribology::JournalKinematics kin;
  kin.eccentricity = e;
  kin.journal_speed = kOmega;
  tribology::BearingLoads loads;
  ASSERT_TRUE(solver.SolveQuasiStatic(kin, &loads).ok());
  const double W = 100.0 * 9.81;
  // The run's last sample is settled to 1e-4 c; the film's stiffness ~W / (0.3 c) turns that
  // into ~3e-4 W, the integrator's error (rtol 1e-7) into less.
  constexpr double kBalanceTolerance = 2e-3;
  EXPECT_NEAR(loads.force.x(), 0.0, kBalanceTolerance * W);
  EXPECT_NEAR(loads.force.y(), W, kBalanceTolerance * W);
  // The journal sits off the load line, turned in the direction of rotation (attitude > 0).
  EXPECT_GT(e.x(), 0.1 * e.norm());
}

INSTANTIATE_TEST_SUITE_P(Models, FilmBearingRotor,
                         ::testing::Values(CavitationModel::kReynolds,
                                           CavitationModel::kMassConserving),
                         ModelName);

// The film rotor's first 20 ms (the journal falls from near the centre, the cavity forms)
// with IDA's own corrector and with the refreshing one (AnalysisSettings::newton_refreshes,
// the default with film states): the same motion, with fewer corrector failures and steps
// (measured: 630 failures and 1,417 steps against 128 and 730).
TEST(FilmBearing, RefreshingCorrectorCrossesTheFilmsSwitchesWithFewerFailures) {
  tribology::ReynoldsBearingParameters bp = Main(CavitationModel::kMassConserving);
  bp.oil_holes.push_back({kPi / 2, 0.0, 6e-3, 0.3e6});
  bp.switch_width = 0.01;
  const System s = Rotor(bp, Vector2d(0.0, -5e-6));
  auto run = [&](int refreshes) {
    AnalysisSettings settings;
    settings.type = AnalysisType::kDynamic;
    settings.t_end = 0.02;
    settings.output_step = 0.001;
    settings.newton_refreshes = refreshes;
    const PreparedRun prepared = PrepareRun(s, settings);
    ThrowIfNotReady(prepared, "rotor");
    const int b = s.FindBody("rotor");
    Vector2d e = Vector2d::Zero();
    const RunResult result = RunAnalysis(prepared, settings, [&](const Sample& smp) {
      e = smp.q.segment<2>(s.layout().position(b));
    });
    EXPECT_TRUE(result.ok()) << result.message;
    return std::pair{e, result.ida_stats};
  };
  const auto [e_own, own] = run(0);
  const auto [e_refresh, refresh] = run(-1);
  // Both runs at rtol 1e-6: the journal's position agrees to well within 1e-3 c.
  EXPECT_LT((e_own - e_refresh).norm(), 1e-3 * bp.clearance);
  EXPECT_LT(2 * refresh.nonlinear_convergence_failures, own.nonlinear_convergence_failures);
  EXPECT_LT(refresh.steps, own.steps);
}

// A journal on a slider driven down at 1 mm/s through its 30 um clearance (a squeeze film
// alone never lets a loaded journal touch: it must be driven). Guide markers with z along
// -y world: the translational joint's travel is the slider's drop.
System DrivenSlider(const tribology::ReynoldsBearingParameters& bp) {
  System s;
  RigidBody b;
  b.name = "slider";
  b.mass = 1.0;
  b.inertia_B = Vector3d(0.01, 0.01, 0.01).asDiagonal();
  b.p_WB = Vector3d(0.0, -5e-6, 0.0);
  b.v_WB = Vector3d(0.0, -1e-3, 0.0);
  s.AddBody(b);
  const Eigen::Matrix3d down = Eigen::AngleAxisd(kPi / 2, Vector3d::UnitX()).toRotationMatrix();
  s.AddMarker("guide", "slider", Vector3d::Zero(), down);
  s.AddMarker("rail", "ground", Vector3d::Zero(), down);
  s.AddMarker("journal", "slider", Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddMarker("bore", "ground", Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.AddJoint("slide", JointType::kTranslational, "guide", "rail");
  s.AddMotion("drop", "slide", JointCoordinate::kTranslation, TimeFunction::Polynomial({5e-6, 1e-3}));
  s.AddForceElement(std::make_shared<FilmBearing>("main", s.FindMarker("journal"),
                                                  s.FindMarker("bore"), bp));
  s.Finalize();
  return s;
}

RunResult RunSlider(const System& s, double t_end, const std::function<void(const Sample&)>& on_sample) {
  AnalysisSettings settings;
  settings.type = AnalysisType::kDynamic;
  settings.t_end = t_end;
  settings.output_step = 0.001;
  const PreparedRun run = PrepareRun(s, settings);
  ThrowIfNotReady(run, "slider");
  return RunAnalysis(run, settings, on_sample);
}

TEST(FilmBearing, JournalDrivenIntoTheShellIsAFailedRunNamingTheBearing) {
  const System s = DrivenSlider(Main(CavitationModel::kReynolds));
  double last = 0.0;
  const RunResult result = RunSlider(s, 0.05, [&](const Sample& smp) { last = smp.t; });
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.message.find("'main'"), std::string::npos) << result.message;
  EXPECT_NE(result.message.find("t = "), std::string::npos) << result.message;
  // The film closes at (30 - 5) um / (1 mm/s) = 25 ms: the samples before it are kept.
  EXPECT_GE(last, 0.02);
  EXPECT_LT(last, 0.026);
}

// The same slider with Greenwood-Tripp asperity contact (sigma 0.4 um) runs on through the
// clearance, with the film's states and without: the contact force is zero while the film is
// thicker than 6 sigma (the tabulated F_5/2 is 0 above 6) and carries the journal once it has
// closed, and the contact output is a channel.
class FilmBearingContact : public ::testing::TestWithParam<CavitationModel> {};

TEST_P(FilmBearingContact, AsperityContactCarriesTheJournalThroughItsClearance) {
  tribology::ReynoldsBearingParameters bp = Main(GetParam());
  bp.asperity_contact = tribology::AsperityContactParameters{};
  bp.asperity_contact->roughness = 0.4e-6;
  bp.asperity_contact->composite_modulus = 2.2e11;
  const System s = DrivenSlider(bp);
  const std::vector<ElementOutput> outputs = s.force_elements().front()->outputs();
  int contact = -1;
  for (std::size_t k = 0; k < outputs.size(); ++k)
    if (outputs[k].name == "contact_force") contact = static_cast<int>(k);
  ASSERT_GE(contact, 0);
  std::vector<std::pair<double, double>> samples;  // (t, contact force)
  const RunResult result = RunSlider(s, 0.03, [&](const Sample& smp) {
    samples.emplace_back(smp.t, smp.force_outputs[contact]);
  });
  ASSERT_TRUE(result.ok()) << result.message;
  ASSERT_FALSE(samples.empty());
  EXPECT_NEAR(samples.back().first, 0.03, 1e-12);
  for (const auto& [t, f] : samples) {
    const double h_min = 30e-6 - (5e-6 + 1e-3 * t);
    if (h_min > 6.0 * 0.4e-6) {
      EXPECT_EQ(f, 0.0) << "t = " << t;
    }
  }
  // At 30 ms the journal is 5 um beyond its nominal clearance: the asperities carry it.
  EXPECT_GT(samples.back().second, 1e3) << "N";
}

INSTANTIATE_TEST_SUITE_P(Models, FilmBearingContact,
                         ::testing::Values(CavitationModel::kReynolds,
                                           CavitationModel::kMassConserving),
                         ModelName);

TEST(FilmBearing, BadParametersNameTheBearingAndTheKey) {
  tribology::ReynoldsBearingParameters p = Main(CavitationModel::kMassConserving);
  p.bulk_modulus = 0.0;
  try {
    FilmBearing("big_end_2", 0, 1, p);
    FAIL() << "a zero bulk modulus was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'big_end_2'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bulk_modulus"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb::mbs
