// Kinematic (nDOF = 0), static and quasi-static analyses (analysis.h).

#include <cmath>
#include <limits>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis_internal.h"
#include "libemb/mbs/constraint_eval.h"

namespace emb::mbs::internal {
namespace {

// Static residual R(q, lambda) = [f(q, 0, t) - C^T lambda; Phi(q, t)].
Eigen::VectorXd StaticResidual(const System& sys, const Eigen::VectorXd& q,
                               const Eigen::VectorXd& lambda, double t, ConstraintWorkspace* ws,
                               Eigen::MatrixXd* C_out = nullptr, double* f_scale = nullptr) {
  const auto bodies = CalcBodyKinematics(sys, q, Eigen::VectorXd());
  const ConstraintEval c = CalcConstraints(sys, bodies, t, ws);
  const Eigen::VectorXd f = CalcGeneralizedForces(sys, bodies, t, ws);
  Eigen::VectorXd r(f.size() + c.phi.size());
  r << f - c.jacobian.transpose() * lambda, c.phi;
  if (C_out) *C_out = c.jacobian;
  if (f_scale) *f_scale = f.size() ? f.cwiseAbs().maxCoeff() : 0.0;
  return r;
}

struct StaticOutcome {
  bool converged{false};
  int iterations{0};
  double force_residual{0.0}, position_residual{0.0};
};

// Newton on the static residual with a difference-quotient stiffness in [delta p, delta pi]
// and the analytic -C^T / C blocks; backtracking on |R|.
StaticOutcome SolveStatic(const System& sys, double t, const AnalysisSettings& s,
                          ConstraintWorkspace* ws, Eigen::VectorXd* q, Eigen::VectorXd* lambda) {
  const int nv = sys.layout().nv();
  const int m = sys.num_equations();
  StaticOutcome out;
  const double sqrt_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  auto norms = [&](const Eigen::VectorXd& r, double f_scale) {
    const double fr = nv ? r.head(nv).cwiseAbs().maxCoeff() / (1.0 + f_scale) : 0.0;
    const double pr = m ? r.tail(m).cwiseAbs().maxCoeff() : 0.0;
    return std::pair{fr, pr};
  };
  for (out.iterations = 0; out.iterations <= s.static_max_iterations; ++out.iterations) {
    Eigen::MatrixXd C;
    double f_scale = 0.0;
    const Eigen::VectorXd r = StaticResidual(sys, *q, *lambda, t, ws, &C, &f_scale);
    const auto [fr, pr] = norms(r, f_scale);
    out.force_residual = fr;
    out.position_residual = pr;
    if (fr <= s.static_force_tolerance && pr <= s.assembly.tolerance) {
      out.converged = true;
      return out;
    }
    if (out.iterations == s.static_max_iterations) break;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nv + m, nv + m);
    for (int j = 0; j < nv; ++j) {
      Eigen::VectorXd dx = Eigen::VectorXd::Zero(nv);
      dx[j] = sqrt_eps;
      const Eigen::VectorXd r1 =
          StaticResidual(sys, ApplyDisplacement(sys, *q, dx), *lambda, t, ws);
      K.col(j) = (r1 - r) / sqrt_eps;
    }
    K.block(0, nv, nv, m) = -C.transpose();
    const Eigen::VectorXd step = -K.completeOrthogonalDecomposition().solve(r);
    double alpha = 1.0;
    const double r_norm = r.norm();
    for (int halving = 0; halving < 20; ++halving, alpha *= 0.5) {
      const Eigen::VectorXd q_try = ApplyDisplacement(sys, *q, alpha * step.head(nv));
      const Eigen::VectorXd l_try = *lambda + alpha * step.tail(m);
      if (StaticResidual(sys, q_try, l_try, t, ws).norm() < r_norm || halving == 19) {
        *q = q_try;
        *lambda = l_try;
        break;
      }
    }
  }
  return out;
}

}  // namespace

RunResult RunKinematic(const PreparedRun& run, const AnalysisSettings& settings,
                       const SampleSink& sink, const ProgressFn& progress) {
  const System& sys = run.system;
  RunResult r;
  if (run.dof.true_dof != 0 || sys.num_equations() != sys.layout().nv()) {
    r.status = RunStatus::kNotKinematic;
    std::ostringstream o;
    o << "a kinematic analysis needs 0 degrees of freedom; the model has " << run.dof.true_dof
      << " (" << sys.num_equations() << " independent equations for " << sys.layout().nv()
      << " coordinates)";
    r.message = o.str();
    return r;
  }
  ConstraintWorkspace ws(sys);
  const Eigen::MatrixXd M = CalcMassMatrix(sys);
  Eigen::VectorXd q = run.q0, v = Eigen::VectorXd::Zero(sys.layout().nv());
  const std::vector<double> times = OutputTimes(settings);
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    // Predictor: move along the previous velocity, then close the loop by Newton.
    const double dt = k ? t - times[k - 1] : 0.0;
    const AssemblyResult a =
        AssemblePositions(sys, ApplyDisplacement(sys, q, dt * v), t, &ws, settings.assembly);
    r.newton_iterations += a.iterations;
    if (!a.converged) {
      r.status = RunStatus::kNewtonFailure;
      r.message = "kinematic analysis at t = " + std::to_string(t) + " s: " + a.message;
      return r;
    }
    q = a.q;
    const auto bodies = CalcBodyKinematics(sys, q, Eigen::VectorXd());
    const ConstraintEval c0 = CalcConstraints(sys, bodies, t, &ws);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(c0.jacobian);
    v = lu.solve(-c0.phi_t);
    const auto bodies_v = CalcBodyKinematics(sys, q, v);
    const ConstraintEval c = CalcConstraints(sys, bodies_v, t, &ws);
    const Eigen::VectorXd vdot = lu.solve(c.gamma());
    const Eigen::VectorXd f = CalcGeneralizedForces(sys, bodies_v, t, &ws);
    const Eigen::VectorXd lambda = c.jacobian.transpose().partialPivLu().solve(f - M * vdot);
    sink(MakeSample(sys, t, q, v, vdot, lambda, &ws));
    ++r.num_samples;
    r.t_reached = t;
    ReportProgress(progress, "kinematic", static_cast<double>(k + 1) / times.size());
  }
  return r;
}

RunResult RunStatic(const PreparedRun& run, const AnalysisSettings& settings,
                    const SampleSink& sink, const ProgressFn& progress, bool sequence) {
  const System& sys = run.system;
  RunResult r;
  ConstraintWorkspace ws(sys);
  Eigen::VectorXd q = run.q0;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(sys.num_equations());
  const Eigen::VectorXd zero_v = Eigen::VectorXd::Zero(sys.layout().nv());
  const std::vector<double> times =
      sequence ? OutputTimes(settings) : std::vector<double>{settings.t_start};
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    const StaticOutcome o = SolveStatic(sys, t, settings, &ws, &q, &lambda);
    r.newton_iterations += o.iterations;
    if (!o.converged) {
      r.status = RunStatus::kNewtonFailure;
      std::ostringstream msg;
      msg << "static equilibrium at t = " << t << " s not found after " << o.iterations
          << " Newton iterations: relative force residual " << o.force_residual
          << ", constraint residual " << o.position_residual;
      r.message = msg.str();
      return r;
    }
    sink(MakeSample(sys, t, q, zero_v, zero_v, lambda, &ws));
    ++r.num_samples;
    r.t_reached = t;
    ReportProgress(progress, sequence ? "quasi-static" : "static",
                   static_cast<double>(k + 1) / times.size());
  }
  return r;
}

}  // namespace emb::mbs::internal
