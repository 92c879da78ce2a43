#include "libemb/mbs/ggl_dae.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/mbs/dynamics.h"
#include "libemb/mbs/primitive.h"
#include "libemb/mbs/rotation.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

GglDae::GglDae(const System& system)
    : system_(system),
      layout_(system.layout().nq(), system.layout().nv(), system.num_equations(),
              system.layout().num_moving()),
      mass_(CalcMassMatrix(system)),
      workspace_(system) {}

Eigen::MatrixXd GglDae::CalcBTranspose(const Eigen::VectorXd& q, const Eigen::MatrixXd& C) const {
  const StateLayout& L = system_.layout();
  const int m = layout_.m();
  Eigen::MatrixXd Bt = Eigen::MatrixXd::Zero(layout_.nq(), layout_.num_mu());
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const Eigen::Vector4d e = q.segment<4>(L.quaternion(b));
    const double n = e.norm();
    Bt.block(L.position(b), 0, 3, m) = C.middleCols<3>(L.velocity(b)).transpose();
    Bt.block(L.quaternion(b), 0, 4, m) = (2.0 / n) * QuaternionRateMatrix(e / n) *
                                         C.middleCols<3>(L.angular_velocity(b)).transpose();
    Bt.block<4, 1>(L.quaternion(b), m + b - 1) = e;
  }
  return Bt;
}

bool GglDae::DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                            const Eigen::Ref<const Eigen::VectorXd>& yp,
                            Eigen::Ref<Eigen::VectorXd> r) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  const Eigen::VectorXd q = y.segment(G.q(), G.nq());
  const Eigen::VectorXd v = y.segment(G.v(), G.nv());
  const auto lambda = y.segment(G.lambda(), G.m());
  const auto mu = y.segment(G.mu(), G.num_mu());
  for (int b = 1; b < system_.num_bodies(); ++b)
    if (!(q.segment<4>(L.quaternion(b)).norm() > 0.0)) return false;  // retry smaller step
  const auto bodies = CalcBodyKinematics(system_, q, v);
  const ConstraintEval c = CalcConstraints(system_, bodies, t, &workspace_);

  // Kinematic rows: q' - H v + B^T mu.
  auto rq = r.segment(G.q(), G.nq());
  rq = yp.segment(G.q(), G.nq()) + CalcBTranspose(q, c.jacobian) * mu;
  for (int b = 1; b < system_.num_bodies(); ++b) {
    rq.segment<3>(L.position(b)) -= v.segment<3>(L.velocity(b));
    rq.segment<4>(L.quaternion(b)) -= 0.5 * QuaternionRateMatrix(q.segment<4>(L.quaternion(b))) *
                                      v.segment<3>(L.angular_velocity(b));
  }
  // Dynamic rows: M v' - f + C^T lambda.
  r.segment(G.v(), G.nv()) = mass_ * yp.segment(G.v(), G.nv()) -
                             CalcGeneralizedForces(system_, bodies, t, &workspace_) +
                             c.jacobian.transpose() * lambda;
  // Velocity and position constraints.
  r.segment(G.lambda(), G.m()) = c.jacobian * v + c.phi_t;
  r.segment(G.mu(), G.m()) = c.phi;
  for (int b = 1; b < system_.num_bodies(); ++b)
    r[G.mu() + G.m() + b - 1] = 0.5 * (q.segment<4>(L.quaternion(b)).squaredNorm() - 1.0);
  return true;
}

namespace {

// P(w) = d(Q(e) w)/de (Q(e) w is linear in e).
Eigen::Matrix4d RateMatrixDerivative(const Eigen::Vector3d& w) {
  Eigen::Matrix4d P;
  P << 0, -w[0], -w[1], -w[2],  //
      w[0], 0, w[2], -w[1],     //
      w[1], -w[2], 0, w[0],     //
      w[2], w[1], -w[0], 0;
  return P;
}

// The force elements' generalised forces (what depends on q and v besides the gyroscopic
// term).
Eigen::VectorXd ElementForces(const System& sys, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              double t, ConstraintWorkspace* ws) {
  return CalcElementForces(sys, CalcBodyKinematics(sys, q, v), t, ws);
}

}  // namespace

void GglDae::DoCalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                            const Eigen::Ref<const Eigen::VectorXd>& yp,
                            Eigen::Ref<Eigen::MatrixXd> J) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  const int nq = G.nq(), nv = G.nv(), m = G.m();
  const Eigen::VectorXd q = y.segment(G.q(), nq);
  const Eigen::VectorXd v = y.segment(G.v(), nv);
  const Eigen::VectorXd lambda = y.segment(G.lambda(), m);
  const Eigen::VectorXd mu = y.segment(G.mu(), G.num_mu());
  const auto bodies = CalcBodyKinematics(system_, q, v);
  const ConstraintEval c = CalcConstraints(system_, bodies, t, &workspace_);

  // Second-derivative terms in x = [delta p, delta pi] (primitive.h):
  //   S_lambda = sum_k lambda_k K_k,  S_mu = sum_k mu_k K_k,  row k of D_cv = v^T K_k.
  Eigen::MatrixXd S_lambda = Eigen::MatrixXd::Zero(nv, nv), S_mu = Eigen::MatrixXd::Zero(nv, nv);
  Eigen::MatrixXd D_cv = Eigen::MatrixXd::Zero(m, nv);
  for (int k = 0; k < m; ++k) {
    const ScalarEquation& eq = system_.equations()[k];
    for (int term = 0; term < eq.num_terms; ++term) {
      const MarkerKinematics I = CalcMarkerKinematics(system_, bodies, eq.marker_i[term]);
      const MarkerKinematics Jm = CalcMarkerKinematics(system_, bodies, eq.marker_j[term]);
      const Eigen::Matrix<double, 12, 12> K =
          eq.coeff[term] * EvalKernelHessian(eq.kernel[term], I, Jm);
      const int body[2] = {I.body, Jm.body};
      for (int a = 0; a < 2; ++a) {
        if (L.is_ground(body[a])) continue;
        for (int b = 0; b < 2; ++b) {
          if (L.is_ground(body[b])) continue;
          const auto Kab = K.block<6, 6>(6 * a, 6 * b);
          const int ra = L.velocity(body[a]), cb = L.velocity(body[b]);
          S_lambda.block<6, 6>(ra, cb) += lambda[k] * Kab;
          S_mu.block<6, 6>(ra, cb) += mu[k] * Kab;
          D_cv.block<1, 6>(k, cb) += v.segment<6>(ra).transpose() * Kab;
        }
      }
    }
  }
  // X = dx/dq: identity on positions, delta pi = T(e)^T delta e with T(e) = 2 Q(e) / |e|^2.
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(nv, nq);
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const Eigen::Vector4d e = q.segment<4>(L.quaternion(b));
    X.block<3, 3>(L.velocity(b), L.position(b)).setIdentity();
    X.block<3, 4>(L.angular_velocity(b), L.quaternion(b)) =
        (2.0 / e.squaredNorm()) * QuaternionRateMatrix(e).transpose();
  }
  const Eigen::MatrixXd Bt = CalcBTranspose(q, c.jacobian);
  J.setZero();

  // Kinematic rows: q' - H v + B^T mu.
  const Eigen::MatrixXd SmuX = S_mu * X;
  const Eigen::VectorXd w_all = c.jacobian.transpose() * mu.head(m);
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const Eigen::Vector4d e = q.segment<4>(L.quaternion(b));
    const double n2 = e.squaredNorm();
    const Eigen::Vector3d w = w_all.segment<3>(L.angular_velocity(b));
    const int rp = G.q() + L.position(b), re = G.q() + L.quaternion(b);
    J.block(rp, G.q(), 3, nq) = SmuX.middleRows<3>(L.velocity(b));
    J.block(re, G.q(), 4, nq) =
        (2.0 / n2) * QuaternionRateMatrix(e) * SmuX.middleRows<3>(L.angular_velocity(b));
    J.block<4, 4>(re, G.q() + L.quaternion(b)) +=
        (2.0 / n2) * RateMatrixDerivative(w) -
        (4.0 / (n2 * n2)) * (QuaternionRateMatrix(e) * w) * e.transpose() +
        mu[m + b - 1] * Eigen::Matrix4d::Identity() -
        0.5 * RateMatrixDerivative(v.segment<3>(L.angular_velocity(b)));
    J.block<3, 3>(rp, G.v() + L.velocity(b)) = -Eigen::Matrix3d::Identity();
    J.block<4, 3>(re, G.v() + L.angular_velocity(b)) = -0.5 * QuaternionRateMatrix(e);
  }
  J.block(G.q(), G.q(), nq, nq).diagonal().array() += cj;
  J.block(G.q(), G.mu(), nq, G.num_mu()) = Bt;

  // Dynamic rows: M v' - f + C^T lambda.
  J.block(G.v(), G.q(), nv, nq) = S_lambda * X;
  J.block(G.v(), G.v(), nv, nv) = cj * mass_;
  for (int b = 1; b < system_.num_bodies(); ++b) {
    // d(omega x J omega)/d omega = [omega x] J - [(J omega) x]; f has its negative.
    const Eigen::Vector3d w = v.segment<3>(L.angular_velocity(b));
    const Eigen::Matrix3d& Jb = system_.body(b).inertia_B;
    J.block<3, 3>(G.v() + L.angular_velocity(b), G.v() + L.angular_velocity(b)) +=
        Skew(w) * Jb - Skew(Jb * w);
  }
  if (!system_.force_elements().empty()) {
    // Force elements: central differences (their stiffness and damping; cheap next to the
    // constraint terms and exact for linear elements up to round-off).
    const double sqrt_eps = std::sqrt(std::numeric_limits<double>::epsilon());
    Eigen::VectorXd qq = q, vv = v;
    for (int j = 0; j < nq; ++j) {
      const double h = sqrt_eps * std::max(1.0, std::abs(q[j]));
      qq[j] = q[j] + h;
      const Eigen::VectorXd fp = ElementForces(system_, qq, v, t, &workspace_);
      qq[j] = q[j] - h;
      const Eigen::VectorXd fm = ElementForces(system_, qq, v, t, &workspace_);
      qq[j] = q[j];
      J.block(G.v(), G.q() + j, nv, 1) -= (fp - fm) / (2 * h);
    }
    for (int j = 0; j < nv; ++j) {
      const double h = sqrt_eps * std::max(1.0, std::abs(v[j]));
      vv[j] = v[j] + h;
      const Eigen::VectorXd fp = ElementForces(system_, q, vv, t, &workspace_);
      vv[j] = v[j] - h;
      const Eigen::VectorXd fm = ElementForces(system_, q, vv, t, &workspace_);
      vv[j] = v[j];
      J.block(G.v(), G.v() + j, nv, 1) -= (fp - fm) / (2 * h);
    }
  }
  J.block(G.v(), G.lambda(), nv, m) = c.jacobian.transpose();

  // Constraint rows.
  J.block(G.lambda(), G.q(), m, nq) = D_cv * X;
  J.block(G.lambda(), G.v(), m, nv) = c.jacobian;
  J.block(G.mu(), G.q(), G.num_mu(), nq) = Bt.transpose();
}

std::vector<std::pair<int, int>> GglDae::DoJacobianPattern() const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  const int nb = system_.num_bodies();
  const int m = G.m();
  // Bodies of each equation and body-body coupling (equations and force elements).
  std::vector<std::vector<int>> eq_bodies(m);
  std::vector<std::vector<bool>> coupled(nb, std::vector<bool>(nb, false));
  auto couple = [&](const std::vector<int>& bodies) {
    for (int a : bodies)
      for (int b : bodies) coupled[a][b] = true;
  };
  for (int k = 0; k < m; ++k) {
    const ScalarEquation& eq = system_.equations()[k];
    for (int term = 0; term < eq.num_terms; ++term)
      for (int mk : {eq.marker_i[term], eq.marker_j[term]}) {
        const int b = system_.marker(mk).body;
        if (!L.is_ground(b) &&
            std::find(eq_bodies[k].begin(), eq_bodies[k].end(), b) == eq_bodies[k].end())
          eq_bodies[k].push_back(b);
      }
    couple(eq_bodies[k]);
  }
  for (const auto& fe : system_.force_elements()) {
    std::vector<int> bodies;
    for (int mk : fe->markers())
      if (!L.is_ground(system_.marker(mk).body)) bodies.push_back(system_.marker(mk).body);
    couple(bodies);
  }
  std::vector<std::pair<int, int>> p;
  auto block = [&](int r0, int nr, int c0, int nc) {
    for (int r = 0; r < nr; ++r)
      for (int c = 0; c < nc; ++c) p.emplace_back(r0 + r, c0 + c);
  };
  for (int a = 1; a < nb; ++a) {
    const int rq = G.q() + L.position(a), rv = G.v() + L.velocity(a);
    for (int b = 1; b < nb; ++b) {
      if (a != b && !coupled[a][b]) continue;
      block(rq, 7, G.q() + L.position(b), 7);  // B^T mu, H v
      block(rv, 6, G.q() + L.position(b), 7);  // C^T lambda, forces
      block(rv, 6, G.v() + L.velocity(b), 6);  // M, gyroscopic, dampers
    }
    block(rq, 7, G.v() + L.velocity(a), 6);  // H
    block(rq, 7, G.mu() + m + a - 1, 1);     // unit-quaternion multiplier
    block(G.mu() + m + a - 1, 1, G.q() + L.position(a), 7);
  }
  for (int k = 0; k < m; ++k)
    for (int b : eq_bodies[k]) {
      block(G.q() + L.position(b), 7, G.mu() + k, 1);      // B^T
      block(G.v() + L.velocity(b), 6, G.lambda() + k, 1);  // C^T
      block(G.lambda() + k, 1, G.q() + L.position(b), 7);  // d(C v)/dq
      block(G.lambda() + k, 1, G.v() + L.velocity(b), 6);  // C
      block(G.mu() + k, 1, G.q() + L.position(b), 7);      // B
    }
  return p;
}

Eigen::VectorXd GglDae::DoDifferentialMask() const {
  Eigen::VectorXd mask = Eigen::VectorXd::Zero(layout_.size());
  mask.head(layout_.nq() + layout_.nv()).setOnes();
  return mask;
}

std::string GglDae::DoComponentName(int i) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  static const char* kQ[] = {"p_WB.x", "p_WB.y", "p_WB.z", "e.w", "e.x", "e.y", "e.z"};
  static const char* kV[] = {"v_WB.x", "v_WB.y", "v_WB.z", "omega_B.x", "omega_B.y", "omega_B.z"};
  if (i < G.v()) {
    const int b = i / StateLayout::kQPerBody + 1;
    return "body '" + system_.body(b).name + "' " + kQ[i - L.position(b)];
  }
  if (i < G.lambda()) {
    const int k = i - G.v();
    const int b = k / StateLayout::kVPerBody + 1;
    return "body '" + system_.body(b).name + "' " + kV[k - L.velocity(b)];
  }
  if (i < G.mu()) return "lambda of " + system_.EquationName(i - G.lambda());
  const int k = i - G.mu();
  if (k < G.m()) return "mu of " + system_.EquationName(k);
  return "mu of unit quaternion of body '" + system_.body(k - G.m() + 1).name + "'";
}

void GglDae::MakeInitialValues(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& vdot, const Eigen::VectorXd& lambda,
                               Eigen::VectorXd* y, Eigen::VectorXd* yp) const {
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
  }
  yp->segment(G.v(), G.nv()) = vdot;
}

}  // namespace emb::mbs
