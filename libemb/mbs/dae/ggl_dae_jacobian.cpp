// The GGL DAE's iteration matrix dF/dy + cj dF/dy' (ggl_dae.h), assembled block by block
// (per body, constraint and force element, and the elements' states) into a dense or a
// compressed-column matrix, allocating nothing (the scratch is the caller's GglWorkspace).

#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/elastic_model.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/mbs/forces/force_jacobian.h"

namespace emb::mbs {
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

// Emits blocks of body coordinates ([rigid 6, modal ne] per body, v-ordering) into the GGL
// matrix: rows or columns in q-space map the rigid part through X_b (6 x 7) and the modal
// part one to one; v-space rows and columns are the v-ordering shifted by G.v().
class BodyBlockEmitter {
 public:
  BodyBlockEmitter(const StateLayout& L, const GglLayout& G, const std::vector<Matrix67>& X,
                   MatrixAssembler* A, ScratchMatrices* scratch)
      : L_(L), G_(G), X_(X), A_(A), scratch_(scratch) {}

  // Rows of body a (q-space if `q_rows`, else v-space) x columns of body b (q or v). Blocks
  // are read in place; the products with X go through fixed-size temporaries or the
  // workspace's scratch (buffers 8, 9): nothing is allocated.
  void Block(int a, bool q_rows, int b, bool q_cols,
             const Eigen::Ref<const Eigen::MatrixXd>& K) const {
    ForEachBodySubBlock(L_, a, b, [&](int r, int c, int i0, int j0, int nr, int nc) {
      const auto sub = K.block(i0, j0, nr, nc);
      const bool rigid_row = i0 == 0, rigid_col = j0 == 0;
      const int row = q_rows ? (rigid_row ? G_.q() + L_.position(a) : G_.q() + L_.elastic_q(a))
                             : G_.v() + r;
      const int col = q_cols ? (rigid_col ? G_.q() + L_.position(b) : G_.q() + L_.elastic_q(b))
                             : G_.v() + c;
      if (q_rows && rigid_row && q_cols && rigid_col) {
        const Matrix6d s6 = sub;
        A_->AddBlock(row, col, Eigen::Matrix<double, 7, 7>(X_[a].transpose() * s6 * X_[b]));
      } else if (q_rows && rigid_row) {
        Eigen::Map<Eigen::MatrixXd> out = scratch_->View(8, 7, nc);
        out.noalias() = X_[a].transpose() * sub;
        A_->AddBlock(row, col, out);
      } else if (q_cols && rigid_col) {
        Eigen::Map<Eigen::MatrixXd> out = scratch_->View(9, nr, 7);
        out.noalias() = sub * X_[b];
        A_->AddBlock(row, col, out);
      } else {
        A_->AddBlock(row, col, sub);
      }
    });
  }
  // A single row `row` x columns of body b (g: 6 + ne entries).
  void Row(int row, int b, bool q_cols, const Eigen::Ref<const Eigen::RowVectorXd>& g) const {
    const Eigen::Matrix<double, 1, 6> g6 = g.head<6>();
    if (q_cols)
      A_->AddBlock(row, G_.q() + L_.position(b), Eigen::Matrix<double, 1, 7>(g6 * X_[b]));
    else
      A_->AddBlock(row, G_.v() + L_.velocity(b), g6);
    const int ne = L_.num_elastic(b);
    if (ne)
      A_->AddBlock(row, q_cols ? G_.q() + L_.elastic_q(b) : G_.v() + L_.elastic_v(b), g.tail(ne));
  }
  // Rows row0, row0 + 1, ... (g.rows()) x columns of body b (q or v; g: rows x (6 + ne)).
  void RowBlock(int row0, int b, bool q_cols, const Eigen::Ref<const Eigen::MatrixXd>& g) const {
    if (q_cols) {
      Eigen::Map<Eigen::MatrixXd> out = scratch_->View(18, g.rows(), 7);
      out.noalias() = g.leftCols<6>() * X_[b];
      A_->AddBlock(row0, G_.q() + L_.position(b), out);
    } else {
      A_->AddBlock(row0, G_.v() + L_.velocity(b), g.leftCols<6>());
    }
    const int ne = L_.num_elastic(b);
    if (ne)
      A_->AddBlock(row0, q_cols ? G_.q() + L_.elastic_q(b) : G_.v() + L_.elastic_v(b),
                   g.rightCols(ne));
  }
  // The dynamic (v-space) rows of body b x columns col0, col0 + 1, ... (g: (6 + ne) x cols).
  void ColumnBlock(int b, int col0, const Eigen::Ref<const Eigen::MatrixXd>& g) const {
    A_->AddBlock(G_.v() + L_.velocity(b), col0, g.topRows<6>());
    const int ne = L_.num_elastic(b);
    if (ne) A_->AddBlock(G_.v() + L_.elastic_v(b), col0, g.bottomRows(ne));
  }
  // Rows of body b x a single column `col` (g: 6 + ne entries).
  void Column(int b, bool q_rows, int col, const Eigen::Ref<const Eigen::VectorXd>& g) const {
    const Eigen::Matrix<double, 6, 1> g6 = g.head<6>();
    if (q_rows)
      A_->AddBlock(G_.q() + L_.position(b), col, Eigen::Matrix<double, 7, 1>(X_[b].transpose() * g6));
    else
      A_->AddBlock(G_.v() + L_.velocity(b), col, g6);
    const int ne = L_.num_elastic(b);
    if (ne)
      A_->AddBlock(q_rows ? G_.q() + L_.elastic_q(b) : G_.v() + L_.elastic_v(b), col, g.tail(ne));
  }

 private:
  const StateLayout& L_;
  const GglLayout& G_;
  const std::vector<Matrix67>& X_;
  MatrixAssembler* A_;
  ScratchMatrices* scratch_;
};

// An element's state blocks: its rows R (from z0) by its states, by the bodies' q and v, and
// the dynamic rows by its states (-df/dz: the rows hold M v' - f).
class GglStateSink final : public StateJacobianSink {
 public:
  GglStateSink(const BodyBlockEmitter& emit, MatrixAssembler* A, int z0, ScratchMatrices* scratch)
      : emit_(emit), A_(A), z0_(z0), scratch_(scratch) {
    UseScratch(scratch);
  }
  void AddStateBlock(int row, int col, const Eigen::Ref<const Eigen::MatrixXd>& block) override {
    A_->AddBlock(z0_ + row, z0_ + col, block);
  }
  void AddStateStiffness(int row, int body,
                         const Eigen::Ref<const Eigen::MatrixXd>& block) override {
    emit_.RowBlock(z0_ + row, body, true, block);
  }
  void AddStateDamping(int row, int body, const Eigen::Ref<const Eigen::MatrixXd>& block) override {
    emit_.RowBlock(z0_ + row, body, false, block);
  }
  void AddForceByState(int body, int col, const Eigen::Ref<const Eigen::MatrixXd>& block) override {
    Eigen::Map<Eigen::MatrixXd> minus = scratch_->View(19, block.rows(), block.cols());
    minus = -block;
    emit_.ColumnBlock(body, z0_ + col, minus);
  }

 private:
  const BodyBlockEmitter& emit_;
  MatrixAssembler* A_;
  int z0_;
  ScratchMatrices* scratch_;
};

// Force elements' blocks into the dynamic rows: -K_ab (q columns of b) and -D_ab (v columns).
class GglForceSink final : public ForceJacobianSink {
 public:
  GglForceSink(const BodyBlockEmitter& emit, ScratchMatrices* scratch)
      : emit_(emit), scratch_(scratch) {
    UseScratch(scratch);
  }
  void AddStiffness(int a, int b, const Eigen::Ref<const Eigen::MatrixXd>& K) override {
    Eigen::Map<Eigen::MatrixXd> minus = scratch_->View(10, K.rows(), K.cols());
    minus = -K;
    emit_.Block(a, false, b, true, minus);
  }
  void AddDamping(int a, int b, const Eigen::Ref<const Eigen::MatrixXd>& D) override {
    Eigen::Map<Eigen::MatrixXd> minus = scratch_->View(10, D.rows(), D.cols());
    minus = -D;
    emit_.Block(a, false, b, false, minus);
  }

 private:
  const BodyBlockEmitter& emit_;
  ScratchMatrices* scratch_;
};


}  // namespace

bool GglDae::DoCalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                            const Eigen::Ref<const Eigen::VectorXd>& yp,
                            Eigen::Ref<Eigen::MatrixXd> J) const {
  ws_->assembler.BeginDense(J);
  return AssembleJacobian(t, cj, y, yp, &ws_->assembler);
}

bool GglDae::DoCalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                                  const Eigen::Ref<const Eigen::VectorXd>& yp,
                                  SparseMatrixd* J) const {
  ws_->assembler.BeginSparse(J, layout_.size(), layout_.size());
  return AssembleJacobian(t, cj, y, yp, &ws_->assembler);
}

bool GglDae::AssembleJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              MatrixAssembler* A) const {
  const StateLayout& L = system_.layout();
  const GglLayout& G = layout_;
  GglWorkspace& W = *ws_;
  const int m = G.m();
  if (!UpdateKinematics(y)) {  // a state the residual cannot be evaluated at either
    A->Abandon();
    ReportRecoverableFailure("the iteration matrix at a vanishing quaternion or non-finite state");
    return false;
  }
  const auto q = y.segment(G.q(), G.nq());
  const auto v = y.segment(G.v(), G.nv());
  const auto lambda = y.segment(G.lambda(), m);
  const auto mu = y.segment(G.mu(), G.num_mu());
  CalcConstraints(system_, W.markers, t, &W.constraint, &W.constraints);
  W.w.noalias() = W.constraints.jacobian.transpose() * mu.head(m);
  const Eigen::VectorXd& w_all = W.w;
  std::vector<Matrix67>& X = W.body_maps;
  for (int b = 1; b < system_.num_bodies(); ++b) X[b] = MakeBodyMap(q.segment<4>(L.quaternion(b)));
  ScratchMatrices& scratch = W.scratch;
  const BodyBlockEmitter emit(L, G, X, A, &scratch);

  // Per body: cj I and the derivative of the maps in the kinematic rows, H, the
  // unit-quaternion multiplier, cj M and the gyroscopic term (flexible bodies: cj M(eta)
  // and the derivatives of their inertia, elastic and gravity terms).
  const auto vdot = yp.segment(G.v(), G.nv());
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
    const int ne = L.num_elastic(b);
    if (ne) {
      const int eq = G.q() + L.elastic_q(b), ev = G.v() + L.elastic_v(b);
      for (int j = 0; j < ne; ++j) {
        A->Add(eq + j, eq + j, cj);
        A->Add(eq + j, ev + j, -1.0);
      }
      auto accel_b = W.accel.head(6 + ne);
      accel_b << yp.segment<6>(G.v() + L.velocity(b)), yp.segment(G.v() + L.elastic_v(b), ne);
      const Eigen::Ref<const Eigen::VectorXd> accel(accel_b);
      const BodyKinematics& k = W.bodies[b];
      const Eigen::Vector3d a_B =
          k.R_WB.transpose() * (vdot.segment<3>(L.velocity(b)) - system_.gravity());
      FlexibleTerms& ft = W.flexible[b];
      CalcFlexibleTerms(*system_.body(b).elastic, k.p_WB, k.R_WB, k.v_WB, k.omega_B, k.eta,
                        k.eta_dot, system_.gravity(), a_B, kFlexibleDerivatives, &accel, &ft);
      // Residual rows M(eta) a - f: d/da = M - df/da, d/dv = -df/dv, d/dx = d(M a)/dx - df/dx.
      Eigen::Map<Eigen::MatrixXd> block = scratch.View(12, 6 + ne, 6 + ne);
      block = cj * (ft.mass - ft.force_accel) - ft.damping;
      emit.Block(b, false, b, false, block);
      block = ft.inertia_stiffness - ft.stiffness;
      emit.Block(b, false, b, true, block);
      continue;
    }
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
  // The first two are linear in the multipliers, so they are summed over consecutive terms
  // between the same two markers' frames (the equations of one joint) and emitted once per
  // run. On a flexible side the sum goes through the marker map, map_s^T (sum H) map_t, and
  // the curvature of the map, d(map^T g)/dx, is linear in the wrench g: one
  // CalcMarkerCurvature per run and side with the summed lambda_k G_k,s (dynamic rows) and
  // mu_k G_k,s (kinematic rows), not one per equation.
  using Matrix12 = Eigen::Matrix<double, 12, 12>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  struct Run {
    int body[2]{-1, -1};
    const MarkerKinematics* marker[2]{nullptr, nullptr};
    Matrix12 H_lambda{Matrix12::Zero()}, H_mu{Matrix12::Zero()};
    Vector6 g_lambda[2]{Vector6::Zero(), Vector6::Zero()}, g_mu[2]{Vector6::Zero(), Vector6::Zero()};
    bool open() const { return body[0] >= 0; }
  } run;
  // map_s^T H map_u with the identity for a rigid side, in the scratch (buffers 13, 14).
  auto side_map = [&scratch](const MarkerKinematics* M, const Eigen::Matrix<double, 6, 6>& H,
                             const MarkerKinematics* Mu) -> Eigen::Map<Eigen::MatrixXd> {
    const Eigen::Index nu = Mu ? Mu->map.cols() : 6;
    Eigen::Map<Eigen::MatrixXd> right = scratch.View(13, 6, nu);
    if (Mu)
      right.noalias() = H * Mu->map;
    else
      right = H;
    if (!M) return right;
    Eigen::Map<Eigen::MatrixXd> out = scratch.View(14, M->map.cols(), nu);
    out.noalias() = M->map.transpose() * right;
    return out;
  };
  // CalcMarkerCurvature(M, g) in the scratch (buffer 15).
  auto curvature = [&scratch](const MarkerKinematics& M, const Vector6& g) {
    const Eigen::Index n = M.map.cols();
    Eigen::Map<Eigen::MatrixXd> out = scratch.View(15, n, n);
    out.setZero();
    AddMarkerCurvature(M, g, out, &scratch);
    return out;
  };
  auto flush = [&] {
    if (!run.open()) return;
    for (int s = 0; s < 2; ++s) {
      if (L.is_ground(run.body[s])) continue;
      for (int u = 0; u < 2; ++u) {
        if (L.is_ground(run.body[u])) continue;
        emit.Block(run.body[s], true, run.body[u], true,
                   side_map(run.marker[s], run.H_mu.block<6, 6>(6 * s, 6 * u), run.marker[u]));
        emit.Block(run.body[s], false, run.body[u], true,
                   side_map(run.marker[s], run.H_lambda.block<6, 6>(6 * s, 6 * u), run.marker[u]));
      }
      if (run.marker[s]) {
        emit.Block(run.body[s], false, run.body[s], true,
                   curvature(*run.marker[s], run.g_lambda[s]));
        emit.Block(run.body[s], true, run.body[s], true, curvature(*run.marker[s], run.g_mu[s]));
      }
    }
    run = Run{};
  };
  const auto visit = [&](const KernelTerm& term) {
    const int k = term.equation;
    const int body[2] = {term.body_i, term.body_j};
    const bool same = run.open() && body[0] == run.body[0] && body[1] == run.body[1] &&
                      term.marker[0] == run.marker[0] && term.marker[1] == run.marker[1];
    if (!same) {
      flush();
      run.body[0] = body[0], run.body[1] = body[1];
      run.marker[0] = term.marker[0], run.marker[1] = term.marker[1];
    }
    run.H_lambda += lambda[k] * term.hessian;
    run.H_mu += mu[k] * term.hessian;
    for (int s = 0; s < 2; ++s) {
      if (!term.marker[s]) continue;
      run.g_lambda[s] += lambda[k] * term.gradient.segment<6>(6 * s).transpose();
      run.g_mu[s] += mu[k] * term.gradient.segment<6>(6 * s).transpose();
    }
    // Velocities of the two sides' virtual bodies: map [v_b; eta'_b].
    Eigen::Matrix<double, 12, 1> v_term = Eigen::Matrix<double, 12, 1>::Zero();
    for (int s = 0; s < 2; ++s) {
      if (L.is_ground(body[s])) continue;
      if (term.marker[s])
        v_term.segment<6>(6 * s) = VirtualBodyVelocity(*term.marker[s]);
      else
        v_term.segment<6>(6 * s) = v.segment<6>(L.velocity(body[s]));
    }
    const Eigen::Matrix<double, 1, 12> v_H = v_term.transpose() * term.hessian;
    for (int s = 0; s < 2; ++s) {
      if (L.is_ground(body[s])) continue;
      const MarkerKinematics* M = term.marker[s];
      const Eigen::Matrix<double, 1, 6> gs = term.gradient.segment<6>(6 * s);
      // The gradient through the map (and its velocity term) in the scratch (buffers 16, 17).
      const Eigen::Index n = M ? M->map.cols() : 6;
      Eigen::Map<Eigen::RowVectorXd> g(scratch.View(16, 1, n).data(), n);
      Eigen::Map<Eigen::RowVectorXd> dv_x(scratch.View(17, 1, n).data(), n);
      if (M) {
        g.noalias() = gs * M->map;
        dv_x.noalias() = v_H.segment<6>(6 * s) * M->map;
        // The velocity constraint g map V also moves with the map: g d(map V)/dx.
        dv_x.noalias() += gs * M->map_rate;
      } else {
        g = gs;
        dv_x = v_H.segment<6>(6 * s);
      }
      emit.Row(G.lambda() + k, body[s], true, dv_x);
      emit.Row(G.lambda() + k, body[s], false, g);
      emit.Row(G.mu() + k, body[s], true, g);
      emit.Column(body[s], true, G.mu() + k, g.transpose());
      emit.Column(body[s], false, G.lambda() + k, g.transpose());
    }
  };
  // Through a reference: the closure is larger than std::function's local storage.
  VisitKernelTerms(system_, W.markers, std::cref(visit));
  flush();

  // Force elements: analytic stiffness and damping.
  GglForceSink sink(emit, &scratch);
  const auto& forces = system_.force_elements();
  W.failure.failed = false;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    ForceContext ctx{&system_, &W.bodies, t, &W.constraint,
                     system_.force_angle_slot(static_cast<int>(k))};
    ctx.markers = &W.markers;
    ctx.failure = &W.failure;
    const int offset = system_.force_state_offset(static_cast<int>(k));
    if (offset >= 0) {
      ctx.z = y.data() + G.z() + offset;
      ctx.z_dot = yp.data() + G.z() + offset;
    }
    forces[k]->AddForceJacobian(ctx, &sink);  // at fixed states
    if (offset >= 0) {
      GglStateSink state_sink(emit, A, G.z() + offset, &scratch);
      forces[k]->AddStateJacobian(ctx, cj, &state_sink);
    }
  }
  if (W.failure.failed) {  // its blocks are missing: this matrix cannot be used
    A->Abandon();
    ReportRecoverableFailure(W.failure.message);
    return false;
  }
  A->Finish();
  return true;
}

}  // namespace emb::mbs
