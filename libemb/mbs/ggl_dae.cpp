#include "libemb/mbs/ggl_dae.h"

#include <vector>

#include "libemb/mbs/dynamics.h"
#include "libemb/mbs/force_jacobian.h"
#include "libemb/mbs/rotation.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

GglDae::GglDae(const System& system)
    : system_(system),
      layout_(system.layout().nq(), system.layout().nv(), system.num_equations(),
              system.layout().num_moving()),
      workspace_(system) {}

namespace {

using Matrix67 = Eigen::Matrix<double, 6, 7>;

// Per moving body, the map from q-space to [delta p, delta pi] (v-space) at e:
//   X = d x / d q = [I 0; 0 (2/|e|^2) Q(e)^T]   (6 x 7),
// so that B = d Phi/dq = C X per body and B^T mu = X^T C^T mu.
Matrix67 MakeBodyMap(const Eigen::Vector4d& e) {
  Matrix67 X = Matrix67::Zero();
  X.block<3, 3>(0, 0).setIdentity();
  X.block<3, 4>(3, 3) = (2.0 / e.squaredNorm()) * QuaternionRateMatrix(e).transpose();
  return X;
}

// P(w) = d(Q(e) w)/de (Q(e) w is linear in e).
Eigen::Matrix4d RateMatrixDerivative(const Eigen::Vector3d& w) {
  Eigen::Matrix4d P;
  P << 0, -w[0], -w[1], -w[2],  //
      w[0], 0, w[2], -w[1],     //
      w[1], -w[2], 0, w[0],     //
      w[2], w[1], -w[0], 0;
  return P;
}

// Force elements' blocks into the dynamic rows: -K_ab X_b (v rows of a, q columns of b) and
// -D_ab (v columns of b).
class GglForceSink final : public ForceJacobianSink {
 public:
  GglForceSink(const StateLayout& L, const GglLayout& G, const std::vector<Matrix67>& X,
               MatrixAssembler* A)
      : L_(L), G_(G), X_(X), A_(A) {}
  void AddStiffness(int a, int b, const Matrix6d& K) override {
    A_->AddBlock(G_.v() + L_.velocity(a), G_.q() + L_.position(b), -K * X_[b]);
  }
  void AddDamping(int a, int b, const Matrix6d& D) override {
    A_->AddBlock(G_.v() + L_.velocity(a), G_.v() + L_.velocity(b), -D);
  }

 private:
  const StateLayout& L_;
  const GglLayout& G_;
  const std::vector<Matrix67>& X_;
  MatrixAssembler* A_;
};

}  // namespace

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

  // Kinematic rows: q' - H v + B^T mu, B^T mu = X_b^T (C^T mu)_b + [0; e_b mu_b].
  const Eigen::VectorXd w = c.jacobian.transpose() * mu.head(G.m());
  const Eigen::VectorXd f = CalcGeneralizedForces(system_, bodies, t, &workspace_);
  const Eigen::VectorXd reaction = c.jacobian.transpose() * lambda;
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const Eigen::Vector4d e = q.segment<4>(L.quaternion(b));
    const auto wb = w.segment<6>(L.velocity(b));
    r.segment<3>(G.q() + L.position(b)) =
        yp.segment<3>(G.q() + L.position(b)) - v.segment<3>(L.velocity(b)) + wb.head<3>();
    r.segment<4>(G.q() + L.quaternion(b)) =
        yp.segment<4>(G.q() + L.quaternion(b)) -
        0.5 * QuaternionRateMatrix(e) * v.segment<3>(L.angular_velocity(b)) +
        (2.0 / e.squaredNorm()) * QuaternionRateMatrix(e) * wb.tail<3>() +
        mu[G.m() + b - 1] * e;
    // Dynamic rows: M v' - f + C^T lambda, M = diag(m I, J_B) per body.
    const RigidBody& body = system_.body(b);
    r.segment<3>(G.v() + L.velocity(b)) = body.mass * yp.segment<3>(G.v() + L.velocity(b)) -
                                          f.segment<3>(L.velocity(b)) +
                                          reaction.segment<3>(L.velocity(b));
    r.segment<3>(G.v() + L.angular_velocity(b)) =
        body.inertia_B * yp.segment<3>(G.v() + L.angular_velocity(b)) -
        f.segment<3>(L.angular_velocity(b)) + reaction.segment<3>(L.angular_velocity(b));
    r[G.mu() + G.m() + b - 1] = 0.5 * (e.squaredNorm() - 1.0);
  }
  // Velocity and position constraints.
  r.segment(G.lambda(), G.m()) = c.jacobian * v + c.phi_t;
  r.segment(G.mu(), G.m()) = c.phi;
  return true;
}

void GglDae::DoCalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                            const Eigen::Ref<const Eigen::VectorXd>&,
                            Eigen::Ref<Eigen::MatrixXd> J) const {
  assembler_.BeginDense(J);
  AssembleJacobian(t, cj, y, &assembler_);
}

void GglDae::DoCalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                                  const Eigen::Ref<const Eigen::VectorXd>&,
                                  SparseMatrixd* J) const {
  assembler_.BeginSparse(J, layout_.size(), layout_.size());
  AssembleJacobian(t, cj, y, &assembler_);
}

void GglDae::AssembleJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                              MatrixAssembler* A) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  const int m = G.m();
  const Eigen::VectorXd q = y.segment(G.q(), G.nq());
  const Eigen::VectorXd v = y.segment(G.v(), G.nv());
  const auto lambda = y.segment(G.lambda(), m);
  const auto mu = y.segment(G.mu(), G.num_mu());
  const auto bodies = CalcBodyKinematics(system_, q, v);
  const ConstraintEval c = CalcConstraints(system_, bodies, t, &workspace_);
  const Eigen::VectorXd w_all = c.jacobian.transpose() * mu.head(m);
  std::vector<Matrix67> X(system_.num_bodies());
  for (int b = 1; b < system_.num_bodies(); ++b) X[b] = MakeBodyMap(q.segment<4>(L.quaternion(b)));

  // Per body: cj I and the derivative of the maps in the kinematic rows, H, the
  // unit-quaternion multiplier, cj M and the gyroscopic term.
  for (int b = 1; b < system_.num_bodies(); ++b) {
    const Eigen::Vector4d e = q.segment<4>(L.quaternion(b));
    const double n2 = e.squaredNorm();
    const Eigen::Vector3d w = w_all.segment<3>(L.angular_velocity(b));
    const Eigen::Vector3d omega = v.segment<3>(L.angular_velocity(b));
    const int rq = G.q() + L.position(b), rv = G.v() + L.velocity(b);
    const int mu_b = G.mu() + m + b - 1;
    Eigen::Matrix<double, 7, 7> Jqq = cj * Eigen::Matrix<double, 7, 7>::Identity();
    Jqq.block<4, 4>(3, 3) += (2.0 / n2) * RateMatrixDerivative(w) -
                             (4.0 / (n2 * n2)) * (QuaternionRateMatrix(e) * w) * e.transpose() +
                             mu[m + b - 1] * Eigen::Matrix4d::Identity() -
                             0.5 * RateMatrixDerivative(omega);
    A->AddBlock(rq, rq, Jqq);
    Eigen::Matrix<double, 7, 6> Jqv = Eigen::Matrix<double, 7, 6>::Zero();
    Jqv.block<3, 3>(0, 0) = -Eigen::Matrix3d::Identity();
    Jqv.block<4, 3>(3, 3) = -0.5 * QuaternionRateMatrix(e);
    A->AddBlock(rq, rv, Jqv);
    A->AddBlock(rq + 3, mu_b, e);
    A->AddBlock(mu_b, rq + 3, e.transpose());
    // d(omega x J omega)/d omega = [omega x] J - [(J omega) x]; f has its negative.
    const RigidBody& body = system_.body(b);
    Matrix6d Jvv = Matrix6d::Zero();
    Jvv.block<3, 3>(0, 0) = cj * body.mass * Eigen::Matrix3d::Identity();
    Jvv.block<3, 3>(3, 3) = cj * body.inertia_B + Skew(omega) * body.inertia_B -
                            Skew(body.inertia_B * omega);
    A->AddBlock(rv, rv, Jvv);
  }

  // Per kernel term of equation k between bodies (s0, s1): with G_s its gradient and H_st its
  // second derivative blocks,
  //   kinematic rows:   mu_k X_s^T H_st X_t        (B^T mu)
  //   dynamic rows:     lambda_k H_st X_t          (C^T lambda)
  //   lambda row k:     (sum_s v_s^T H_st) X_t,  G_t
  //   mu row k:         G_t X_t;   columns lambda_k / mu_k: G_s^T / X_s^T G_s^T.
  // The first two are summed over consecutive terms between the same two bodies (the
  // equations of one joint) and emitted once per run: one set of 7x7 blocks per joint
  // instead of per equation.
  using Matrix12 = Eigen::Matrix<double, 12, 12>;
  Matrix12 H_lambda = Matrix12::Zero(), H_mu = Matrix12::Zero();
  int run_body[2] = {-1, -1};
  auto flush = [&] {
    if (run_body[0] < 0) return;
    for (int s = 0; s < 2; ++s) {
      if (L.is_ground(run_body[s])) continue;
      const int rq = G.q() + L.position(run_body[s]), rv = G.v() + L.velocity(run_body[s]);
      for (int u = 0; u < 2; ++u) {
        if (L.is_ground(run_body[u])) continue;
        const int cq = G.q() + L.position(run_body[u]);
        const Matrix67& Xu = X[run_body[u]];
        A->AddBlock(rq, cq, X[run_body[s]].transpose() * (H_mu.block<6, 6>(6 * s, 6 * u) * Xu));
        A->AddBlock(rv, cq, H_lambda.block<6, 6>(6 * s, 6 * u) * Xu);
      }
    }
    H_lambda.setZero();
    H_mu.setZero();
  };
  VisitKernelTerms(system_, bodies, [&](const KernelTerm& term) {
    const int k = term.equation;
    const int body[2] = {term.body_i, term.body_j};
    if (body[0] != run_body[0] || body[1] != run_body[1]) {
      flush();
      run_body[0] = body[0];
      run_body[1] = body[1];
    }
    H_lambda += lambda[k] * term.hessian;
    H_mu += mu[k] * term.hessian;
    Eigen::Matrix<double, 12, 1> v_term = Eigen::Matrix<double, 12, 1>::Zero();
    for (int s = 0; s < 2; ++s)
      if (!L.is_ground(body[s])) v_term.segment<6>(6 * s) = v.segment<6>(L.velocity(body[s]));
    const Eigen::Matrix<double, 1, 12> v_H = v_term.transpose() * term.hessian;
    for (int s = 0; s < 2; ++s) {
      if (L.is_ground(body[s])) continue;
      const int rq = G.q() + L.position(body[s]), rv = G.v() + L.velocity(body[s]);
      const Eigen::Matrix<double, 1, 6> g = term.gradient.segment<6>(6 * s);
      A->AddBlock(G.lambda() + k, rq, v_H.segment<6>(6 * s) * X[body[s]]);
      A->AddBlock(G.lambda() + k, rv, g);
      A->AddBlock(G.mu() + k, rq, g * X[body[s]]);
      A->AddBlock(rq, G.mu() + k, X[body[s]].transpose() * g.transpose());
      A->AddBlock(rv, G.lambda() + k, g.transpose());
    }
  });
  flush();

  // Force elements: analytic stiffness and damping.
  GglForceSink sink(L, G, X, A);
  const auto& forces = system_.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const ForceContext ctx{&system_, &bodies, t, &workspace_,
                           system_.force_angle_slot(static_cast<int>(k))};
    forces[k]->AddForceJacobian(ctx, &sink);
  }
  A->Finish();
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
