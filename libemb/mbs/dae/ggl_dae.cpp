#include "libemb/mbs/dae/ggl_dae.h"

#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/core/elastic_model.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

GglDae::GglDae(const System& system) : GglDae(system, nullptr) {}

GglDae::GglDae(const System& system, GglWorkspace* workspace)
    : system_(system),
      layout_(system.layout().nq(), system.layout().nv(), system.num_equations(),
              system.layout().num_moving(), system.num_force_states()),
      own_(workspace ? nullptr : std::make_unique<GglWorkspace>(system)),
      ws_(workspace ? workspace : own_.get()) {
  EMB_CHECK(ws_->body_maps.size() == static_cast<std::size_t>(system.num_bodies()));
  InitRoots();
}

GglDae::~GglDae() = default;

GglWorkspace::GglWorkspace(const System& system)
    : constraint(system),
      flexible(static_cast<std::size_t>(system.num_bodies())),
      body_maps(static_cast<std::size_t>(system.num_bodies())) {
  int ne_max = 0;
  for (int b = 1; b < system.num_bodies(); ++b)
    ne_max = std::max(ne_max, system.layout().num_elastic(b));
  accel.setZero(6 + ne_max);
  Ma.setZero(6 + ne_max);
}

bool GglDae::UpdateKinematics(const Eigen::Ref<const Eigen::VectorXd>& y) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  const auto q = y.segment(G.q(), G.nq());
  const auto v = y.segment(G.v(), G.nv());
  // A trial iterate the residual cannot be evaluated at: the integrator retries with a
  // smaller step, and if it gives up its report names the unknown (issue 36).
  for (int b = 1; b < system_.num_bodies(); ++b) {
    if (q.segment<4>(L.quaternion(b)).norm() > 0.0) continue;
    std::ostringstream o;
    o << "the quaternion of body " << system_.body(b).name << " is "
      << q.segment<4>(L.quaternion(b)).transpose() << " in a trial iterate";
    ReportRecoverableFailure(o.str());
    return false;
  }
  if (!q.allFinite() || !v.allFinite()) {
    Eigen::Index i = 0;
    const auto qv = y.head(G.v() + G.nv());
    while (std::isfinite(qv[i])) ++i;
    std::ostringstream o;
    o << ComponentName(static_cast<int>(i)) << " is " << qv[i] << " in a trial iterate";
    ReportRecoverableFailure(o.str());
    return false;
  }
  CalcBodyKinematics(system_, q, v, &ws_->bodies);
  CalcAllMarkerKinematics(system_, ws_->bodies, &ws_->markers);
  return true;
}

bool GglDae::DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                            const Eigen::Ref<const Eigen::VectorXd>& yp,
                            Eigen::Ref<Eigen::VectorXd> r) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  GglWorkspace& W = *ws_;
  if (!UpdateKinematics(y)) return false;
  const auto q = y.segment(G.q(), G.nq());
  const auto v = y.segment(G.v(), G.nv());
  const auto vdot = yp.segment(G.v(), G.nv());
  const auto lambda = y.segment(G.lambda(), G.m());
  const auto mu = y.segment(G.mu(), G.num_mu());
  CalcConstraints(system_, W.markers, t, &W.constraint, &W.constraints);
  const ConstraintEval& c = W.constraints;

  // Generalised forces: gravity and gyroscopic terms, flexible bodies' terms (with their mass
  // matrices, kept for the dynamic rows), force elements.
  W.f.setZero(L.nv());
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const RigidBody& body = system_.body(b);
    const BodyKinematics& k = W.bodies[b];
    const int ne = L.num_elastic(b);
    if (ne) {
      const Eigen::Vector3d a_B =
          k.R_WB.transpose() * (vdot.segment<3>(L.velocity(b)) - system_.gravity());
      FlexibleTerms& ft = W.flexible[b];
      CalcFlexibleTerms(*body.elastic, k.p_WB, k.R_WB, k.v_WB, k.omega_B, k.eta, k.eta_dot,
                        system_.gravity(), a_B, kFlexibleMass | kFlexibleForce, nullptr, &ft);
      W.f.segment<6>(L.velocity(b)) += ft.force.head<6>();
      W.f.segment(L.elastic_v(b), ne) += ft.force.tail(ne);
      continue;
    }
    W.f.segment<3>(L.velocity(b)) += body.mass * system_.gravity();
    W.f.segment<3>(L.angular_velocity(b)) -= k.omega_B.cross(body.inertia_B * k.omega_B);
  }
  W.failure.failed = false;
  const double* z = G.nz() ? y.data() + G.z() : nullptr;
  const double* z_dot = G.nz() ? yp.data() + G.z() : nullptr;
  AddElementForces(system_, W.bodies, W.markers, t, &W.constraint, W.f, &W.failure, z, z_dot);
  // The elements' state rows R(t, z, z', q, v).
  if (G.nz()) {
    const auto& forces = system_.force_elements();
    for (std::size_t k = 0; k < forces.size(); ++k) {
      const int offset = system_.force_state_offset(static_cast<int>(k));
      if (offset < 0) continue;
      ForceContext ctx{&system_, &W.bodies, t, &W.constraint,
                       system_.force_angle_slot(static_cast<int>(k))};
      ctx.markers = &W.markers;
      ctx.failure = &W.failure;
      ctx.z = z + offset;
      ctx.z_dot = z_dot + offset;
      forces[k]->CalcStateResidual(
          ctx, r.segment(G.z() + offset, forces[k]->num_continuous_states()));
    }
  }
  if (W.failure.failed) {  // an element outside its domain: the integrator cuts the step
    ReportRecoverableFailure(W.failure.message);
    return false;
  }
  W.force_scale = W.f.size() ? W.f.cwiseAbs().maxCoeff() : 0.0;

  // Kinematic rows: q' - H v + B^T mu, B^T mu = X_b^T (C^T mu)_b + [0; e_b mu_b].
  W.w.noalias() = c.jacobian.transpose() * mu.head(G.m());
  W.reaction.noalias() = c.jacobian.transpose() * lambda;
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const Eigen::Vector4d e = q.segment<4>(L.quaternion(b));
    const auto wb = W.w.segment<6>(L.velocity(b));
    r.segment<3>(G.q() + L.position(b)) =
        yp.segment<3>(G.q() + L.position(b)) - v.segment<3>(L.velocity(b)) + wb.head<3>();
    r.segment<4>(G.q() + L.quaternion(b)) =
        yp.segment<4>(G.q() + L.quaternion(b)) -
        0.5 * QuaternionRateMatrix(e) * v.segment<3>(L.angular_velocity(b)) +
        (2.0 / e.squaredNorm()) * QuaternionRateMatrix(e) * wb.tail<3>() +
        mu[G.m() + b - 1] * e;
    r[G.mu() + G.m() + b - 1] = 0.5 * (e.squaredNorm() - 1.0);
    const int ne = L.num_elastic(b);
    if (ne) {
      // eta' - eta_dot + (C^T mu)_eta; M(eta) [vdot_b; eta''] - f + C^T lambda.
      r.segment(G.q() + L.elastic_q(b), ne) = yp.segment(G.q() + L.elastic_q(b), ne) -
                                              v.segment(L.elastic_v(b), ne) +
                                              W.w.segment(L.elastic_v(b), ne);
      auto accel = W.accel.head(6 + ne);
      auto Ma = W.Ma.head(6 + ne);
      accel << vdot.segment<6>(L.velocity(b)), vdot.segment(L.elastic_v(b), ne);
      Ma.noalias() = W.flexible[b].mass * accel;
      r.segment<6>(G.v() + L.velocity(b)) =
          Ma.head<6>() - W.f.segment<6>(L.velocity(b)) + W.reaction.segment<6>(L.velocity(b));
      r.segment(G.v() + L.elastic_v(b), ne) = Ma.tail(ne) - W.f.segment(L.elastic_v(b), ne) +
                                              W.reaction.segment(L.elastic_v(b), ne);
      continue;
    }
    // Dynamic rows: M v' - f + C^T lambda, M = diag(m I, J_B) per body.
    const RigidBody& body = system_.body(b);
    r.segment<3>(G.v() + L.velocity(b)) = body.mass * yp.segment<3>(G.v() + L.velocity(b)) -
                                          W.f.segment<3>(L.velocity(b)) +
                                          W.reaction.segment<3>(L.velocity(b));
    r.segment<3>(G.v() + L.angular_velocity(b)) =
        body.inertia_B * yp.segment<3>(G.v() + L.angular_velocity(b)) -
        W.f.segment<3>(L.angular_velocity(b)) + W.reaction.segment<3>(L.angular_velocity(b));
  }
  // Velocity and position constraints.
  r.segment(G.lambda(), G.m()).noalias() = c.jacobian * v;
  r.segment(G.lambda(), G.m()) += c.phi_t;
  r.segment(G.mu(), G.m()) = c.phi;
  return r.allFinite();
}

Eigen::VectorXd GglDae::DoDifferentialMask() const {
  Eigen::VectorXd mask = Eigen::VectorXd::Zero(layout_.size());
  mask.head(layout_.nq() + layout_.nv()).setOnes();
  // The rates of quasi-static modes have no inertia: their derivative appears nowhere.
  const StateLayout& L = system_.layout();
  for (int b = 1; b < system_.num_bodies(); ++b)
    for (int j = 0; j < L.num_elastic(b); ++j)
      if (system_.body(b).elastic->is_quasi_static(j)) mask[layout_.v() + L.elastic_v(b) + j] = 0.0;
  // The elements' states: those in the error test are differential.
  ForEachForceState([&](int i, const ForceElement& e, int j) {
    mask[layout_.z() + i] = e.StateErrorWeight(j) > 0.0 ? 1.0 : 0.0;
  });
  return mask;
}

std::vector<std::vector<int>> GglDae::DoDenseBlocks() const {
  const StateLayout& L = system_.layout();
  std::vector<std::vector<int>> blocks;
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const int ne = L.num_elastic(b);
    if (ne == 0) continue;
    std::vector<int> unknowns;
    for (int j = 0; j < ne; ++j) unknowns.push_back(layout_.q() + L.elastic_q(b) + j);
    for (int j = 0; j < ne; ++j) unknowns.push_back(layout_.v() + L.elastic_v(b) + j);
    blocks.push_back(std::move(unknowns));
  }
  return blocks;
}

std::string GglDae::DoComponentName(int i) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  static const char* kQ[] = {"p_WB.x", "p_WB.y", "p_WB.z", "e.w", "e.x", "e.y", "e.z"};
  static const char* kV[] = {"v_WB.x", "v_WB.y", "v_WB.z", "omega_B.x", "omega_B.y", "omega_B.z"};
  auto modal = [&](int k, bool rate) {
    for (int b = 1; b < system_.num_bodies(); ++b) {
      const int start = rate ? L.elastic_v(b) : L.elastic_q(b);
      if (L.num_elastic(b) && k >= start && k < start + L.num_elastic(b))
        return "body '" + system_.body(b).name + "' " + (rate ? "eta'" : "eta") + "[" +
               std::to_string(k - start) + "]";
    }
    return std::string("?");
  };
  const int rigid_q = StateLayout::kQPerBody * L.num_moving();
  const int rigid_v = StateLayout::kVPerBody * L.num_moving();
  if (i < G.v()) {
    if (i >= rigid_q) return modal(i, false);
    const int b = i / StateLayout::kQPerBody + 1;
    return "body '" + system_.body(b).name + "' " + kQ[i - L.position(b)];
  }
  if (i < G.lambda()) {
    const int k = i - G.v();
    if (k >= rigid_v) return modal(k, true);
    const int b = k / StateLayout::kVPerBody + 1;
    return "body '" + system_.body(b).name + "' " + kV[k - L.velocity(b)];
  }
  if (i < G.mu()) return "lambda of " + system_.EquationName(i - G.lambda());
  if (i >= G.z()) {
    std::string name;
    ForEachForceState([&](int s, const ForceElement& e, int j) {
      if (G.z() + s == i) name = "force element '" + e.name() + "' " + e.StateName(j);
    });
    return name;
  }
  const int k = i - G.mu();
  if (k < G.m()) return "mu of " + system_.EquationName(k);
  return "mu of unit quaternion of body '" + system_.body(k - G.m() + 1).name + "'";
}

void GglDae::MakeInitialValues(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& vdot, const Eigen::VectorXd& lambda,
                               Eigen::VectorXd* y, Eigen::VectorXd* yp, const Eigen::VectorXd* z,
                               const Eigen::VectorXd* z_dot) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  y->setZero(G.size());
  yp->setZero(G.size());
  y->segment(G.q(), G.nq()) = q;
  y->segment(G.v(), G.nv()) = v;
  y->segment(G.lambda(), G.m()) = lambda;
  for (int b = 1; b < system_.num_bodies(); ++b) {
    yp->segment<3>(L.position(b)) = v.segment<3>(L.velocity(b));
    yp->segment<4>(L.quaternion(b)) = 0.5 * QuaternionRateMatrix(q.segment<4>(L.quaternion(b))) *
                                      v.segment<3>(L.angular_velocity(b));
    const int ne = L.num_elastic(b);
    if (ne) yp->segment(L.elastic_q(b), ne) = v.segment(L.elastic_v(b), ne);
  }
  yp->segment(G.v(), G.nv()) = vdot;
  if (G.nz() == 0) return;
  if (z != nullptr) {
    EMB_CHECK(z->size() == G.nz() && z_dot != nullptr && z_dot->size() == G.nz());
    y->segment(G.z(), G.nz()) = *z;
    yp->segment(G.z(), G.nz()) = *z_dot;
    return;
  }
  // The elements' steady states at (q, v).
  const std::vector<BodyKinematics> bodies = CalcBodyKinematics(system_, q, v);
  const auto& forces = system_.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const int offset = system_.force_state_offset(static_cast<int>(k));
    if (offset < 0) continue;
    const int n = forces[k]->num_continuous_states();
    const ForceContext ctx{&system_, &bodies, 0.0, &ws_->constraint,
                           system_.force_angle_slot(static_cast<int>(k))};
    forces[k]->CalcSteadyStates(ctx, y->segment(G.z() + offset, n), yp->segment(G.z() + offset, n));
  }
}

void GglDae::ForEachForceState(
    const std::function<void(int, const ForceElement&, int)>& visit) const {
  const auto& forces = system_.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const int offset = system_.force_state_offset(static_cast<int>(k));
    for (int j = 0; j < forces[k]->num_continuous_states(); ++j) visit(offset + j, *forces[k], j);
  }
}

}  // namespace emb::mbs
