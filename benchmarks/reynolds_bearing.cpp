// Cost and precision of the finite-width Reynolds bearing (libemb/tribology, issue 30): one
// quasi-static evaluation with its load Jacobian against the grid, the work-precision of load
// and minimum film against a fine grid, the two complementarity solvers (Elrod-Adams switch,
// Fischer-Burmeister-Newton), a naive sparse LU of the same Jacobian, and the Ocvirk short
// bearing for comparison.
//   build/benchmarks/reynolds_bearing [--json] [--quick]
// The case: a passenger-car main bearing (R = 30 mm, L = 20 mm, c = 30 um) at 3000 rpm on a
// representative SAE 10W-30 at 100 C (Walther through nu40 = 70, nu100 = 10.5 mm^2/s,
// rho = 860 kg/m^3: SAE J300 grade 30 window), an oil hole (4 mm, 3 bar) in the unloaded
// upper shell, JFO cavitation; steady loads W = 4, 10, 25 kN downwards. For each grid and
// load: the equilibrium eccentricity (Newton on F(e) + W = 0 with the load Jacobian), its
// h_min, and the film force at the reference grid's equilibrium eccentricity, both against
// the reference grid (384 x 48). Timing: an evaluation with its Jacobian at points of a small
// orbit (radius 1 % of c) around the equilibrium, warm-started from the previous point (as a
// DAE calls it), best of 3 batches of >= 0.2 s; and cold (the warm start reset each call).
// With --json one JSON document on stdout (benchmarks/record.py stores it).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/SparseLU>

#include "libemb/engine/journal_bearing.h"
#include "libemb/tribology/film_solver.h"

namespace {

using namespace emb::tribology;
using Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;
constexpr double kOmega = 3000.0 * 2.0 * kPi / 60.0;
constexpr double kRadius = 0.03, kLength = 0.02, kClearance = 30e-6;
const std::vector<double> kLoads = {4e3, 10e3, 25e3};  // N, downwards (-y)
constexpr double kOrbitFraction = 0.01;                // orbit radius / c
constexpr int kOrbitPoints = 64;
constexpr double kMinBatchSeconds = 0.2;

ReynoldsBearingParameters MainBearing(GridSize grid) {
  ReynoldsBearingParameters p;
  p.radius = kRadius;
  p.length = kLength;
  p.clearance = kClearance;
  p.grid = grid;
  p.lubricant.temperature_law = ViscosityTemperatureLaw::kWalther;
  p.lubricant.nu_40 = 70e-6;
  p.lubricant.nu_100 = 10.5e-6;
  p.lubricant.density = 860.0;
  p.lubricant.temperature = 373.15;
  p.oil_holes.push_back({0.5 * kPi, 0.0, 4e-3, 3e5});
  p.cavitation = CavitationModel::kMassConserving;
  return p;
}

JournalKinematics At(const Vector2d& e) {
  JournalKinematics k;
  k.eccentricity = e;
  k.journal_speed = kOmega;
  return k;
}

struct Equilibrium {
  bool ok{false};
  Vector2d e{0.0, 0.0};
  BearingLoads loads;
  int newton{0};
};

// F(e) + W = 0 by Newton with the load Jacobian's 2 x 2 position block.
Equilibrium SolveEquilibrium(FilmSolver& solver, double W, Vector2d e0) {
  Equilibrium q;
  q.e = e0;
  const Vector2d load(0.0, -W);
  for (int it = 0; it < 60; ++it) {
    LoadJacobian J;
    const FilmSolveInfo info = solver.SolveQuasiStatic(At(q.e), &q.loads, &J);
    if (!info.ok()) return q;
    const Vector2d r = q.loads.force + load;
    ++q.newton;
    if (r.norm() < 1e-10 * W) {
      q.ok = true;
      return q;
    }
    Vector2d step = -J.d_position.topLeftCorner<2, 2>().partialPivLu().solve(r);
    // Keep the journal inside the clearance: halve until eps < 0.995.
    while ((q.e + step).norm() > 0.995 * kClearance) step *= 0.5;
    q.e += step;
  }
  return q;
}

double Seconds(std::chrono::steady_clock::time_point a) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

struct Timing {
  double us{0.0};
  double iterations{0.0};
};

// Mean time per evaluation over orbit points around e, best of 3 batches.
Timing TimeOrbit(FilmSolver& solver, const Vector2d& e, bool jacobian, bool cold) {
  Timing best;
  best.us = 1e300;
  BearingLoads loads;
  LoadJacobian J;
  for (int batch = 0; batch < 3; ++batch) {
    int calls = 0, iterations = 0;
    const auto start = std::chrono::steady_clock::now();
    do {
      for (int k = 0; k < kOrbitPoints; ++k) {
        const double a = 2.0 * kPi * k / kOrbitPoints;
        const Vector2d ek = e + kOrbitFraction * kClearance * Vector2d(std::cos(a), std::sin(a));
        if (cold) solver.ResetWarmStart();
        const FilmSolveInfo info = solver.SolveQuasiStatic(At(ek), &loads, jacobian ? &J : nullptr);
        iterations += info.iterations;
        ++calls;
      }
    } while (Seconds(start) < kMinBatchSeconds);
    const double us = 1e6 * Seconds(start) / calls;
    if (us < best.us) {
      best.us = us;
      best.iterations = static_cast<double>(iterations) / calls;
    }
  }
  return best;
}

struct GridRow {
  GridSize grid;
  int unknowns{0};
  std::vector<Equilibrium> eq;
  std::vector<double> force_at_reference;  // |F(e_ref)| [N]
  Timing warm_jac, warm, cold_jac;
};

}  // namespace

int main(int argc, char** argv) {
  bool json = false, quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--json")) json = true;
    if (!std::strcmp(argv[i], "--quick")) quick = true;
  }
  const GridSize reference_grid{quick ? 192 : 384, quick ? 24 : 48};
  std::vector<GridSize> grids = {{16, 4},  {24, 4},  {24, 6},  {32, 4},  {32, 6},  {32, 8},
                                 {40, 6},  {48, 6},  {48, 8},  {64, 6},  {64, 8},  {64, 12},
                                 {96, 8},  {96, 12}, {128, 16}, {192, 24}};
  if (quick) grids = {{24, 4}, {32, 6}, {48, 8}, {64, 8}, {96, 12}};

  // Reference equilibria.
  const ReynoldsBearing ref_bearing("main_ref", MainBearing(reference_grid));
  FilmSolver ref_solver(ref_bearing);
  std::vector<Equilibrium> ref;
  for (double W : kLoads) {
    ref.push_back(SolveEquilibrium(ref_solver, W, Vector2d(0.0, -0.5 * kClearance)));
    if (!ref.back().ok) {
      std::fprintf(stderr, "reference equilibrium failed at W = %g N\n", W);
      return 1;
    }
  }

  std::vector<GridRow> rows;
  for (const GridSize& g : grids) {
    GridRow row;
    row.grid = g;
    const ReynoldsBearing bearing("main", MainBearing(g));
    row.unknowns = bearing.num_unknowns();
    FilmSolver solver(bearing);
    for (size_t l = 0; l < kLoads.size(); ++l) {
      row.eq.push_back(SolveEquilibrium(solver, kLoads[l], ref[l].e));
      BearingLoads at_ref;
      solver.SolveQuasiStatic(At(ref[l].e), &at_ref);
      row.force_at_reference.push_back(at_ref.force.norm());
    }
    // Timing at the middle load's equilibrium.
    const Vector2d e = row.eq[1].ok ? row.eq[1].e : ref[1].e;
    BearingLoads scratch;
    solver.SolveQuasiStatic(At(e), &scratch);
    row.warm_jac = TimeOrbit(solver, e, true, false);
    row.warm = TimeOrbit(solver, e, false, false);
    row.cold_jac = TimeOrbit(solver, e, true, true);
    rows.push_back(row);
    if (!json)
      std::printf("%4d x %2d  n = %5d  eval+jac %8.1f us (%.2f it)  eval %8.1f us  cold %8.1f us\n",
                  g.circumferential, g.axial, row.unknowns, row.warm_jac.us,
                  row.warm_jac.iterations, row.warm.us, row.cold_jac.us);
  }

  nlohmann::json out;
  out["bearing"] = {{"radius_m", kRadius},       {"length_m", kLength},
                    {"clearance_m", kClearance}, {"speed_rpm", 3000.0},
                    {"viscosity_pa_s", ref_bearing.lubricant().ambient_viscosity()},
                    {"oil_hole", "4 mm at phi = 90 deg, z = 0, 3 bar"},
                    {"cavitation", "mass-conserving (JFO)"}};
  out["loads_n"] = kLoads;
  out["reference_grid"] = {reference_grid.circumferential, reference_grid.axial};
  nlohmann::json ref_rows = nlohmann::json::array();
  for (size_t l = 0; l < kLoads.size(); ++l)
    ref_rows.push_back({{"load_n", kLoads[l]},
                        {"eccentricity_ratio", ref[l].e.norm() / kClearance},
                        {"h_min_um", 1e6 * ref[l].loads.min_film},
                        {"p_max_mpa", 1e-6 * ref[l].loads.max_pressure},
                        {"friction_power_w", ref[l].loads.power_loss},
                        {"side_flow_l_per_min", 6e4 * ref[l].loads.side_flow}});
  out["reference"] = ref_rows;
  nlohmann::json jrows = nlohmann::json::array();
  std::string converged;
  for (const GridRow& row : rows) {
    double load_err = 0.0, hmin_err = 0.0, pmax_err = 0.0;
    bool ok = true;
    for (size_t l = 0; l < kLoads.size(); ++l) {
      ok = ok && row.eq[l].ok;
      if (!row.eq[l].ok) continue;
      load_err = std::max(load_err, std::abs(row.force_at_reference[l] / kLoads[l] - 1.0));
      hmin_err = std::max(hmin_err, std::abs(row.eq[l].loads.min_film / ref[l].loads.min_film - 1.0));
      pmax_err = std::max(pmax_err, std::abs(row.eq[l].loads.max_pressure /
                                                 ref[l].loads.max_pressure - 1.0));
    }
    const std::string name =
        std::to_string(row.grid.circumferential) + " x " + std::to_string(row.grid.axial);
    if (converged.empty() && ok && load_err <= 0.01 && hmin_err <= 0.01) converged = name;
    jrows.push_back({{"name", name},
                     {"circumferential", row.grid.circumferential},
                     {"axial", row.grid.axial},
                     {"unknowns", row.unknowns},
                     {"equilibria_ok", ok},
                     {"load_error_pct", 100 * load_err},
                     {"h_min_error_pct", 100 * hmin_err},
                     {"p_max_error_pct", 100 * pmax_err},
                     {"eval_jacobian_us", row.warm_jac.us},
                     {"eval_us", row.warm.us},
                     {"cold_eval_jacobian_us", row.cold_jac.us},
                     {"iterations_warm", row.warm_jac.iterations},
                     {"iterations_cold", row.cold_jac.iterations}});
    if (!json)
      std::printf("%-10s load %6.3f %%  h_min %6.3f %%  p_max %6.2f %%\n", name.c_str(),
                  100 * load_err, 100 * hmin_err, 100 * pmax_err);
  }
  out["grids"] = jrows;
  out["converged_grid"] = converged;

  // Naive sparse LU (Eigen SparseLU, COLAMD) of the same film Jacobian on MBDyn's default
  // 85 x 20 grid: analyse + factorise + one solve per evaluation.
  {
    const ReynoldsBearing bearing("main_85x20", MainBearing({85, 20}));
    FilmSolver solver(bearing);
    BearingLoads scratch;
    solver.SolveQuasiStatic(At(ref[1].e), &scratch);
    const FilmUnknowns& x = solver.unknowns();
    Eigen::SparseMatrix<double> J;
    StorageInputs st;
    FillFilmJacobian(solver.film(), x, st,
                     ColumnWeights{x.dpsi_du.data(), x.dtheta_du.data(), x.dslack_du.data()}, &J);
    Eigen::VectorXd b = Eigen::VectorXd::Ones(J.rows());
    double best = 1e300;
    for (int batch = 0; batch < 3; ++batch) {
      int calls = 0;
      const auto start = std::chrono::steady_clock::now();
      do {
        Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
        lu.compute(J);
        Eigen::VectorXd xs = lu.solve(b);
        ++calls;
      } while (Seconds(start) < kMinBatchSeconds);
      best = std::min(best, 1e6 * Seconds(start) / calls);
    }
    const Timing own = TimeOrbit(solver, ref[1].e, false, false);
    out["naive_sparse_lu"] = {{"grid", "85 x 20"},
                              {"unknowns", bearing.num_unknowns()},
                              {"eigen_sparse_lu_factor_solve_us", best},
                              {"film_solver_eval_us", own.us}};
    if (!json)
      std::printf("85 x 20: Eigen SparseLU analyse+factor+solve %.1f us; FilmSolver eval %.1f us\n",
                  best, own.us);
  }

  // Complementarity solvers on the converged grid (or 48 x 8): cold and warm.
  {
    const GridSize g = {48, 8};
    nlohmann::json solvers = nlohmann::json::array();
    for (ComplementaritySolver cs :
         {ComplementaritySolver::kElrodAdamsSwitch, ComplementaritySolver::kFischerBurmeister}) {
      ReynoldsBearingParameters p = MainBearing(g);
      p.complementarity = cs;
      const ReynoldsBearing bearing("main", p);
      FilmSolver solver(bearing);
      double worst_force_diff = 0.0;
      for (size_t l = 0; l < kLoads.size(); ++l) {
        BearingLoads a, b;
        solver.ResetWarmStart();
        solver.SolveQuasiStatic(At(ref[l].e), &a);
        ReynoldsBearingParameters pe = MainBearing(g);
        const ReynoldsBearing be("main", pe);
        FilmSolver se(be);
        se.SolveQuasiStatic(At(ref[l].e), &b);
        worst_force_diff = std::max(worst_force_diff, (a.force - b.force).norm() / b.force.norm());
      }
      const Timing cold = TimeOrbit(solver, ref[1].e, true, true);
      const Timing warm = TimeOrbit(solver, ref[1].e, true, false);
      const std::string name = cs == ComplementaritySolver::kElrodAdamsSwitch
                                   ? "Elrod-Adams switch"
                                   : "Fischer-Burmeister-Newton";
      solvers.push_back({{"name", name},
                         {"grid", "48 x 8"},
                         {"cold_iterations", cold.iterations},
                         {"cold_us", cold.us},
                         {"warm_iterations", warm.iterations},
                         {"warm_us", warm.us},
                         {"force_vs_switch_rel", worst_force_diff}});
      if (!json)
        std::printf("%-26s cold %.2f it %.1f us  warm %.2f it %.1f us  |dF|/F %.1e\n",
                    name.c_str(), cold.iterations, cold.us, warm.iterations, warm.us,
                    worst_force_diff);
    }
    out["solvers"] = solvers;
  }

  // Ocvirk short bearing (half-Sommerfeld, closed form): cost of one force evaluation, and its
  // equilibrium h_min against the finite-width reference.
  {
    emb::mbs::JournalBearingParameters op{kRadius, kLength, kClearance,
                                          ref_bearing.lubricant().ambient_viscosity()};
    const emb::mbs::JournalBearing ocvirk("ocvirk", 0, 1, op);
    double best = 1e300;
    for (int batch = 0; batch < 3; ++batch) {
      int calls = 0;
      double sink = 0.0;
      const auto start = std::chrono::steady_clock::now();
      do {
        for (int k = 0; k < kOrbitPoints; ++k) {
          const double a = 2.0 * kPi * k / kOrbitPoints;
          const Vector2d ek = ref[1].e + kOrbitFraction * kClearance * Vector2d(std::cos(a), std::sin(a));
          sink += ocvirk.CalcFilmLoad(ek, Vector2d::Zero(), kOmega).force.x();
          ++calls;
        }
      } while (Seconds(start) < kMinBatchSeconds);
      best = std::min(best, 1e6 * Seconds(start) / calls);
      if (sink == 1.2345) std::printf(" ");
    }
    nlohmann::json errs = nlohmann::json::array();
    for (size_t l = 0; l < kLoads.size(); ++l) {
      // Equilibrium of the closed form by Newton with difference quotients (2 x 2).
      Vector2d e = ref[l].e;
      for (int it = 0; it < 50; ++it) {
        const Vector2d r = ocvirk.CalcFilmLoad(e, Vector2d::Zero(), kOmega).force + Vector2d(0, -kLoads[l]);
        if (r.norm() < 1e-10 * kLoads[l]) break;
        Eigen::Matrix2d J;
        for (int c = 0; c < 2; ++c) {
          Vector2d d = Vector2d::Zero();
          d[c] = 1e-7 * kClearance;
          J.col(c) = (ocvirk.CalcFilmLoad(e + d, Vector2d::Zero(), kOmega).force -
                      ocvirk.CalcFilmLoad(e - d, Vector2d::Zero(), kOmega).force) /
                     (2e-7 * kClearance);
        }
        Vector2d step = -J.partialPivLu().solve(r);
        while ((e + step).norm() > 0.995 * kClearance) step *= 0.5;
        e += step;
      }
      const double hmin = kClearance - e.norm();
      const double F_at_ref = ocvirk.CalcFilmLoad(ref[l].e, Vector2d::Zero(), kOmega).force.norm();
      errs.push_back({{"load_n", kLoads[l]},
                      {"h_min_um", 1e6 * hmin},
                      {"h_min_error_pct", 100 * (hmin / ref[l].loads.min_film - 1.0)},
                      {"load_error_pct", 100 * (F_at_ref / kLoads[l] - 1.0)}});
      if (!json)
        std::printf("Ocvirk W = %6.0f N: h_min %.2f um (ref %.2f um), force at ref e %.1f %%\n",
                    kLoads[l], 1e6 * hmin, 1e6 * ref[l].loads.min_film,
                    100 * (F_at_ref / kLoads[l] - 1.0));
    }
    out["ocvirk"] = {{"eval_us", best}, {"loads", errs}};
    if (!json) std::printf("Ocvirk eval %.3f us\n", best);
  }
  if (json) std::cout << out.dump(1) << "\n";
  else std::printf("converged grid (load and h_min within 1 %%): %s\n", converged.c_str());
  return 0;
}
