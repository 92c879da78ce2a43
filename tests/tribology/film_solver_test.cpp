// The quasi-static film solver on a main bearing: the loads' Jacobian (adjoint) against central
// differences for every cavitation model, with misalignment, squeeze, an oil hole, a
// pressure-dependent viscosity and asperity contact; exact identities of the discrete loads
// (moment balance of the film, mirror symmetry, steady mass balance); Fischer-Burmeister-
// Newton against the Elrod-Adams switch; the reduced pressure route against the isoviscous
// solution; and the numerical outcomes (touching shell, contact that keeps running).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "libemb/tribology/film_solver.h"
#include "tests/tribology/bearing_cases.h"

namespace emb::tribology {
namespace {

using Eigen::Vector2d;
using namespace test;

// Central differences of the solver's loads with relative steps 1e-6: truncation ~1e-12,
// the linear solves' round-off (~1e-15 of the loads) divided by the step ~1e-9. Entries
// are compared relative to the largest entry of their row (loads mix N and N m).
constexpr double kJacobianTolerance = 1e-6;
// Identities that hold for the discrete sums exactly: a few hundred round-offs of the sums.
constexpr double kIdentityTolerance = 1e-11;

ReynoldsBearingParameters Case(CavitationModel model) {
  ReynoldsBearingParameters p = MainBearing({48, 8}, model);
  p.oil_holes.push_back({0.5 * kPi, 0.0, 4e-3, 3e5});
  return p;
}

// Case with an oil hole in the journal too (at 2.3 rad in Moving(), off the mid-plane).
ReynoldsBearingParameters CaseWithJournalHole(CavitationModel model) {
  ReynoldsBearingParameters p = Case(model);
  p.journal_oil_holes.push_back({2.0, 2e-3, 4e-3, 4e5});
  return p;
}

Eigen::Matrix<double, 6, 1> Loads(FilmSolver& s, const JournalKinematics& k) {
  BearingLoads l;
  const FilmSolveInfo info = s.SolveQuasiStatic(k, &l);
  EXPECT_TRUE(info.ok()) << info.message;
  return l.Stacked();
}

void ExpectJacobianMatchesDifferences(const ReynoldsBearingParameters& p,
                                      const JournalKinematics& k0, const std::string& label) {
  using KL = KinematicsLayout;
  const ReynoldsBearing b("main_1", p);
  FilmSolver s(b);
  BearingLoads loads;
  LoadJacobian J;
  const FilmSolveInfo info = s.SolveQuasiStatic(k0, &loads, &J);
  ASSERT_TRUE(info.ok()) << label << ": " << info.message;
  Eigen::Matrix<double, 6, kNumInputs> analytic, fd;
  analytic << J.d_position, J.d_velocity;
  const Eigen::Matrix<double, kNumInputs, 1> steps = InputSteps();
  for (int col = 0; col < kNumInputs; ++col) {
    JournalKinematics kp = k0, km = k0;
    Nudge(&kp, col, steps[col]);
    Nudge(&km, col, -steps[col]);
    fd.col(col) = (Loads(s, kp) - Loads(s, km)) / (2.0 * steps[col]);
  }
  if (!p.journal_oil_holes.empty())
    EXPECT_GT(analytic.col(KL::kJournalAngle).cwiseAbs().maxCoeff(), 0.0) << label;
  for (int row = 0; row < 6; ++row) {
    // Scale: the row's largest entry, per group of columns with one unit (e, gamma, psi, e',
    // gamma', omega).
    for (auto [first, count] : {std::pair{0, 2}, {2, 2}, {4, 1}, {5, 2}, {7, 2}, {9, 2}}) {
      const double scale = std::max(analytic.row(row).segment(first, count).cwiseAbs().maxCoeff(),
                                    fd.row(row).segment(first, count).cwiseAbs().maxCoeff());
      for (int col = first; col < first + count; ++col)
        EXPECT_NEAR(analytic(row, col), fd(row, col), kJacobianTolerance * scale + 1e-300)
            << label << ": d(load " << row << ")/d(input " << col << ")";
    }
  }
}

TEST(FilmSolver, LoadJacobianMatchesCentralDifferences) {
  for (CavitationModel m : {CavitationModel::kMassConserving, CavitationModel::kReynolds,
                            CavitationModel::kHalfSommerfeld, CavitationModel::kFullSommerfeld})
    ExpectJacobianMatchesDifferences(CaseWithJournalHole(m), Moving(),
                                     "model " + std::to_string(int(m)));
  // The journal hole over the shell's (pi/2 in Moving()): its feed must leave held nodes be.
  ReynoldsBearingParameters over = Case(CavitationModel::kMassConserving);
  over.journal_oil_holes.push_back({0.5 * kPi - Moving().journal_angle, 0.0, 4e-3, 4e5});
  ExpectJacobianMatchesDifferences(over, Moving(), "journal hole over the shell hole");
}

TEST(FilmSolver, LoadJacobianWithPiezoviscosityAndContact) {
  ReynoldsBearingParameters barus = CaseWithJournalHole(CavitationModel::kMassConserving);
  barus.lubricant.pressure_law = PressureViscosityLaw::kBarus;
  barus.lubricant.pressure_viscosity_coefficient = 1.5e-8;
  // Peak pressure ~30 MPa: alpha p ~ 0.5 (with rigid surfaces Barus has no solution once the
  // isoviscous pressure reaches 1/alpha = 67 MPa: a numerical outcome, tested below).
  JournalKinematics heavy = Moving();
  heavy.eccentricity = Vector2d(0.15, -0.75) * kMainClearance;
  ExpectJacobianMatchesDifferences(barus, heavy, "Barus");
  ReynoldsBearingParameters roelands = barus;
  roelands.lubricant.pressure_law = PressureViscosityLaw::kRoelands;
  ExpectJacobianMatchesDifferences(roelands, heavy, "Roelands");
  // Asperity contact: h_min = c - 0.985 c = 0.45 um = 1.5 sigma at the loaded edge.
  ReynoldsBearingParameters rough = CaseWithJournalHole(CavitationModel::kMassConserving);
  rough.asperity_contact = AsperityContactParameters{};
  rough.asperity_contact->roughness = 0.3e-6;
  rough.asperity_contact->composite_modulus = 2.2e11;
  JournalKinematics thin = Moving();
  thin.eccentricity = Vector2d(0.1, -0.97) * kMainClearance;
  thin.tilt = Vector2d(0.2e-3, 0.0);
  ExpectJacobianMatchesDifferences(rough, thin, "contact");
}

TEST(FilmSolver, FilmIsInMomentBalance) {
  // T_j + T_s + (e x F)_z - (gamma - gamma_b) . M = 0 (notation.h), exactly for the sums.
  for (CavitationModel m : {CavitationModel::kMassConserving, CavitationModel::kHalfSommerfeld}) {
    ReynoldsBearingParameters p = Case(m);
    p.bore_tilt = Vector2d(-0.1e-3, 0.3e-3);
    const ReynoldsBearing b("main_1", p);
    FilmSolver s(b);
    const JournalKinematics k = Moving();
    BearingLoads l;
    ASSERT_TRUE(s.SolveQuasiStatic(k, &l).ok());
    const Vector2d e = k.eccentricity, F = l.force, g = k.tilt - p.bore_tilt;
    const double exF = e.x() * F.y() - e.y() * F.x();
    const double sum = l.journal_torque + l.shell_torque + exF - g.dot(l.moment);
    const double scale = std::abs(l.journal_torque) + std::abs(exF);
    EXPECT_NEAR(sum, 0.0, kIdentityTolerance * scale);
  }
}

TEST(FilmSolver, MirrorSymmetryOfTheTilt) {
  // A bearing symmetric about its mid-plane: gamma -> -gamma mirrors z, so F(-gamma) = F(gamma)
  // and M(-gamma) = -M(gamma); aligned, M = 0.
  const ReynoldsBearing b("main_1", Case(CavitationModel::kMassConserving));
  FilmSolver s(b);
  JournalKinematics k = Rotating(Vector2d(0.1, -0.7) * kMainClearance, kMainSpeed);
  BearingLoads aligned, plus, minus;
  ASSERT_TRUE(s.SolveQuasiStatic(k, &aligned).ok());
  EXPECT_LT(aligned.moment.norm(), kIdentityTolerance * aligned.force.norm() * kMainLength);
  k.tilt = Vector2d(0.5e-3, 0.3e-3);
  ASSERT_TRUE(s.SolveQuasiStatic(k, &plus).ok());
  k.tilt = -k.tilt;
  ASSERT_TRUE(s.SolveQuasiStatic(k, &minus).ok());
  EXPECT_LT((plus.force - minus.force).norm(), kIdentityTolerance * plus.force.norm());
  EXPECT_LT((plus.moment + minus.moment).norm(), kIdentityTolerance * plus.moment.norm());
  EXPECT_GT(plus.moment.norm(), 1e-3 * plus.force.norm() * kMainLength);  // not trivially zero
  // The tilt takes up clearance at an edge: h_min = c - |e(L/2)| there.
  const Vector2d edge = k.eccentricity + 0.5 * kMainLength * k.tilt;
  const Vector2d other = k.eccentricity - 0.5 * kMainLength * k.tilt;
  EXPECT_NEAR(minus.min_film, kMainClearance - std::max(edge.norm(), other.norm()), 1e-15);
}

TEST(FilmSolver, SteadyFilmBalancesSupplyAndLeakage) {
  // No squeeze: the storage term is zero, so the oil hole supplies what leaks at the edges.
  const ReynoldsBearing b("main_1", Case(CavitationModel::kMassConserving));
  FilmSolver s(b);
  BearingLoads l;
  const FilmSolveInfo info =
      s.SolveQuasiStatic(Rotating(Vector2d(0.0, -0.7) * kMainClearance, kMainSpeed), &l);
  ASSERT_TRUE(info.ok());
  EXPECT_LT(info.residual, 1e-12);
  EXPECT_GT(l.side_flow, 0.0);
  EXPECT_NEAR(l.supply_flow, l.side_flow, kIdentityTolerance * l.side_flow);
  EXPECT_GT(l.cavitated_fraction, 0.1);
  EXPECT_LT(l.cavitated_fraction, 0.9);
  EXPECT_GT(l.power_loss, 0.0);
  EXPECT_GT(l.max_pressure, 3e5);
  EXPECT_NEAR(l.min_film, 0.3 * kMainClearance, 1e-15);
  EXPECT_NEAR(l.min_film_angle, -0.5 * kPi, 1e-15);
}

// The smoothed JFO switch (ReynoldsBearingParameters::switch_width) changes the film only in
// its band |u| < w, where it adds at most p_ref w of pressure and takes at most w of fill:
// steady and squeezed, heavily and lightly loaded, the loads move little, the Newton
// iteration still converges to round-off, and the steady mass balance stays exact.
TEST(FilmSolver, SmoothedSwitchMovesTheLoadsLittle) {
  // The film bearing's scene default: a band of 0.01 (10 kPa at p_ref 1 MPa). Measured here:
  // the loads move by 1e-6 and 5e-5 at the two loaded cases and by 0.2 % at the light one
  // (150 N, eps 0.28, film pressures ~0.3 MPa, where 10 kPa is not small): 0.3 % bounds them.
  // (A band of 0.05 moved the light case's load by 2.6 %.)
  constexpr double kWidth = 0.01;
  constexpr double kSmoothingTolerance = 3e-3;
  const JournalKinematics cases[] = {Moving(), Rotating(Vector2d(0.0, -0.7) * kMainClearance, kMainSpeed),
                                     Rotating(Vector2d(0.2, -0.2) * kMainClearance, kMainSpeed)};
  for (const JournalKinematics& k : cases) {
    ReynoldsBearingParameters p = Case(CavitationModel::kMassConserving);
    const ReynoldsBearing exact("main_1", p);
    p.switch_width = kWidth;
    const ReynoldsBearing smooth("main_1", p);
    FilmSolver a(exact), c(smooth);
    BearingLoads la, lc;
    ASSERT_TRUE(a.SolveQuasiStatic(k, &la).ok());
    const FilmSolveInfo info = c.SolveQuasiStatic(k, &lc);
    ASSERT_TRUE(info.ok()) << info.message;
    EXPECT_LT(info.residual, 1e-12);
    int in_band = 0;
    for (int i = 0; i < c.universal().size(); ++i) in_band += std::abs(c.universal()[i]) < kWidth;
    EXPECT_GT(in_band, 0) << "no node in the band: the smoothing goes untested";
    EXPECT_LT((la.force - lc.force).norm(), kSmoothingTolerance * la.force.norm());
    EXPECT_NEAR(la.power_loss, lc.power_loss, kSmoothingTolerance * la.power_loss);
    EXPECT_NEAR(la.side_flow, lc.side_flow, kSmoothingTolerance * la.side_flow);
    if (k.eccentricity_rate.isZero()) {
      EXPECT_NEAR(lc.supply_flow, lc.side_flow, kIdentityTolerance * lc.side_flow);
    }
  }
}

TEST(FilmSolver, FischerBurmeisterAgreesWithTheSwitch) {
  for (CavitationModel m : {CavitationModel::kMassConserving, CavitationModel::kReynolds}) {
    ReynoldsBearingParameters p = Case(m);
    const ReynoldsBearing sw("main_1", p);
    p.complementarity = ComplementaritySolver::kFischerBurmeister;
    const ReynoldsBearing fb("main_1", p);
    FilmSolver a(sw), c(fb);
    BearingLoads la, lc;
    ASSERT_TRUE(a.SolveQuasiStatic(Moving(), &la).ok());
    const FilmSolveInfo info = c.SolveQuasiStatic(Moving(), &lc);
    ASSERT_TRUE(info.ok()) << info.message;
    EXPECT_LT((la.Stacked() - lc.Stacked()).norm(), kIdentityTolerance * la.Stacked().norm());
    EXPECT_LT((a.universal() - c.universal()).cwiseAbs().maxCoeff(), 1e-10);
  }
}

TEST(FilmSolver, WarmAndColdStartsGiveOneSolution) {
  const ReynoldsBearing b("main_1", Case(CavitationModel::kMassConserving));
  FilmSolver s(b);
  BearingLoads first, again;
  const JournalKinematics k = Moving();
  const FilmSolveInfo cold = s.SolveQuasiStatic(k, &first);
  const FilmSolveInfo warm = s.SolveQuasiStatic(k, &again);
  ASSERT_TRUE(cold.ok() && warm.ok());
  EXPECT_EQ(warm.iterations, 1);  // the pattern is already right: one factorisation
  EXPECT_GT(cold.iterations, 1);
  EXPECT_LT((first.Stacked() - again.Stacked()).norm(), kIdentityTolerance * first.Stacked().norm());
}

// A caller that wants the film state only passes no loads: the same state as with them (this
// crashed when the loads were written through a null pointer).
TEST(FilmSolver, StateWithoutLoadsIsTheSameSolution) {
  const ReynoldsBearing b("main_1", Case(CavitationModel::kMassConserving));
  FilmSolver with(b), without(b);
  BearingLoads l;
  ASSERT_TRUE(with.SolveQuasiStatic(Moving(), &l).ok());
  ASSERT_TRUE(without.SolveQuasiStatic(Moving(), nullptr).ok());
  EXPECT_EQ(with.universal(), without.universal());
}

TEST(FilmSolver, ReducedPressureRouteMatchesTheIsoviscousFilm) {
  // With Barus, the film equations in Psi are the isoviscous ones: p = -ln(1 - alpha Psi)/alpha
  // with Psi the isoviscous pressure, node by node (the isoviscous bearing supplied at
  // Psi(p_s) = (1 - exp(-alpha p_s))/alpha).
  const double alpha = 2e-8;
  ReynoldsBearingParameters p = Case(CavitationModel::kMassConserving);
  p.oil_holes[0].supply_pressure = -std::expm1(-alpha * 3e5) / alpha;
  const ReynoldsBearing iso("main_1", p);
  p.oil_holes[0].supply_pressure = 3e5;
  p.lubricant.pressure_law = PressureViscosityLaw::kBarus;
  p.lubricant.pressure_viscosity_coefficient = alpha;
  const ReynoldsBearing barus("main_1", p);
  FilmSolver a(iso), c(barus);
  BearingLoads la, lc;
  const JournalKinematics k = Rotating(Vector2d(0.0, -0.9) * kMainClearance, kMainSpeed);
  ASSERT_TRUE(a.SolveQuasiStatic(k, &la).ok());
  ASSERT_TRUE(c.SolveQuasiStatic(k, &lc).ok());
  for (int i = 0; i < iso.num_unknowns(); ++i) {
    const double psi = a.unknowns().pressure[i];
    EXPECT_NEAR(c.unknowns().pressure[i], -std::log1p(-alpha * psi) / alpha,
                1e-12 * la.max_pressure + 1e-9);
  }
  EXPECT_GT(lc.force.norm(), la.force.norm());
  EXPECT_GT(lc.max_pressure, la.max_pressure);
}

TEST(FilmSolver, UnboundedPiezoviscousPressureIsANamedOutcome) {
  // Rigid surfaces, Barus: no solution once the isoviscous film needs Psi >= 1/alpha.
  ReynoldsBearingParameters p = Case(CavitationModel::kMassConserving);
  p.lubricant.pressure_law = PressureViscosityLaw::kBarus;
  p.lubricant.pressure_viscosity_coefficient = 2e-8;
  const ReynoldsBearing b("big_end_2", p);
  FilmSolver s(b);
  BearingLoads l;
  const FilmSolveInfo info =
      s.SolveQuasiStatic(Rotating(Vector2d(0.0, -0.97) * kMainClearance, kMainSpeed), &l);
  EXPECT_EQ(info.status, FilmStatus::kBeyondViscosityLaw);
  EXPECT_NE(info.message.find("bearing 'big_end_2'"), std::string::npos) << info.message;
  // The limit 1/alpha = 5e7 Pa, and what carries such a load.
  EXPECT_NE(info.message.find("limit 5e+07 Pa"), std::string::npos) << info.message;
  EXPECT_NE(info.message.find("without pressure_law"), std::string::npos) << info.message;
}

TEST(FilmSolver, JournalThroughItsClearanceIsANamedOutcome) {
  const ReynoldsBearing b("big_end_2", Case(CavitationModel::kMassConserving));
  FilmSolver s(b);
  BearingLoads l;
  JournalKinematics k = Rotating(Vector2d(0.0, -1.01) * kMainClearance, kMainSpeed);
  FilmSolveInfo info = s.SolveQuasiStatic(k, &l);
  EXPECT_EQ(info.status, FilmStatus::kJournalTouchesShell);
  EXPECT_NE(info.message.find("bearing 'big_end_2'"), std::string::npos) << info.message;
  EXPECT_NE(info.message.find("phi ="), std::string::npos) << info.message;
  // Aligned inside the clearance but tilted through it at an edge.
  k.eccentricity = Vector2d(0.0, -0.8) * kMainClearance;
  k.tilt = Vector2d(0.0, -2.5e-3);
  info = s.SolveQuasiStatic(k, &l);
  EXPECT_EQ(info.status, FilmStatus::kJournalTouchesShell);
  // The solver recovers on the next good call.
  k.tilt.setZero();
  EXPECT_TRUE(s.SolveQuasiStatic(k, &l).ok());
}

TEST(FilmSolver, AsperityContactKeepsRunningThroughTheClearance) {
  ReynoldsBearingParameters p = Case(CavitationModel::kMassConserving);
  p.asperity_contact = AsperityContactParameters{};
  p.asperity_contact->roughness = 0.3e-6;
  p.asperity_contact->composite_modulus = 2.2e11;
  const ReynoldsBearing b("big_end_2", p);
  FilmSolver s(b);
  BearingLoads l;
  const Vector2d e(0.0, -1.01 * kMainClearance);
  const FilmSolveInfo info = s.SolveQuasiStatic(Rotating(e, kMainSpeed), &l);
  ASSERT_TRUE(info.ok()) << info.message;
  EXPECT_LT(l.min_film, 0.0);
  EXPECT_GT(l.max_contact_pressure, 0.0);
  EXPECT_GT(l.contact_force.y(), 0.0);  // pushes the journal back up
  EXPECT_TRUE(l.force.allFinite());
}

}  // namespace
}  // namespace emb::tribology
