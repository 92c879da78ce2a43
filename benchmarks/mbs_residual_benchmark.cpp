// Cost of one GGL residual and one iteration-matrix (Jacobian) evaluation, dense and sparse
// (compressed-column values refilled on the fixed structure), vs the number of bodies: a
// planar chain of N rods joined by revolute joints (5 N equations).
//   build/benchmarks/mbs_residual_benchmark

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/ggl_dae.h"

namespace {

using namespace emb::mbs;

System Chain(int n) {
  System s;
  const double l = 0.3;
  s.AddMarker("o", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  for (int k = 0; k < n; ++k) {
    RigidBody b;
    b.name = "link" + std::to_string(k);
    b.mass = 1.0;
    b.inertia_B = Eigen::Vector3d(1e-4, l * l / 12, l * l / 12).asDiagonal();
    b.p_WB = Eigen::Vector3d((k + 0.5) * l, 0, 0);
    s.AddBody(b);
    s.AddMarker(b.name + "_a", b.name, Eigen::Vector3d(-0.5 * l, 0, 0),
                Eigen::Matrix3d::Identity());
    s.AddMarker(b.name + "_b", b.name, Eigen::Vector3d(0.5 * l, 0, 0), Eigen::Matrix3d::Identity());
    s.AddJoint("j" + std::to_string(k), JointType::kRevolute, b.name + "_a",
               k == 0 ? "o" : "link" + std::to_string(k - 1) + "_b");
  }
  s.SetGravity(Eigen::Vector3d(0, -9.81, 0));
  s.Finalize();
  return s;
}

struct Fixture {
  explicit Fixture(int n) : sys(Chain(n)), dae(sys) {
    AnalysisSettings st;
    const PreparedRun run = PrepareRun(sys, st);
    ThrowIfNotReady(run);
    ConstraintWorkspace& ws = dae.workspace();
    const AccelerationSolution acc = SolveAccelerations(sys, run.q0, run.v0, 0.0, &ws);
    dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &y, &yp);
  }
  System sys;
  GglDae dae;
  Eigen::VectorXd y, yp;
};

void BM_Residual(benchmark::State& state) {
  Fixture f(static_cast<int>(state.range(0)));
  Eigen::VectorXd r(f.dae.size());
  for (auto _ : state) {
    f.dae.CalcResidual(0.0, f.y, f.yp, r);
    benchmark::DoNotOptimize(r.data());
  }
  state.counters["unknowns"] = f.dae.size();
}

void BM_Jacobian(benchmark::State& state) {
  Fixture f(static_cast<int>(state.range(0)));
  Eigen::MatrixXd J(f.dae.size(), f.dae.size());
  for (auto _ : state) {
    f.dae.CalcJacobian(0.0, 100.0, f.y, f.yp, J);
    benchmark::DoNotOptimize(J.data());
  }
  state.counters["unknowns"] = f.dae.size();
}

void BM_SparseJacobian(benchmark::State& state) {
  Fixture f(static_cast<int>(state.range(0)));
  emb::SparseMatrixd J;
  f.dae.CalcSparseJacobian(0.0, 100.0, f.y, f.yp, &J);  // structure, once
  for (auto _ : state) {
    f.dae.CalcSparseJacobian(0.0, 100.0, f.y, f.yp, &J);  // values refilled
    benchmark::DoNotOptimize(J.valuePtr());
  }
  state.counters["unknowns"] = f.dae.size();
  state.counters["nnz"] = static_cast<double>(J.nonZeros());
}

BENCHMARK(BM_Residual)->RangeMultiplier(2)->Range(1, 64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Jacobian)->RangeMultiplier(2)->Range(1, 64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SparseJacobian)->RangeMultiplier(2)->Range(1, 64)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
