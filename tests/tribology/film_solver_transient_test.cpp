// The transient mass-conserving film (backward Euler on the film content): per step, the
// content gained equals supply minus leakage to round-off, on a whirling journal and on a
// squeezing one, both with film rupture and reformation; a steady journal steps to the
// quasi-static film; the step's load Jacobian against central differences.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "libemb/tribology/film_solver.h"
#include "tests/tribology/bearing_cases.h"

namespace emb::tribology {
namespace {

using Eigen::Vector2d;
using namespace test;

// Per step: |sum A (m - m_prev)/dt - (supply - leakage)| against the flows. The residual
// is solved exactly for its switch pattern (film_solver.h), so the balance holds to the
// round-off of the flux sums: 1e-11 of the largest flow leaves a factor 100 of margin.
constexpr double kMassBalanceTolerance = 1e-11;
// Steady limit: after the steps the film has forgotten its start to this (relative).
constexpr double kSteadyTolerance = 1e-8;
// As film_solver_test (central differences, relative steps 1e-6).
constexpr double kJacobianTolerance = 1e-6;

ReynoldsBearingParameters Supplied() {
  ReynoldsBearingParameters p = MainBearing({48, 8}, CavitationModel::kMassConserving);
  p.oil_holes.push_back({0.5 * kPi, 0.0, 4e-3, 3e5});
  return p;
}

// A journal orbiting at 0.35 of its speed with a radius pulsing between 0.45 and 0.85 c: the
// cavitated zone travels around the shell and changes size.
constexpr double kWhirlSpeed = 0.35 * kMainSpeed;
JournalKinematics Whirling(double t) {
  const double eps = 0.65 + 0.2 * std::sin(2.0 * kWhirlSpeed * t);
  return Rotating(eps * kMainClearance *
                      Vector2d(std::cos(kWhirlSpeed * t), std::sin(kWhirlSpeed * t)),
                  kMainSpeed);
}

struct Events {
  int ruptures{0}, reformations{0};
  double worst_balance{0.0};
};

// Steps through kin(t) from the quasi-static film at t = 0, checking every step's balance.
Events Stepping(const ReynoldsBearing& b, const std::function<JournalKinematics(double)>& kin,
           double dt, int steps) {
  FilmSolver s(b);
  BearingLoads l;
  EXPECT_TRUE(s.SolveQuasiStatic(kin(0.0), &l).ok());
  FilmState state = s.state(), next;
  Events ev;
  const double A = b.grid().node_area();
  for (int n = 1; n <= steps; ++n) {
    const FilmSolveInfo info = s.Step(state, dt, kin(n * dt), &next, &l);
    EXPECT_TRUE(info.ok()) << "step " << n << ": " << info.message;
    if (!info.ok()) return ev;
    double gained = 0.0;
    for (int k = 0; k < b.num_unknowns(); ++k) {
      if (b.is_supply(k)) continue;
      gained += A * (next.content[k] - state.content[k]) / dt;
      const bool was_cavitated = state.universal[k] < 0.0, is_cavitated = next.universal[k] < 0.0;
      ev.ruptures += !was_cavitated && is_cavitated;
      ev.reformations += was_cavitated && !is_cavitated;
    }
    const double flows = std::abs(l.supply_flow) + std::abs(l.side_flow) + std::abs(gained);
    const double balance = std::abs(gained - (l.supply_flow - l.side_flow)) / flows;
    ev.worst_balance = std::max(ev.worst_balance, balance);
    EXPECT_NEAR(gained, l.storage_rate, kMassBalanceTolerance * flows);
    state = next;
  }
  return ev;
}

TEST(FilmSolverTransient, WhirlingJournalConservesMassPerStep) {
  const ReynoldsBearing b("big_end_1", Supplied());
  const double period = 2.0 * kPi / kWhirlSpeed;
  const Events ev = Stepping(b, Whirling, period / 120.0, 240);
  EXPECT_LT(ev.worst_balance, kMassBalanceTolerance);
  EXPECT_GT(ev.ruptures, 0);
  EXPECT_GT(ev.reformations, 0);
}

TEST(FilmSolverTransient, SqueezingJournalConservesMassPerStep) {
  // No rotation at all: the film is pumped by the squeeze alone, with the oil hole refilling
  // it; the journal swings from 0.2 c to 0.8 c below the centre and back.
  const ReynoldsBearing b("big_end_1", Supplied());
  const double w = 2.0 * kPi * 50.0;  // 50 Hz
  auto kin = [&](double t) {
    JournalKinematics k;
    k.eccentricity = Vector2d(0.0, -kMainClearance * (0.5 - 0.3 * std::cos(w * t)));
    return k;
  };
  const Events ev = Stepping(b, kin, 2.0 * kPi / w / 100.0, 200);
  EXPECT_LT(ev.worst_balance, kMassBalanceTolerance);
  EXPECT_GT(ev.ruptures, 0);
  EXPECT_GT(ev.reformations, 0);
}

TEST(FilmSolverTransient, RotatingJournalHoleConservesMassPerStep) {
  // A big end fed only through its crankpin's drilling: the hole turns with the journal
  // (psi = omega t) past the loaded and the cavitated zones while the journal whirls.
  ReynoldsBearingParameters p = MainBearing({48, 8}, CavitationModel::kMassConserving);
  p.journal_oil_holes.push_back({0.0, 0.0, 4e-3, 3e5});
  const ReynoldsBearing b("big_end_1", p);
  const double period = 2.0 * kPi / kWhirlSpeed;
  auto kin = [](double t) {
    JournalKinematics k = Whirling(t);
    k.journal_angle = kMainSpeed * t;
    return k;
  };
  const Events ev = Stepping(b, kin, period / 240.0, 480);
  EXPECT_LT(ev.worst_balance, kMassBalanceTolerance);
  EXPECT_GT(ev.ruptures, 0);
  EXPECT_GT(ev.reformations, 0);
}

TEST(FilmSolverTransient, SteadyJournalStepsToTheQuasiStaticFilm) {
  const ReynoldsBearing b("main_1", Supplied());
  FilmSolver s(b);
  const JournalKinematics k = Rotating(Vector2d(0.2, -0.75) * kMainClearance, kMainSpeed);
  BearingLoads steady, l;
  ASSERT_TRUE(s.SolveQuasiStatic(k, &steady).ok());
  // Start fully flooded at ambient pressure, step 2 revolutions at a time.
  FilmState state;
  state.universal = Eigen::VectorXd::Zero(b.num_unknowns());
  state.content.resize(b.num_unknowns());
  for (int kk = 0; kk < b.num_unknowns(); ++kk) {
    const BearingGrid& g = b.grid();
    state.content[kk] = s.film().node_film()[g.Node(g.column_of(kk), g.row_of(kk))];
  }
  FilmState next;
  const double dt = 2.0 * 2.0 * kPi / kMainSpeed;
  for (int n = 0; n < 80; ++n) {
    ASSERT_TRUE(s.Step(state, dt, k, &next, &l).ok());
    state = next;
  }
  EXPECT_LT((l.Stacked() - steady.Stacked()).norm(), kSteadyTolerance * steady.Stacked().norm());
  EXPECT_NEAR(l.storage_rate, 0.0, kSteadyTolerance * steady.side_flow);
}

TEST(FilmSolverTransient, StepLoadJacobianMatchesCentralDifferences) {
  ReynoldsBearingParameters p = Supplied();
  p.journal_oil_holes.push_back({2.0, 2e-3, 4e-3, 4e5});  // the journal angle's column
  const ReynoldsBearing b("main_1", p);
  FilmSolver s(b);
  JournalKinematics k0 = Rotating(Vector2d(0.1, -0.6) * kMainClearance, kMainSpeed);
  k0.tilt = Vector2d(0.3e-3, -0.2e-3);
  BearingLoads l;
  ASSERT_TRUE(s.SolveQuasiStatic(k0, &l).ok());
  const FilmState previous = s.state();
  JournalKinematics k1 = k0;
  k1.eccentricity += Vector2d(0.03, -0.02) * kMainClearance;
  const double dt = 2e-4;
  LoadJacobian J;
  FilmState next;
  ASSERT_TRUE(s.Step(previous, dt, k1, &next, &l, &J).ok());
  auto loads = [&](const JournalKinematics& k) {
    BearingLoads out;
    EXPECT_TRUE(s.Step(previous, dt, k, &next, &out).ok());
    return out.Stacked();
  };
  const Eigen::Matrix<double, kNumInputs, 1> steps = InputSteps();
  EXPECT_GT(J.d_position.col(KinematicsLayout::kJournalAngle).cwiseAbs().maxCoeff(), 0.0);
  for (int col = 0; col < KinematicsLayout::kNumPositions; ++col) {
    JournalKinematics kp = k1, km = k1;
    const double step = steps[col];
    Nudge(&kp, col, step);
    Nudge(&km, col, -step);
    const Eigen::Matrix<double, 6, 1> fd = (loads(kp) - loads(km)) / (2 * step);
    for (int row = 0; row < 6; ++row) {
      const double scale = std::max(J.d_position.row(row).cwiseAbs().maxCoeff(), 1e-300);
      EXPECT_NEAR(J.d_position(row, col), fd[row], kJacobianTolerance * scale)
          << "row " << row << ", col " << col;
    }
  }
  // Backward Euler takes the squeeze from the content, not from the rates.
  EXPECT_EQ(J.d_velocity.leftCols<4>().norm(), 0.0);
}

}  // namespace
}  // namespace emb::tribology
