#include "libemb/mbs/dae/linearization.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <utility>

#include <Eigen/Eigenvalues>

#include "libemb/common/error.h"
#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

// Every force element's K_ab and D_ab at the bodies' state, in one dense sink.
DenseForceJacobian CollectForceJacobian(const System& sys, const std::vector<BodyKinematics>& bodies,
                                        const std::vector<MarkerKinematics>& markers, double t,
                                        ConstraintWorkspace* ws) {
  DenseForceJacobian forces(sys.layout());
  const auto& elements = sys.force_elements();
  for (std::size_t k = 0; k < elements.size(); ++k) {
    ForceContext ctx{&sys, &bodies, t, ws, sys.force_angle_slot(static_cast<int>(k))};
    ctx.markers = &markers;
    elements[k]->AddForceJacobian(ctx, &forces);
  }
  return forces;
}

}  // namespace

Eigen::MatrixXd CalcTangentStiffness(const System& sys, const Eigen::VectorXd& q,
                                     const Eigen::VectorXd& v, const Eigen::VectorXd& lambda,
                                     double t, ConstraintWorkspace* ws,
                                     const Eigen::VectorXd& vdot) {
  const StateLayout& L = sys.layout();
  const auto bodies = CalcBodyKinematics(sys, q, v);
  std::vector<MarkerKinematics> markers;
  CalcAllMarkerKinematics(sys, bodies, &markers);
  const DenseForceJacobian forces = CollectForceJacobian(sys, bodies, markers, t, ws);
  Eigen::MatrixXd K = forces.stiffness();
  auto add_body_block = [&](int a, int b, const Eigen::MatrixXd& block) {
    ForEachBodySubBlock(L, a, b, [&](int r, int c, int i0, int j0, int nr, int nc) {
      K.block(r, c, nr, nc) += block.block(i0, j0, nr, nc);
    });
  };
  for (int b = 1; b < sys.num_bodies(); ++b)
    if (L.num_elastic(b))
      add_body_block(b, b, CalcBodyFlexibleTerms(sys, bodies[b], b, nullptr, true).stiffness);
  VisitKernelTerms(sys, markers, [&](const KernelTerm& term) {
    const int body[2] = {term.body_i, term.body_j};
    Eigen::MatrixXd T[2];
    for (int s = 0; s < 2; ++s)
      T[s] = term.marker[s] ? term.marker[s]->map : Eigen::MatrixXd(Eigen::MatrixXd::Identity(6, 6));
    for (int s = 0; s < 2; ++s)
      for (int u = 0; u < 2; ++u)
        if (!L.is_ground(body[s]) && !L.is_ground(body[u]))
          add_body_block(body[s], body[u],
                         -lambda[term.equation] * T[s].transpose() *
                             term.hessian.block<6, 6>(6 * s, 6 * u) * T[u]);
  });
  // Flexible bodies' columns: central differences of f - C^T lambda in x (rigid part
  // through ApplyDisplacement, modal coordinates directly); h ~ eps^(1/3) x scale.
  auto load = [&](const Eigen::VectorXd& qx) {
    const auto bx = CalcBodyKinematics(sys, qx, v);
    const ConstraintEval c = CalcConstraints(sys, bx, t, ws);
    return Eigen::VectorXd(CalcGeneralizedForces(sys, bx, t, ws, vdot.size() ? &vdot : nullptr) -
                           c.jacobian.transpose() * lambda);
  };
  for (int b = 1; b < sys.num_bodies(); ++b) {
    const int ne = L.num_elastic(b);
    if (!ne) continue;
    std::vector<int> cols;
    for (int i = 0; i < StateLayout::kVPerBody; ++i) cols.push_back(L.velocity(b) + i);
    for (int i = 0; i < ne; ++i) cols.push_back(L.elastic_v(b) + i);
    for (int j : cols) {
      const double h = j >= L.elastic_v(b) ? 6e-6 * std::max(1e-3, std::abs(q[L.elastic_q(b) + j - L.elastic_v(b)]))
                                            : 6e-6;
      Eigen::VectorXd dx = Eigen::VectorXd::Zero(L.nv());
      dx[j] = h;
      const Eigen::VectorXd fp = load(ApplyDisplacement(sys, q, dx));
      dx[j] = -h;
      const Eigen::VectorXd fm = load(ApplyDisplacement(sys, q, dx));
      K.col(j) = (fp - fm) / (2.0 * h);
    }
  }
  return K;
}

namespace {

// -df/dv (nv x nv): force elements' damping, the rigid bodies' gyroscopic term and the
// flexible bodies' velocity terms.
Eigen::MatrixXd CalcVelocityStiffness(const System& sys, const std::vector<BodyKinematics>& bodies,
                                      double t, ConstraintWorkspace* ws) {
  const StateLayout& L = sys.layout();
  std::vector<MarkerKinematics> markers;
  CalcAllMarkerKinematics(sys, bodies, &markers);
  const DenseForceJacobian forces = CollectForceJacobian(sys, bodies, markers, t, ws);
  Eigen::MatrixXd G = -forces.damping();
  for (int b = 1; b < sys.num_bodies(); ++b) {
    if (L.num_elastic(b)) {
      const Eigen::MatrixXd D = CalcBodyFlexibleTerms(sys, bodies[b], b, nullptr, true).damping;
      ForEachBodySubBlock(L, b, b, [&](int r, int c, int i0, int j0, int nr, int nc) {
        G.block(r, c, nr, nc) -= D.block(i0, j0, nr, nc);
      });
      continue;
    }
    const Eigen::Matrix3d& J = sys.body(b).inertia_B;
    const Eigen::Vector3d& w = bodies[b].omega_B;
    G.block<3, 3>(L.angular_velocity(b), L.angular_velocity(b)) +=
        Skew(w) * J - Skew(J * w);
  }
  return G;
}

}  // namespace

bool HasQuasiStaticCoordinates(const System& sys) {
  for (int b = 1; b < sys.num_bodies(); ++b)
    if (sys.body(b).elastic && sys.body(b).elastic->num_quasi_static() > 0) return true;
  return false;
}

LinearizedModel CalcLinearizedModel(const System& system, const Eigen::VectorXd& q,
                                    const Eigen::VectorXd& v_in, double t,
                                    const Eigen::VectorXd& lambda, ConstraintWorkspace* workspace,
                                    const Eigen::VectorXd& vdot) {
  const int nv = system.layout().nv();
  const Eigen::VectorXd v = v_in.size() ? v_in : Eigen::VectorXd::Zero(nv);
  const auto bodies = CalcBodyKinematics(system, q, v);
  LinearizedModel m;
  m.M = CalcMassMatrix(system, bodies);
  m.K = -CalcTangentStiffness(system, q, v, lambda, t, workspace, vdot);
  m.G = CalcVelocityStiffness(system, bodies, t, workspace);
  const Eigen::MatrixXd C(CalcConstraints(system, bodies, t, workspace).jacobian);
  // Null space of C from a complete orthogonal decomposition of C^T.
  if (C.rows() == 0) {
    m.Z = Eigen::MatrixXd::Identity(nv, nv);
  } else {
    const Eigen::FullPivHouseholderQR<Eigen::MatrixXd> qr(C.transpose());
    const int rank = static_cast<int>(qr.rank());
    const Eigen::MatrixXd Q = qr.matrixQ();
    m.Z = Q.rightCols(nv - rank);
  }
  return m;
}

LinearModes CalcLinearModes(const System& system, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v_in, double t, const Eigen::VectorXd& lambda,
                            ConstraintWorkspace* workspace, bool undamped,
                            const Eigen::VectorXd& vdot) {
  const LinearizedModel lin = CalcLinearizedModel(system, q, v_in, t, lambda, workspace, vdot);
  const Eigen::MatrixXd& M = lin.M;
  const Eigen::MatrixXd& K = lin.K;
  const Eigen::MatrixXd& G = lin.G;
  const Eigen::MatrixXd& Z = lin.Z;
  LinearModes out;
  const int n = static_cast<int>(Z.cols());
  out.num_free = n;
  if (n == 0) return out;
  const Eigen::MatrixXd Mz = Z.transpose() * M * Z, Kz = Z.transpose() * K * Z;
  const Eigen::MatrixXd Gz = Z.transpose() * G * Z;
  if (undamped || Gz.cwiseAbs().maxCoeff() == 0.0) {
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(
        0.5 * (Kz + Kz.transpose()), 0.5 * (Mz + Mz.transpose()));
    if (eig.info() != Eigen::Success)
      EMB_THROW(NumericalError,
                "linearised modes: the reduced mass matrix is not positive definite");
    const Eigen::VectorXd& lam = eig.eigenvalues();
    out.frequencies_hz.resize(lam.size());
    for (Eigen::Index i = 0; i < lam.size(); ++i)
      out.frequencies_hz[i] =
          (lam[i] >= 0 ? 1.0 : -1.0) * std::sqrt(std::abs(lam[i])) / (2 * std::numbers::pi);
    out.shapes = Z * eig.eigenvectors();
    return out;
  }
  // First-order form x' = A x, x = [y; y'].
  std::vector<std::pair<double, double>> pairs;  // (frequency, decay) with Im s > 0
  const Eigen::LLT<Eigen::MatrixXd> llt(0.5 * (Mz + Mz.transpose()));
  if (llt.info() == Eigen::Success && !HasQuasiStaticCoordinates(system)) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -llt.solve(Kz);
    A.bottomRightCorner(n, n) = -llt.solve(Gz);
    const Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
    if (es.info() != Eigen::Success)
      EMB_THROW(NumericalError, "linearised modes: the eigen-solve of the first-order form failed");
    for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
      const std::complex<double> s = es.eigenvalues()[i];
      if (s.imag() > 0.0) pairs.emplace_back(s.imag() / (2 * std::numbers::pi), -s.real());
    }
  } else {
    // Massless (quasi-static) coordinates make M_z singular: the pencil
    // [0 I; -K -G] x = s [I 0; 0 M] x keeps their finite eigenvalues (relaxations and the
    // vibrations of what they carry) and puts the massless directions at s = infinity.
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n), B = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -Kz;
    A.bottomRightCorner(n, n) = -Gz;
    B.topLeftCorner(n, n).setIdentity();
    B.bottomRightCorner(n, n) = 0.5 * (Mz + Mz.transpose());
    const Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> ges(A, B, false);
    if (ges.info() != Eigen::Success)
      EMB_THROW(NumericalError, "linearised modes: the eigen-solve of the first-order pencil failed");
    const double scale = std::max(1.0, A.cwiseAbs().maxCoeff());
    for (Eigen::Index i = 0; i < ges.alphas().size(); ++i) {
      const double beta = ges.betas()[i];
      if (std::abs(beta) <= 1e-14 * std::abs(ges.alphas()[i]) || beta == 0.0) continue;
      const std::complex<double> s = ges.alphas()[i] / beta;
      if (std::abs(s) > 1e8 * scale) continue;  // numerically infinite
      if (s.imag() > 0.0) pairs.emplace_back(s.imag() / (2 * std::numbers::pi), -s.real());
    }
  }
  std::sort(pairs.begin(), pairs.end());
  out.frequencies_hz.resize(static_cast<Eigen::Index>(pairs.size()));
  out.decay.resize(static_cast<Eigen::Index>(pairs.size()));
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    out.frequencies_hz[static_cast<Eigen::Index>(i)] = pairs[i].first;
    out.decay[static_cast<Eigen::Index>(i)] = pairs[i].second;
  }
  return out;
}

}  // namespace emb::mbs
