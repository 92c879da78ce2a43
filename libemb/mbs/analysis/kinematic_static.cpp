// Kinematic (nDOF = 0), static and quasi-static analyses (analysis.h).

#include <cmath>
#include <numbers>
#include <limits>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis_internal.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/dae/linearization.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs::internal {
namespace {

// Static residual R(q, lambda) = [f(q, 0, t) - C^T lambda; Phi(q, t)] and what its Jacobian
// needs.
struct StaticEval {
  Eigen::VectorXd r;
  ConstraintJacobian C;
  double f_scale{0.0};  // max |f|
  std::vector<BodyKinematics> bodies;
};

StaticEval EvalStatic(const System& sys, const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
                      double t, ConstraintWorkspace* ws) {
  StaticEval e;
  e.bodies = CalcBodyKinematics(sys, q, Eigen::VectorXd());
  ConstraintEval c = CalcConstraints(sys, e.bodies, t, ws);
  const Eigen::VectorXd f = CalcGeneralizedForces(sys, e.bodies, t, ws);
  e.r.resize(f.size() + c.phi.size());
  e.r << f - c.jacobian.transpose() * lambda, c.phi;
  e.f_scale = f.size() ? f.cwiseAbs().maxCoeff() : 0.0;
  e.C = std::move(c.jacobian);
  return e;
}

// K = dR/d[x, lambda] = [df/dx - sum_k lambda_k K_k, -C^T; C, 0] in x = [delta p, delta pi].
Eigen::MatrixXd StaticJacobian(const System& sys, const StaticEval& e, const Eigen::VectorXd& q,
                               const Eigen::VectorXd& lambda, double t,
                               ConstraintWorkspace* ws) {
  const int nv = sys.layout().nv(), m = sys.num_equations();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nv + m, nv + m);
  K.topLeftCorner(nv, nv) = CalcTangentStiffness(sys, q, Eigen::VectorXd(), lambda, t, ws);
  const Eigen::MatrixXd C(e.C);
  K.block(0, nv, nv, m) = -C.transpose();
  K.block(nv, 0, m, nv) = C;
  return K;
}

// "body 'crank' moment y" for component i of a v-space vector.
std::string ForceComponentName(const System& sys, int i) {
  const StateLayout& L = sys.layout();
  if (i >= StateLayout::kVPerBody * L.num_moving()) {
    for (int b = 1; b < sys.num_bodies(); ++b)
      if (L.num_elastic(b) && i >= L.elastic_v(b) && i < L.elastic_v(b) + L.num_elastic(b))
        return "body '" + sys.body(b).name + "' modal force " + std::to_string(i - L.elastic_v(b));
  }
  const int b = i / StateLayout::kVPerBody + 1;
  const int c = i % StateLayout::kVPerBody;
  static const char* kNames[] = {"force x (W)",  "force y (W)",  "force z (W)",
                                 "moment x (B)", "moment y (B)", "moment z (B)"};
  return "body '" + sys.body(b).name + "' " + kNames[c];
}

// Newton on the static residual, x updated on the rotation manifold (ApplyDisplacement).
// Convergence: max |r_f| <= tol_f (1 + max |f|) and max |Phi| <= tol_Phi. Steps are damped by
// backtracking on the merit phi = |W r|^2 / 2, W = diag(1/(tol_f (1 + max |f|)), 1/tol_Phi)
// fixed per iteration, with the Armijo condition phi(a) <= (1 - 2 c a) phi(0), for which the
// Newton direction is a descent direction whenever the stiffness is regular.
StaticReport SolveStatic(const System& sys, double t, const AnalysisSettings& s,
                         ConstraintWorkspace* ws, Eigen::VectorXd* q, Eigen::VectorXd* lambda) {
  const int nv = sys.layout().nv();
  const int m = sys.num_equations();
  // Armijo sufficient-decrease constant and the smallest step tried (2^-30).
  constexpr double kArmijo = 1e-4;
  constexpr int kMaxHalvings = 30;
  StaticReport rep;
  rep.t = t;
  StaticEval e = EvalStatic(sys, *q, *lambda, t, ws);
  ++rep.residual_evals;
  auto weights = [&](const StaticEval& ev) {
    Eigen::VectorXd w(nv + m);
    w.head(nv).setConstant(1.0 / (s.static_force_tolerance * (1.0 + ev.f_scale)));
    w.tail(m).setConstant(1.0 / s.assembly.tolerance);
    return w;
  };
  auto describe = [&](const StaticEval& ev) {
    rep.force_residual = 0.0;
    rep.position_residual = 0.0;
    rep.worst_force.clear();
    rep.worst_equation.clear();
    Eigen::Index i = 0;
    if (nv) {
      rep.force_residual = ev.r.head(nv).cwiseAbs().maxCoeff(&i) / (1.0 + ev.f_scale);
      rep.worst_force = ForceComponentName(sys, static_cast<int>(i));
    }
    if (m) {
      rep.position_residual = ev.r.tail(m).cwiseAbs().maxCoeff(&i);
      rep.worst_equation = sys.EquationName(static_cast<int>(i));
    }
  };
  for (rep.iterations = 0;; ++rep.iterations) {
    describe(e);
    if (!e.r.allFinite()) {
      rep.status = NewtonStatus::kNonFinite;
      return rep;
    }
    if (rep.force_residual <= s.static_force_tolerance &&
        rep.position_residual <= s.assembly.tolerance) {
      rep.status = NewtonStatus::kConverged;
      return rep;
    }
    if (rep.iterations == s.static_max_iterations) {
      rep.status = NewtonStatus::kMaxIterations;
      return rep;
    }
    const Eigen::MatrixXd K = StaticJacobian(sys, e, *q, *lambda, t, ws);
    const Eigen::VectorXd step = -K.completeOrthogonalDecomposition().solve(e.r);
    const Eigen::VectorXd w = weights(e);
    const double phi0 = 0.5 * e.r.cwiseProduct(w).squaredNorm();
    double alpha = 1.0;
    bool accepted = false;
    for (int halving = 0; halving <= kMaxHalvings; ++halving, alpha *= 0.5) {
      const Eigen::VectorXd q_try = ApplyDisplacement(sys, *q, alpha * step.head(nv));
      const Eigen::VectorXd l_try = *lambda + alpha * step.tail(m);
      StaticEval e_try = EvalStatic(sys, q_try, l_try, t, ws);
      ++rep.residual_evals;
      const double phi = 0.5 * e_try.r.cwiseProduct(w).squaredNorm();
      if (std::isfinite(phi) && phi <= (1.0 - 2.0 * kArmijo * alpha) * phi0) {
        *q = q_try;
        *lambda = l_try;
        e = std::move(e_try);
        accepted = true;
        break;
      }
    }
    rep.last_step_length = accepted ? alpha : 0.0;
    if (!accepted) {
      rep.status = NewtonStatus::kLineSearchFailed;
      return rep;
    }
  }
}

std::string StaticFailureMessage(const StaticReport& r, const AnalysisSettings& s) {
  std::ostringstream msg;
  msg << "static equilibrium at t = " << r.t << " s not found (" << Name(r.status) << ") after "
      << r.iterations << " Newton iterations: relative force residual " << r.force_residual;
  if (!r.worst_force.empty()) msg << " at " << r.worst_force;
  msg << " (tolerance " << s.static_force_tolerance << "), constraint residual "
      << r.position_residual;
  if (!r.worst_equation.empty()) msg << " at " << r.worst_equation;
  msg << " (tolerance " << s.assembly.tolerance << ")";
  if (r.status == NewtonStatus::kLineSearchFailed)
    msg << "; no step down to 2^-30 of the Newton step reduced the residual: the stiffness is "
           "singular or indefinite there (an unloaded free motion, a limit point of the load) "
           "or the start is too far";
  if (r.status == NewtonStatus::kMaxIterations)
    msg << "; raise static_iterations or start closer to equilibrium";
  return msg.str();
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
  const Eigen::MatrixXd M =
      CalcMassMatrix(sys, CalcBodyKinematics(sys, run.q0, Eigen::VectorXd()));
  Eigen::VectorXd q = run.q0, v = Eigen::VectorXd::Zero(sys.layout().nv());
  const OutputTimes times(settings);
  const StateLayout& L = sys.layout();
  for (long long k = 0; k < times.size(); ++k) {
    const double t = times[k];
    // Predictor: move along the previous velocity, then close the loop by Newton. The angle
    // kernels follow a turn only within +-pi of their last value (ConstraintWorkspace), so
    // an output step over which a body turns more than a quarter turn is crossed in
    // sub-steps of at most that, each with its own velocity.
    const double dt = k ? t - times[k - 1] : 0.0;
    double turn = 0.0;  // [rad] the largest rotation of a body over dt at the last speed
    for (int b = 1; b < sys.num_bodies(); ++b)
      turn = std::max(turn, dt * v.segment<3>(L.angular_velocity(b)).norm());
    constexpr double kQuarterTurn = 0.5 * std::numbers::pi;
    const int substeps = static_cast<int>(std::min(1e6, std::ceil(turn / kQuarterTurn)));
    for (int s = 1; s <= std::max(1, substeps); ++s) {
      const double ts = s == substeps || substeps <= 1 ? t : times[k - 1] + dt * s / substeps;
      const double h = substeps > 1 ? dt / substeps : dt;
      const AssemblyResult a =
          AssemblePositions(sys, ApplyDisplacement(sys, q, h * v), ts, &ws, settings.assembly);
      r.newton_iterations += a.iterations;
      if (!a.converged) {
        r.status = RunStatus::kNewtonFailure;
        r.message = "kinematic analysis at t = " + std::to_string(ts) + " s: " + a.message;
        return r;
      }
      q = a.q;
      if (s < substeps) {  // the velocity at the sub-step, for the next predictor
        const ConstraintEval cs = CalcConstraints(sys, CalcBodyKinematics(sys, q, Eigen::VectorXd()), ts, &ws);
        v = Eigen::MatrixXd(cs.jacobian).partialPivLu().solve(-cs.phi_t);
      }
    }
    const auto bodies = CalcBodyKinematics(sys, q, Eigen::VectorXd());
    const ConstraintEval c0 = CalcConstraints(sys, bodies, t, &ws);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu((Eigen::MatrixXd(c0.jacobian)));
    v = lu.solve(-c0.phi_t);
    const auto bodies_v = CalcBodyKinematics(sys, q, v);
    const ConstraintEval c = CalcConstraints(sys, bodies_v, t, &ws);
    const Eigen::VectorXd vdot = lu.solve(c.gamma());
    const Eigen::VectorXd f = CalcGeneralizedForces(sys, bodies_v, t, &ws);
    const Eigen::VectorXd lambda =
        Eigen::MatrixXd(c.jacobian.transpose()).partialPivLu().solve(f - M * vdot);
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
  const OutputTimes times(settings, /*single=*/!sequence);
  for (long long k = 0; k < times.size(); ++k) {
    const double t = times[k];
    r.static_report = SolveStatic(sys, t, settings, &ws, &q, &lambda);
    r.newton_iterations += r.static_report.iterations;
    if (!r.static_report.ok()) {
      r.status = RunStatus::kNewtonFailure;
      r.message = StaticFailureMessage(r.static_report, settings);
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
