// Work-precision of the multibody DAE (GGL index-2 on IDA): error against a reference vs
// wall time over a tolerance sweep, for the slider-crank (reference: closed form of the
// piston position) and the seed's single-cylinder engine, variant (c) (reference: the same
// run at rtol 1e-11); each also with the earlier fixed multiplier atol (1e-4 of the model's
// forces) against the default that follows rtol (AnalysisSettings).
//   build/benchmarks/mbs_work_precision [repeats] [--json]
// Prints one line per (model, rtol): IDA steps, residual and Jacobian evaluations, the
// linear solver the automatic choice took, wall time per run (best of `repeats`), and the
// max error over the output times; then dense vs KLU on chains of N rods. With --json the
// same numbers as one JSON document on stdout (benchmarks/record.py stores it with the
// commit and machine in benchmarks/results/mbs_work_precision.json).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/scene/scene.h"

namespace {

using emb::mbs::AnalysisSettings;
using emb::mbs::RunResult;
using emb::mbs::Sample;

struct Outcome {
  RunResult result;
  std::vector<Eigen::VectorXd> q;
  std::vector<double> t;
  double seconds{0};
};

// The multipliers' Newton atol (AnalysisSettings): the default follows rtol below rtol 1e-6
// (min(1e-4, 100 rtol) F_ref); kFixed is the earlier 1e-4 F_ref at every rtol.
enum class MultiplierRule { kFollowsRtol, kFixed };
constexpr double kEarlierFixedFraction = 1e-4;

Outcome Run(const emb::scene::Scene& sc, AnalysisSettings s, double rtol, int repeats,
            MultiplierRule rule = MultiplierRule::kFollowsRtol) {
  s.type = emb::mbs::AnalysisType::kDynamic;
  if (rule == MultiplierRule::kFixed) s.multiplier_atol_relative = kEarlierFixedFraction;
  s.ida.rtol = rtol;
  s.ida.atol = rtol * 1e-2;  // the analysis raises it to the model's floor if needed
  Outcome best;
  best.seconds = 1e300;
  for (int k = 0; k < repeats; ++k) {
    Outcome o;
    const auto start = std::chrono::steady_clock::now();
    const emb::mbs::PreparedRun run = emb::mbs::PrepareRun(sc.system, s);
    emb::mbs::ThrowIfNotReady(run);
    o.result = emb::mbs::RunAnalysis(run, s, [&](const Sample& smp) {
      o.q.push_back(smp.q);
      o.t.push_back(smp.t);
    });
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (o.seconds < best.seconds) best = std::move(o);
  }
  return best;
}

// The counters of one run, as a JSON object.
nlohmann::json Counters(const Outcome& o) {
  return {{"status", emb::mbs::Name(o.result.status)},
          {"message", o.result.message},
          {"steps", o.result.ida_stats.steps},
          {"residual_evals", o.result.ida_stats.residual_evals},
          {"jacobian_evals", o.result.ida_stats.jacobian_evals},
          {"full_factorizations", o.result.ida_stats.full_factorizations},
          {"jacobian_nonzeros", o.result.jacobian_nonzeros},
          {"linear_solver", emb::Name(o.result.linear_solver)},
          {"seconds", o.seconds}};
}

void PrintRow(const char* model, double rtol, const Outcome& o, double error, bool json,
              nlohmann::json* rows) {
  if (json) {
    nlohmann::json row = Counters(o);
    row["model"] = model;
    row["rtol"] = rtol;
    row["max_error_m"] = error;
    rows->push_back(row);
    return;
  }
  std::printf("%-14s %8.0e %8ld %9ld %7ld %6s %10.4f %12.3e %s\n", model, rtol,
              o.result.ida_stats.steps, o.result.ida_stats.residual_evals,
              o.result.ida_stats.jacobian_evals, emb::Name(o.result.linear_solver), o.seconds,
              error, o.result.ok() ? "" : o.result.message.c_str());
}

// One row of the multiplier-rule comparison: the earlier fixed atol against the default.
void CompareRules(const char* model, double rtol, const Outcome& fixed, double fixed_error,
                  const Outcome& follows, double follows_error, bool json, nlohmann::json* rows) {
  if (json) {
    rows->push_back({{"model", model},
                     {"rtol", rtol},
                     {"fixed", Counters(fixed)},
                     {"fixed_multiplier_atol", fixed.result.multiplier_atol},
                     {"fixed_max_error_m", fixed_error},
                     {"follows_rtol", Counters(follows)},
                     {"follows_rtol_multiplier_atol", follows.result.multiplier_atol},
                     {"follows_rtol_max_error_m", follows_error}});
    return;
  }
  std::printf("%-14s %8.0e  fixed: %6ld steps, error %10.3e   follows rtol: %6ld steps, "
              "error %10.3e\n",
              model, rtol, fixed.result.ida_stats.steps, fixed_error,
              follows.result.ida_stats.steps, follows_error);
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 3;
  bool json = false;
  for (int k = 1; k < argc; ++k) {
    if (std::string(argv[k]) == "--json")
      json = true;
    else
      repeats = std::atoi(argv[k]);
  }
  nlohmann::json work_precision = nlohmann::json::array(), chains = nlohmann::json::array(),
                 rules = nlohmann::json::array();
  const std::string dir = std::string(EMB_SOURCE_DIR) + "/tools/scenes/";
  if (!json)
    std::printf("%-14s %8s %8s %9s %7s %6s %10s %12s\n", "model", "rtol", "steps", "residuals",
                "jacobians", "solver", "wall [s]", "max error");

  // Slider-crank, one crank revolution at 600 rpm, piston position vs the closed form.
  {
    const emb::scene::Scene sc = emb::scene::LoadScene(dir + "slider_crank.yaml");
    const int piston = sc.system.FindBody("piston");
    const double r = 0.05, l = 0.2, w = 2 * std::numbers::pi * 10;
    auto error = [&](const Outcome& o) {
      double err = 0;
      for (std::size_t k = 0; k < o.t.size(); ++k) {
        const double a = w * o.t[k];
        const double x = r * std::cos(a) + std::sqrt(l * l - r * r * std::sin(a) * std::sin(a));
        err = std::max(err, std::abs(o.q[k][sc.system.layout().position(piston)] - x));
      }
      return err;
    };
    for (double rtol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10}) {
      const Outcome o = Run(sc, sc.analysis, rtol, repeats);
      PrintRow("slider-crank", rtol, o, error(o), json, &work_precision);
      const Outcome fixed = Run(sc, sc.analysis, rtol, repeats, MultiplierRule::kFixed);
      CompareRules("slider-crank", rtol, fixed, error(fixed), o, error(o), json, &rules);
    }
  }
  // Single-cylinder engine (c): 2 DOF, bushing big end, gas force; one 4-stroke cycle.
  {
    const emb::scene::Scene sc = emb::scene::LoadScene(dir + "engine_c.yaml");
    // The reference with the tighter of the two multiplier rules at rtol 1e-11 (its
    // multipliers' atol 1e-9 F_ref), so that neither rule is its own reference.
    const Outcome ref = Run(sc, sc.analysis, 1e-11, 1);
    auto error = [&](const Outcome& o) {
      double err = 0;
      // Positions only (p_WB of every body), quaternion parts excluded to keep units [m].
      for (std::size_t k = 0; k < std::min(o.q.size(), ref.q.size()); ++k)
        for (int b = 1; b < sc.system.num_bodies(); ++b)
          err = std::max(err, (o.q[k].segment<3>(sc.system.layout().position(b)) -
                               ref.q[k].segment<3>(sc.system.layout().position(b)))
                                  .cwiseAbs()
                                  .maxCoeff());
      return err;
    };
    for (double rtol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9}) {
      const Outcome o = Run(sc, sc.analysis, rtol, repeats);
      PrintRow("engine (c)", rtol, o, error(o), json, &work_precision);
      const Outcome fixed = Run(sc, sc.analysis, rtol, repeats, MultiplierRule::kFixed);
      CompareRules("engine (c)", rtol, fixed, error(fixed), o, error(o), json, &rules);
    }
  }
  // Linear solver: a chain of N rods (planar, revolute joints), 1 s, rtol 1e-6, dense vs KLU
  // (dense skipped at 64 links: ~0.5 s per factorisation of the 1536-unknown matrix).
  if (!json)
    std::printf("\n%-14s %8s %8s %9s %7s %7s %9s %10s\n", "chain", "solver", "steps", "residuals",
                "jacobians", "full LU", "nnz", "wall [s]");
  for (int n : {1, 2, 4, 16, 32, 64}) {
    emb::mbs::System chain;
    const double l = 0.3;
    chain.AddMarker("o", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
    for (int k = 0; k < n; ++k) {
      emb::mbs::RigidBody b;
      b.name = "link" + std::to_string(k);
      b.mass = 1.0;
      b.inertia_B = Eigen::Vector3d(1e-4, l * l / 12, l * l / 12).asDiagonal();
      b.p_WB = Eigen::Vector3d((k + 0.5) * l, 0, 0);
      chain.AddBody(b);
      chain.AddMarker(b.name + "_a", b.name, Eigen::Vector3d(-0.5 * l, 0, 0),
                      Eigen::Matrix3d::Identity());
      chain.AddMarker(b.name + "_b", b.name, Eigen::Vector3d(0.5 * l, 0, 0),
                      Eigen::Matrix3d::Identity());
      chain.AddJoint("j" + std::to_string(k), emb::mbs::JointType::kRevolute, b.name + "_a",
                     k == 0 ? "o" : "link" + std::to_string(k - 1) + "_b");
    }
    chain.SetGravity(Eigen::Vector3d(0, -9.81, 0));
    chain.Finalize();
    emb::scene::Scene sc;
    sc.system = chain;
    sc.analysis.t_end = 1.0;
    sc.analysis.output_step = 0.1;
    for (auto ls : {emb::LinearSolverKind::kDense, emb::LinearSolverKind::kKlu}) {
      if (n > 32 && ls == emb::LinearSolverKind::kDense) continue;
      sc.analysis.ida.linear_solver = ls;
      const int chain_repeats = n > 16 ? 1 : 3;
      const Outcome o = Run(sc, sc.analysis, 1e-6, chain_repeats);
      if (json) {
        nlohmann::json row = Counters(o);
        row["bodies"] = n;
        row["unknowns"] = 24 * n;
        row["repeats"] = chain_repeats;
        chains.push_back(row);
        continue;
      }
      std::printf("%-14d %8s %8ld %9ld %7ld %7ld %9ld %10.4f %s\n", n, emb::Name(ls),
                  o.result.ida_stats.steps, o.result.ida_stats.residual_evals,
                  o.result.ida_stats.jacobian_evals, o.result.ida_stats.full_factorizations,
                  o.result.jacobian_nonzeros, o.seconds,
                  o.result.ok() ? "" : o.result.message.c_str());
    }
  }
  if (json)
    std::cout << nlohmann::json{{"repeats", repeats},
                                {"work_precision", work_precision},
                                {"multiplier_rule", rules},
                                {"chains", chains}}
                     .dump(1)
              << std::endl;
  return 0;
}
