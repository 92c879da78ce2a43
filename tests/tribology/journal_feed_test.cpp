// Oil holes in the journal (supply_features.h): the feed's conductances sum to the hole's at
// every journal angle and their slopes are the derivatives; the loads approach those of a
// hole held at its supply pressure as the feed conductance grows (the default's accuracy);
// a hole in the journal and one in the shell at the same place carry nearly the same load.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "libemb/tribology/film_solver.h"
#include "tests/tribology/bearing_cases.h"

namespace emb::tribology {
namespace {

using Eigen::Vector2d;
using namespace test;

// Sums of a few dozen normalised weights: round-off (the normalisation makes the sum exact
// by construction; what the test adds is that some node is always fed and nothing is NaN).
constexpr double kSumTolerance = 1e-12;
// Central differences with step 1e-8 rad of weights that are C^1 (w = q^2; the second
// derivative jumps at the footprint's rim): truncation and cancellation both ~1e-8 of the
// slopes' scale.
constexpr double kSlopeTolerance = 1e-6;

TEST(JournalFeed, ConductancesSumToTheHoleAtEveryAngle) {
  for (GridSize grid : {GridSize{24, 6}, GridSize{48, 8}}) {
    for (double d : {4e-3, 0.5e-3}) {  // larger and smaller than a cell
      const BearingGrid g(kMainRadius, kMainLength, grid);
      const std::vector<JournalOilHole> holes = {{0.4, 1.5e-3, d, 3e5}};
      const double G = 2.5e-9;
      JournalFeed feed, plus, minus;
      double worst_sum = 0.0, worst_slope = 0.0;
      for (int a = 0; a < 720; ++a) {
        const double psi = 2.0 * kPi * a / 720.0 - kPi;
        CalcJournalFeed(g, holes, G, {3e5}, psi, &feed);
        ASSERT_GT(feed.size(), 0);
        double sum = 0.0, slope_scale = 0.0;
        for (int e = 0; e < feed.size(); ++e) {
          EXPECT_GE(feed.conductance[e], 0.0);
          sum += feed.conductance[e];
          slope_scale = std::max(slope_scale, std::abs(feed.conductance_slope[e]));
        }
        // NaN-safe: a NaN sum or slope makes the worst NaN, and the EXPECT_LTs fail.
        const double sum_error = std::abs(sum - G) / G;
        if (!(sum_error <= worst_sum)) worst_sum = sum_error;
        // Slopes by differences, matched by unknown (the footprint's entries are stable
        // for a step this small unless a node sits exactly on its rim, where w = w' = 0).
        const double h = 1e-8;
        CalcJournalFeed(g, holes, G, {3e5}, psi + h, &plus);
        CalcJournalFeed(g, holes, G, {3e5}, psi - h, &minus);
        auto at = [](const JournalFeed& f, int k) {
          for (int e = 0; e < f.size(); ++e)
            if (f.unknown[e] == k) return f.conductance[e];
          return 0.0;
        };
        for (int e = 0; e < feed.size(); ++e) {
          const int k = feed.unknown[e];
          const double fd = (at(plus, k) - at(minus, k)) / (2.0 * h);
          const double error = std::abs(fd - feed.conductance_slope[e]) / slope_scale;
          if (!(error <= worst_slope)) worst_slope = error;
        }
      }
      EXPECT_LT(worst_sum, kSumTolerance)
          << grid.circumferential << " x " << grid.axial << ", d " << d;
      EXPECT_LT(worst_slope, kSlopeTolerance)
          << grid.circumferential << " x " << grid.axial << ", d " << d;
    }
  }
}

// The main bearing fed only by a hole in its journal, in the unloaded half.
ReynoldsBearingParameters JournalFed(double ratio, GridSize grid = {48, 8}) {
  ReynoldsBearingParameters p = MainBearing(grid, CavitationModel::kMassConserving);
  p.journal_oil_holes.push_back({0.0, 0.0, 4e-3, 3e5});
  p.journal_feed_ratio = ratio;
  return p;
}

JournalKinematics Loaded(double psi) {
  JournalKinematics k = Rotating(Vector2d(0.1, -0.7) * kMainClearance, kMainSpeed);
  k.journal_angle = psi;
  return k;
}

BearingLoads Solve(const ReynoldsBearingParameters& p, const JournalKinematics& k) {
  const ReynoldsBearing b("big_end_1", p);
  FilmSolver s(b);
  BearingLoads l;
  const FilmSolveInfo info = s.SolveQuasiStatic(k, &l);
  EXPECT_TRUE(info.ok()) << info.message;
  return l;
}

TEST(JournalFeed, LoadsConvergeAsTheFeedConductanceGrows) {
  // The hole at phi = 2 rad (upstream of the loaded zone below the centre). The feed's
  // error falls like 1/kappa: the hole's nodes sit below p_s by the film's outflow over G.
  const JournalKinematics k = Loaded(2.0);
  const BearingLoads limit = Solve(JournalFed(1e7), k);
  std::vector<double> errors;
  for (double ratio : {1e1, 1e2, 1e3, 1e4}) {
    const BearingLoads l = Solve(JournalFed(ratio), k);
    errors.push_back((l.force - limit.force).norm() / limit.force.norm());
    EXPECT_GT(l.supply_flow, 0.0);
  }
  // The hole's rim nodes (w < 1) are held less firmly than its core: towards 1/kappa
  // (ratios ~0.1) only once the feed dominates the film there; 0.3 per decade at least.
  for (size_t j = 1; j < errors.size(); ++j)
    EXPECT_LT(errors[j], 0.3 * errors[j - 1]) << "kappa 1e" << j + 1;
  // The default ratio (1e4) is within 0.1 % of the limit (reynolds_bearing.h).
  EXPECT_EQ(ReynoldsBearingParameters{}.journal_feed_ratio, 1e4);
  EXPECT_LT(errors[3], 1e-3);
}

TEST(JournalFeed, AJournalHoleCarriesTheLoadOfAShellHoleAtTheSamePlace) {
  // With the journal's hole turned to where a shell hole of the same size is, the two films
  // differ only by the hole's footprint (held nodes inside the hole against a feed spread
  // over 1.2 cells beyond the rim): on refinement the footprint shrinks to the hole.
  std::vector<double> differences;
  for (GridSize grid : {GridSize{48, 8}, GridSize{96, 16}}) {
    ReynoldsBearingParameters shell = MainBearing(grid, CavitationModel::kMassConserving);
    shell.oil_holes.push_back({2.0, 0.0, 4e-3, 3e5});
    const BearingLoads held = Solve(shell, Loaded(0.0));
    const BearingLoads fed = Solve(JournalFed(1e4, grid), Loaded(2.0));
    differences.push_back((fed.force - held.force).norm() / held.force.norm());
  }
  std::printf("journal hole vs shell hole: force differs by %.3g (48 x 8), %.3g (96 x 16)\n",
              differences[0], differences[1]);
  // The taper is 1.2 cells wide: first order in the spacing (0.5 per halving; 0.6 allowed),
  // a few per cent on the engine grids.
  EXPECT_LT(differences[1], 0.6 * differences[0]);
  EXPECT_LT(differences[0], 0.1);
}

}  // namespace
}  // namespace emb::tribology
