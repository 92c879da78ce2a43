#include "libemb/mbs/constraints/assembly.h"

#include <cmath>

#include "libemb/common/error.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

Eigen::MatrixXd Kkt(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C) {
  const auto n = M.rows(), m = C.rows();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + m, n + m);
  K.topLeftCorner(n, n) = M;
  K.topRightCorner(n, m) = C.transpose();
  K.bottomLeftCorner(m, n) = C;
  return K;
}

Eigen::VectorXd SolveKkt(const Eigen::MatrixXd& K, const Eigen::VectorXd& rhs, const char* what) {
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(K);
  const Eigen::VectorXd x = lu.solve(rhs);
  // Relative residual beyond which the KKT matrix is taken as singular (redundant rows).
  constexpr double kKktResidualTolerance = 1e-8;
  const double r = (K * x - rhs).norm();
  if (!x.allFinite() || r > kKktResidualTolerance * (1.0 + rhs.norm()))
    EMB_THROW(NumericalError, what << ": the constraint Jacobian is rank deficient (redundant "
                                      "constraints?); run `emb dof` on the scene");
  return x;
}

}  // namespace

Eigen::VectorXd ApplyDisplacement(const System& system, const Eigen::VectorXd& q,
                                  const Eigen::VectorXd& dx) {
  const StateLayout& L = system.layout();
  Eigen::VectorXd out = q;
  for (int b = 1; b < system.num_bodies(); ++b) {
    out.segment<3>(L.position(b)) += dx.segment<3>(L.velocity(b));
    out.segment<4>(L.quaternion(b)) =
        RotateQuaternion(q.segment<4>(L.quaternion(b)), dx.segment<3>(L.angular_velocity(b)));
    const int ne = L.num_elastic(b);
    if (ne && dx.size() == L.nv()) out.segment(L.elastic_q(b), ne) += dx.segment(L.elastic_v(b), ne);
  }
  return out;
}

AssemblyResult AssemblePositions(const System& system, const Eigen::VectorXd& q0, double t,
                                 ConstraintWorkspace* workspace, const AssemblyOptions& options) {
  EMB_CHECK(system.finalized());
  AssemblyResult r;
  r.q = q0;
  // Normalise the quaternions of the starting guess.
  for (int b = 1; b < system.num_bodies(); ++b)
    r.q.segment<4>(system.layout().quaternion(b)).normalize();
  const Eigen::VectorXd no_v;
  auto eval = [&](const Eigen::VectorXd& q) {
    return CalcConstraints(system, CalcBodyKinematics(system, q, no_v), t, workspace);
  };
  ConstraintEval c = eval(r.q);
  double res = c.phi.size() ? c.phi.cwiseAbs().maxCoeff() : 0.0;
  // Only the rigid-body coordinates move: the modal coordinates of flexible bodies keep
  // their initial values (the joints must close with the given deformation).
  const int rigid_v = StateLayout::kVPerBody * system.layout().num_moving();
  for (r.iterations = 0; r.iterations < options.max_iterations && res > options.tolerance;
       ++r.iterations) {
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(
        Eigen::MatrixXd(c.jacobian).leftCols(rigid_v));
    const Eigen::VectorXd dx = -cod.solve(c.phi);
    // Backtracking: halve the step while the residual grows (far from the solution).
    double step = 1.0;
    Eigen::VectorXd q_try;
    ConstraintEval c_try;
    double res_try = 0.0;
    for (int halving = 0; halving < 12; ++halving, step *= 0.5) {
      q_try = ApplyDisplacement(system, r.q, step * dx);
      c_try = eval(q_try);
      res_try = c_try.phi.cwiseAbs().maxCoeff();
      if (res_try < res || !std::isfinite(res)) break;
    }
    r.q = q_try;
    c = c_try;
    res = res_try;
  }
  r.residual = res;
  r.converged = res <= options.tolerance;
  if (!r.converged) {
    const WorstEquation w = FindWorstEquation(c.phi);
    r.worst_equation = w.equation;
    if (w.equation >= 0) r.worst_name = system.EquationName(w.equation);
    std::ostringstream o;
    o << "position assembly did not close after " << r.iterations
      << " Newton iterations: max |Phi| = " << res << " (tolerance " << options.tolerance << ") at "
      << r.worst_name;
    r.message = o.str();
  }
  return r;
}

VelocityProjection ProjectVelocities(const System& system, const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& v0, double t,
                                     ConstraintWorkspace* workspace) {
  const auto bodies = CalcBodyKinematics(system, q, v0);
  const ConstraintEval c = CalcConstraints(system, bodies, t, workspace);
  const Eigen::MatrixXd M = CalcMassMatrix(system, bodies);
  // Only the rigid-body velocities move (as in the position assembly): the modal rates of
  // flexible bodies keep their initial values, else the cheapest correction in the
  // kinetic-energy metric would be a burst of elastic velocity.
  const Eigen::Index n = StateLayout::kVPerBody * system.layout().num_moving();
  const Eigen::Index m = c.jacobian.rows();
  const Eigen::MatrixXd C(c.jacobian);
  const Eigen::MatrixXd Mr = M.topLeftCorner(n, n);
  Eigen::VectorXd rhs(n + m);
  rhs << Mr * v0.head(n), -c.phi_t - C.rightCols(M.rows() - n) * v0.tail(M.rows() - n);
  const Eigen::VectorXd x = SolveKkt(Kkt(Mr, C.leftCols(n)), rhs, "velocity projection");
  VelocityProjection p;
  p.v = v0;
  p.v.head(n) = x.head(n);
  const Eigen::VectorXd dv = p.v - v0;
  const double e0 = v0.dot(M * v0);
  const double de = dv.dot(M * dv);
  p.relative_change = e0 > 0.0 ? std::sqrt(de / e0) : std::sqrt(de);
  p.velocity_residual = m ? (c.jacobian * p.v + c.phi_t).cwiseAbs().maxCoeff() : 0.0;
  return p;
}

AccelerationSolution SolveAccelerations(const System& system, const Eigen::VectorXd& q,
                                        const Eigen::VectorXd& v, double t,
                                        ConstraintWorkspace* workspace) {
  const auto bodies = CalcBodyKinematics(system, q, v);
  const ConstraintEval c = CalcConstraints(system, bodies, t, workspace);
  Eigen::MatrixXd M = CalcMassMatrix(system, bodies);
  // Quasi-static modes have no inertia, so M is singular in their rows. Their rates are
  // algebraic in the DAE (set by D eta' = loads - K eta), and what this solve gives the
  // integrator for them is only a starting guess: solve with the unit modal mass they had
  // before they were made quasi-static (mass-normalised modes), which keeps the system
  // regular; the first step settles them.
  const StateLayout& L = system.layout();
  for (int b = 1; b < system.num_bodies(); ++b)
    for (int j = 0; j < L.num_elastic(b); ++j)
      if (system.body(b).elastic->is_quasi_static(j))
        M(L.elastic_v(b) + j, L.elastic_v(b) + j) += 1.0;
  const auto n = M.rows(), m = c.jacobian.rows();
  Eigen::VectorXd rhs(n + m);
  rhs << CalcGeneralizedForces(system, bodies, t, workspace), c.gamma();
  const Eigen::VectorXd x =
      SolveKkt(Kkt(M, Eigen::MatrixXd(c.jacobian)), rhs, "acceleration solve");
  return {x.head(n), x.tail(m)};
}

}  // namespace emb::mbs
