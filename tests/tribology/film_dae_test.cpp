// The film as DAE states: the residual vanishes at the quasi-static film (a consistent start
// with u_dot = 0); its sum telescopes to the mass balance; every Jacobian block a DAE needs
// (dr/du, dr/du_dot, dr/dx, dr/dv and the loads' partials) against central differences;
// which states are differential.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/tribology/film_dae.h"
#include "tests/tribology/bearing_cases.h"

namespace emb::tribology {
namespace {

using Eigen::Vector2d;
using Eigen::VectorXd;
using namespace test;

// The quasi-static solve leaves residuals at the round-off of the flux sums.
constexpr double kConsistencyTolerance = 1e-12;
// Telescoping sums: round-off of n flux terms.
constexpr double kBalanceTolerance = 1e-11;
// Central differences with relative steps 1e-6 of blocks that are piecewise polynomial in
// the inputs (h^3): truncation ~1e-12, cancellation ~1e-10 of the entries' scale.
constexpr double kJacobianTolerance = 1e-6;

// The journal hole apart from the shell's, or over it (at pi/2 in Moving(): a feed that
// reaches held nodes, which it must leave alone).
enum class JournalHole { kApart, kOverTheShellHole };

ReynoldsBearingParameters Supplied(JournalHole where = JournalHole::kApart) {
  ReynoldsBearingParameters p = MainBearing({24, 6}, CavitationModel::kMassConserving);
  p.oil_holes.push_back({0.5 * kPi, 0.0, 5e-3, 3e5});
  const double angle = where == JournalHole::kApart ? 2.0 : 0.5 * kPi - Moving().journal_angle;
  p.journal_oil_holes.push_back({angle, 1e-3, 4e-3, 4e5});  // 2.3 rad or pi/2 in Moving()
  p.lubricant.pressure_law = PressureViscosityLaw::kBarus;
  p.lubricant.pressure_viscosity_coefficient = 1.5e-8;
  return p;
}

// A state near the quasi-static film: u from the solve, a random u_dot of the film's time
// scale; no u within 1e-4 of the switch (central differences must not cross it).
void State(const ReynoldsBearing& b, VectorXd* u, VectorXd* u_dot) {
  FilmSolver s(b);
  BearingLoads l;
  ASSERT_TRUE(s.SolveQuasiStatic(Moving(), &l).ok());
  *u = s.universal();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  u_dot->resize(u->size());
  for (int k = 0; k < u->size(); ++k) {
    if (std::abs((*u)[k]) < 1e-4 && !b.is_supply(k)) (*u)[k] = -1e-3;
    (*u_dot)[k] = b.is_supply(k) ? 0.0 : 10.0 * kMainSpeed * U(rng) * 1e-2;
  }
}

class FilmDaeHoles : public ::testing::TestWithParam<JournalHole> {};

TEST_P(FilmDaeHoles, QuasiStaticFilmIsAConsistentStart) {
  const ReynoldsBearing b("main_1", Supplied(GetParam()));
  FilmSolver s(b);
  BearingLoads ls, ld;
  ASSERT_TRUE(s.SolveQuasiStatic(Moving(), &ls).ok());
  FilmDae dae(b);
  VectorXd r;
  ASSERT_TRUE(dae.CalcResidual(s.universal(), VectorXd::Zero(dae.size()), Moving(), &r, &ld).ok());
  const double scale = std::abs(ls.side_flow) + std::abs(ls.supply_flow);
  EXPECT_LT(r.cwiseAbs().maxCoeff(), kConsistencyTolerance * scale);
  EXPECT_LT((ls.Stacked() - ld.Stacked()).norm(), kConsistencyTolerance * ls.Stacked().norm());
}

TEST_P(FilmDaeHoles, ResidualSumIsTheMassBalance) {
  const ReynoldsBearing b("main_1", Supplied(GetParam()));
  VectorXd u, u_dot, r;
  State(b, &u, &u_dot);
  FilmDae dae(b);
  BearingLoads l;
  ASSERT_TRUE(dae.CalcResidual(u, u_dot, Moving(), &r, &l).ok());
  double sum = 0.0;
  for (int k = 0; k < dae.size(); ++k)
    if (!b.is_supply(k)) sum += r[k];
  const double scale = std::abs(l.side_flow) + std::abs(l.supply_flow) + std::abs(l.storage_rate);
  EXPECT_NEAR(sum, l.storage_rate + l.side_flow - l.supply_flow, kBalanceTolerance * scale);
}

TEST_P(FilmDaeHoles, JacobianBlocksMatchCentralDifferences) {
  using KL = KinematicsLayout;
  const ReynoldsBearing b("main_1", Supplied(GetParam()));
  VectorXd u, u_dot;
  State(b, &u, &u_dot);
  FilmDae dae(b);
  FilmDaeJacobian J;
  ASSERT_TRUE(dae.CalcJacobian(u, u_dot, Moving(), &J).ok());
  const int n = dae.size();
  const Eigen::MatrixXd dr_du = Eigen::MatrixXd(J.dr_du);
  auto eval = [&](const VectorXd& uu, const VectorXd& ud, const JournalKinematics& k,
                  VectorXd* r, Eigen::Matrix<double, 6, 1>* y) {
    BearingLoads l;
    EXPECT_TRUE(dae.CalcResidual(uu, ud, k, r, &l).ok());
    *y = l.Stacked();
  };
  VectorXd rp, rm;
  Eigen::Matrix<double, 6, 1> yp, ym;
  const double r_scale = std::max(dr_du.cwiseAbs().maxCoeff(), 1e-300);
  for (int k = 0; k < n; ++k) {
    const double h = 1e-6 * std::max(1.0, std::abs(u[k]));
    VectorXd up = u, um = u;
    up[k] += h;
    um[k] -= h;
    eval(up, u_dot, Moving(), &rp, &yp);
    eval(um, u_dot, Moving(), &rm, &ym);
    const VectorXd col = (rp - rm) / (2 * h);
    EXPECT_LT((col - dr_du.col(k)).cwiseAbs().maxCoeff(), kJacobianTolerance * r_scale) << k;
    const Eigen::Matrix<double, 6, 1> ycol = (yp - ym) / (2 * h);
    for (int row = 0; row < 6; ++row) {
      const double scale = std::max(J.loads.d_unknowns.row(row).cwiseAbs().maxCoeff(), 1e-300);
      EXPECT_NEAR(J.loads.d_unknowns(row, k), ycol[row], kJacobianTolerance * scale) << k;
    }
    // dr/du_dot is diagonal.
    const double hd = 1e-6 * kMainSpeed;
    VectorXd dp = u_dot, dm = u_dot;
    dp[k] += hd;
    dm[k] -= hd;
    eval(u, dp, Moving(), &rp, &yp);
    eval(u, dm, Moving(), &rm, &ym);
    VectorXd dcol = (rp - rm) / (2 * hd);
    EXPECT_NEAR(dcol[k], J.dr_du_dot[k], kJacobianTolerance * J.dr_du_dot.cwiseAbs().maxCoeff());
    dcol[k] = 0.0;
    EXPECT_LT(dcol.cwiseAbs().maxCoeff(), 1e-12 * J.dr_du_dot.cwiseAbs().maxCoeff() + 1e-300);
  }
  // Kinematics (the journal hole makes the angle's column non-zero: checked below).
  const Eigen::Matrix<double, kNumInputs, 1> steps = InputSteps();
  Eigen::MatrixXd dr_dk(n, kNumInputs);
  dr_dk << J.dr_dx, J.dr_dv;
  EXPECT_GT(J.dr_dx.col(KL::kJournalAngle).cwiseAbs().maxCoeff(), 0.0);
  Eigen::Matrix<double, 6, kNumInputs> dy_dk;
  dy_dk << J.loads.d_position, J.loads.d_velocity;
  for (int col = 0; col < kNumInputs; ++col) {
    JournalKinematics kp = Moving(), km = Moving();
    Nudge(&kp, col, steps[col]);
    Nudge(&km, col, -steps[col]);
    eval(u, u_dot, kp, &rp, &yp);
    eval(u, u_dot, km, &rm, &ym);
    const VectorXd col_r = (rp - rm) / (2 * steps[col]);
    const double scale_r = std::max(dr_dk.col(col).cwiseAbs().maxCoeff(), col_r.cwiseAbs().maxCoeff());
    EXPECT_LT((col_r - dr_dk.col(col)).cwiseAbs().maxCoeff(), kJacobianTolerance * scale_r + 1e-300)
        << "dr/d(input " << col << ")";
    const Eigen::Matrix<double, 6, 1> col_y = (yp - ym) / (2 * steps[col]);
    for (int row = 0; row < 6; ++row) {
      const double scale = std::max({dy_dk.row(row).cwiseAbs().maxCoeff(), std::abs(col_y[row]), 1e-300});
      EXPECT_NEAR(dy_dk(row, col), col_y[row], kJacobianTolerance * scale)
          << "d(load " << row << ")/d(input " << col << ")";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(JournalHole, FilmDaeHoles,
                         ::testing::Values(JournalHole::kApart, JournalHole::kOverTheShellHole),
                         [](const ::testing::TestParamInfo<JournalHole>& i) {
                           return i.param == JournalHole::kApart ? std::string("Apart")
                                                                 : std::string("OverTheShellHole");
                         });

// With the smoothed switch, states inside its band: the storage's slope changes with u there,
// and dr/du carries that change (A h s'(u) u_dot, here ~10 % of the diagonal: without it the
// comparison fails); dr/du against central differences on the band's states (steps 1e-7, far
// inside the band's half-width 0.05).
TEST(FilmDae, SmoothedSwitchJacobianMatchesCentralDifferences) {
  ReynoldsBearingParameters p = Supplied();
  p.switch_width = 0.05;
  const ReynoldsBearing b("main_1", p);
  VectorXd u, u_dot;
  State(b, &u, &u_dot);
  std::vector<int> band;
  for (int k = 0; k < u.size(); ++k) {
    if (b.is_supply(k) || k % 3 != 0) continue;
    u[k] = 0.04 * std::sin(1.0 + k);  // both sides of the kink
    band.push_back(k);
  }
  FilmDae dae(b);
  FilmDaeJacobian J;
  ASSERT_TRUE(dae.CalcJacobian(u, u_dot, Moving(), &J).ok());
  const Eigen::MatrixXd dr_du = Eigen::MatrixXd(J.dr_du);
  const double r_scale = dr_du.cwiseAbs().maxCoeff();
  for (int k : band) {
    const double h = 1e-7;
    VectorXd up = u, um = u, rp, rm;
    up[k] += h;
    um[k] -= h;
    ASSERT_TRUE(dae.CalcResidual(up, u_dot, Moving(), &rp, nullptr).ok());
    ASSERT_TRUE(dae.CalcResidual(um, u_dot, Moving(), &rm, nullptr).ok());
    const VectorXd col = (rp - rm) / (2 * h);
    EXPECT_LT((col - dr_du.col(k)).cwiseAbs().maxCoeff(), kJacobianTolerance * r_scale) << k;
  }
}

TEST(FilmDae, CavitatedStatesAreTheDifferentialOnes) {
  const ReynoldsBearing b("main_1", Supplied());
  VectorXd u, u_dot, id;
  State(b, &u, &u_dot);
  FilmDae dae(b);
  dae.DifferentialStates(u, &id);
  int differential = 0;
  for (int k = 0; k < dae.size(); ++k) {
    EXPECT_EQ(id[k], (!b.is_supply(k) && u[k] < 0.0) ? 1.0 : 0.0);
    differential += id[k] > 0.0;
  }
  EXPECT_GT(differential, 0);
  EXPECT_LT(differential, dae.size());
}

TEST(FilmDae, RefusesANonConservingModel) {
  const ReynoldsBearing b("main_1", MainBearing({24, 6}, CavitationModel::kReynolds));
  EXPECT_THROW(FilmDae dae(b), InputError);
}

}  // namespace
}  // namespace emb::tribology
