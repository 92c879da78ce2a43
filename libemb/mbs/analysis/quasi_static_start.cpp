#include "libemb/mbs/analysis/quasi_static_start.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/core/elastic_model.h"

namespace emb::mbs {
namespace {

// The elastic coordinates of a system: their q and v indices and w_j^2.
struct ElasticIndex {
  std::vector<int> q, v;
  Eigen::VectorXd omega2;   // [rad^2/s^2]
  Eigen::VectorXd h;        // forward-difference steps [eta units]
};

ElasticIndex IndexElastic(const System& system) {
  const StateLayout& L = system.layout();
  ElasticIndex e;
  std::vector<double> w2, h;
  for (int b = 1; b < system.num_bodies(); ++b) {
    const int ne = L.num_elastic(b);
    if (!ne) continue;
    const ElasticModel& m = *system.body(b).elastic;
    // eta of a mass-normalised mode is a displacement times sqrt(kg): a step of 1e-7 m of
    // the body's modal displacement, far inside the linear range and above round-off.
    const double step = 1e-7 * std::sqrt(std::max(system.body(b).mass, 1e-300));
    for (int j = 0; j < ne; ++j) {
      e.q.push_back(L.elastic_q(b) + j);
      e.v.push_back(L.elastic_v(b) + j);
      const double w = 2.0 * std::numbers::pi * m.frequencies_hz[j];
      w2.push_back(std::max(w * w, 1e-300));
      h.push_back(step);
    }
  }
  e.omega2 = Eigen::Map<Eigen::VectorXd>(w2.data(), static_cast<Eigen::Index>(w2.size()));
  e.h = Eigen::Map<Eigen::VectorXd>(h.data(), static_cast<Eigen::Index>(h.size()));
  return e;
}

// eta'' as a function of the elastic coordinates and rates at a consistent state: the rigid
// coordinates re-assembled and the rigid velocities re-projected about the given ones (the
// deformed interfaces move the joints; assembly and projection move rigid coordinates
// only), so that the solution needs no correction afterwards that would undo it.
class ModalAcceleration {
 public:
  ModalAcceleration(const System& s, const ElasticIndex& e, ConstraintWorkspace* ws,
                    const AssemblyOptions& assembly)
      : system_(s), e_(e), ws_(ws), assembly_(assembly) {}

  // Makes (q, v) consistent at t. @throws NumericalError if the assembly fails.
  void Consistent(double t, Eigen::VectorXd* q, Eigen::VectorXd* v) {
    const AssemblyResult a = AssemblePositions(system_, *q, t, ws_, assembly_);
    EMB_THROW_IF(!a.converged, "the deformed model cannot be assembled: " << a.message);
    *q = a.q;
    *v = ProjectVelocities(system_, *q, *v, t, ws_).v;
  }
  // eta'' at the consistent state about (q, v).
  Eigen::VectorXd operator()(Eigen::VectorXd q, Eigen::VectorXd v, double t) {
    Consistent(t, &q, &v);
    const AccelerationSolution a = SolveAccelerations(system_, q, v, t, ws_);
    Eigen::VectorXd g(static_cast<Eigen::Index>(e_.v.size()));
    for (std::size_t j = 0; j < e_.v.size(); ++j) g[j] = a.vdot[e_.v[j]];
    return g;
  }
  // Full accelerations at (q, v), consistent already (for the motion derivative).
  Eigen::VectorXd Full(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t) {
    return SolveAccelerations(system_, q, v, t, ws_).vdot;
  }

 private:
  const System& system_;
  const ElasticIndex& e_;
  ConstraintWorkspace* ws_;
  AssemblyOptions assembly_;
};

Eigen::VectorXd Gather(const Eigen::VectorXd& x, const std::vector<int>& idx) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(idx.size()));
  for (std::size_t j = 0; j < idx.size(); ++j) out[j] = x[idx[j]];
  return out;
}
void Scatter(const Eigen::VectorXd& x, const std::vector<int>& idx, Eigen::VectorXd* out) {
  for (std::size_t j = 0; j < idx.size(); ++j) (*out)[idx[j]] = x[j];
}

}  // namespace

QuasiStaticStartReport SetQuasiStaticStart(const System& system, double t, Eigen::VectorXd* q,
                                           Eigen::VectorXd* v, ConstraintWorkspace* workspace,
                                           const QuasiStaticStartOptions& options) {
  EMB_CHECK(system.finalized() && q && v && workspace);
  QuasiStaticStartReport r;
  const ElasticIndex e = IndexElastic(system);
  const int ne = static_cast<int>(e.q.size());
  if (ne == 0) {
    r.converged = true;
    r.message = "no elastic coordinates";
    return r;
  }
  ModalAcceleration accel(system, e, workspace, options.assembly);
  // The static displacement of an imbalance g: max_j |g_j| / w_j^2.
  auto measure = [&](const Eigen::VectorXd& g) { return g.cwiseQuotient(e.omega2).cwiseAbs().maxCoeff(); };
  const double eta_floor = 1e-3 * e.h.maxCoeff();
  try {
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    auto jacobian = [&](const Eigen::VectorXd& g0) {
      Eigen::MatrixXd J(ne, ne);
      for (int j = 0; j < ne; ++j) {
        Eigen::VectorXd qj = *q;
        qj[e.q[j]] += e.h[j];
        J.col(j) = (accel(qj, *v, t) - g0) / e.h[j];
      }
      ++r.jacobians;
      lu.compute(J);
      const double rcond = lu.rcond();
      EMB_THROW_IF(!(rcond > 1e-14), "the elastic Jacobian is singular (rcond " << rcond << ")");
    };
    bool have_jacobian = false;
    for (int round = 0; round < options.rounds; ++round) {
      // eta at the current eta': chord iterations on g(eta) = 0.
      bool converged = false;
      Eigen::VectorXd g = accel(*q, *v, t);
      double previous = measure(g);
      for (int it = 0; it < options.max_iterations; ++it) {
        const double tol =
            options.tolerance * std::max(Gather(*q, e.q).cwiseAbs().maxCoeff(), eta_floor);
        if (previous <= tol) {
          converged = true;
          break;
        }
        if (!have_jacobian) {
          jacobian(g);
          have_jacobian = true;
        }
        const Eigen::VectorXd d = lu.solve(-g);
        EMB_THROW_IF(!d.allFinite(), "non-finite elastic correction");
        Eigen::VectorXd eta = Gather(*q, e.q) + d;
        Scatter(eta, e.q, q);
        g = accel(*q, *v, t);
        const double now = measure(g);
        ++r.iterations;
        EMB_THROW_IF(!std::isfinite(now), "the modal accelerations became non-finite");
        if (now > 0.5 * previous && have_jacobian) {
          jacobian(g);  // slow contraction: a fresh Jacobian at the new eta
        }
        previous = now;
      }
      if (!converged) {
        std::ostringstream o;
        o << "the quasi-static start did not converge in " << options.max_iterations
          << " iterations (imbalance " << previous << ")";
        r.message = o.str();
        return r;
      }
      if (round + 1 == options.rounds) break;
      // eta' = -J^{-1} dg/dt along the rigid motion at fixed eta and eta'.
      const double dt = 1e-6 * std::max(1.0, std::abs(t)) + 1e-7;
      accel.Consistent(t, q, v);
      const Eigen::VectorXd vdot = accel.Full(*q, *v, t);
      Eigen::VectorXd motion = *v, dv = vdot;
      for (int j : e.v) motion[j] = 0.0, dv[j] = 0.0;
      const Eigen::VectorXd q1 = ApplyDisplacement(system, *q, dt * motion);
      const Eigen::VectorXd v1 = *v + dt * dv;
      const Eigen::VectorXd dgdt = (accel(q1, v1, t + dt) - accel(*q, *v, t)) / dt;
      if (!have_jacobian) {
        jacobian(accel(*q, *v, t));
        have_jacobian = true;
      }
      const Eigen::VectorXd rate = lu.solve(-dgdt);
      EMB_THROW_IF(!rate.allFinite(), "non-finite elastic rates");
      Scatter(rate, e.v, v);
    }
    accel.Consistent(t, q, v);
    r.residual = measure(accel(*q, *v, t));
  } catch (const std::runtime_error& err) {
    r.message = std::string("the quasi-static start failed: ") + err.what();
    return r;
  }
  r.converged = true;
  r.max_eta = Gather(*q, e.q).cwiseAbs().maxCoeff();
  r.max_eta_rate = Gather(*v, e.v).cwiseAbs().maxCoeff();
  std::ostringstream o;
  o << "quasi-static elastic start: " << r.iterations << " iterations, " << r.jacobians
    << " Jacobian(s) of " << ne << " columns; max |eta| " << r.max_eta << ", max |eta'| "
    << r.max_eta_rate << ", remaining imbalance " << r.residual << " (as a static displacement)";
  r.message = o.str();
  return r;
}

}  // namespace emb::mbs
