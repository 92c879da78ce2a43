#include "libemb/mbs/core/elastic_model.h"

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {
namespace {

// Rows of the 9 x ne matrix Bm (row 3i+j, column k = B_k(i, j)) that give the axial vector
// of B_k - B_k^T, i.e. the column k of ∫ρ u x Phi_k.
Eigen::Matrix<double, 3, Eigen::Dynamic> AxialRows(const Eigen::MatrixXd& Bm) {
  Eigen::Matrix<double, 3, Eigen::Dynamic> a(3, Bm.cols());
  a.row(0) = Bm.row(5) - Bm.row(7);
  a.row(1) = Bm.row(6) - Bm.row(2);
  a.row(2) = Bm.row(1) - Bm.row(3);
  return a;
}

Eigen::Matrix3d Block3(const Eigen::MatrixXd& Bm, int k) {
  Eigen::Matrix3d B;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) B(i, j) = Bm(3 * i + j, k);
  return B;
}

// The six products c_p(w) of the geometric stiffness and their derivatives d c_p / d w.
Eigen::Matrix<double, 6, 1> CentrifugalProducts(const Eigen::Vector3d& w) {
  Eigen::Matrix<double, 6, 1> c;
  c << w.x() * w.x(), w.y() * w.y(), w.z() * w.z(), w.x() * w.y(), w.y() * w.z(), w.z() * w.x();
  return c;
}
Eigen::Matrix<double, 6, 3> CentrifugalProductsDerivative(const Eigen::Vector3d& w) {
  Eigen::Matrix<double, 6, 3> d = Eigen::Matrix<double, 6, 3>::Zero();
  d(0, 0) = 2 * w.x();
  d(1, 1) = 2 * w.y();
  d(2, 2) = 2 * w.z();
  d(3, 0) = w.y(), d(3, 1) = w.x();
  d(4, 1) = w.z(), d(4, 2) = w.y();
  d(5, 2) = w.x(), d(5, 0) = w.z();
  return d;
}

}  // namespace

Eigen::Matrix3d ElasticModel::RigidInertia() const {
  return second_moment.trace() * Eigen::Matrix3d::Identity() - second_moment;
}

void ElasticModel::Validate(const std::string& name) const {
  const int ne = num_modes();
  auto fail_if = [&](bool bad, const std::string& what) {
    EMB_THROW_IF(bad, "flexible body '" << name << "' (" << source << "): " << what);
  };
  fail_if(!(mass > 0.0), "expected a positive mass");
  fail_if(K.cols() != ne || D.rows() != ne || D.cols() != ne || St.rows() != 3 ||
              St.cols() != ne || Ibar.rows() != 9 || Ibar.cols() != ne,
          "inconsistent sizes of the modal matrices and invariants");
  for (const auto& S : Sbar) fail_if(S.rows() != ne || S.cols() != ne, "inconsistent Sbar size");
  fail_if(!quasi_static.empty() && static_cast<int>(quasi_static.size()) != ne,
          "inconsistent size of the quasi-static mode flags");
  if (geometric_stiffening) {
    for (const auto& k : kg_centrifugal)
      fail_if(k.rows() != ne || k.cols() != ne, "inconsistent geometric stiffness size");
    for (const auto& k : kg_translational)
      fail_if(k.rows() != ne || k.cols() != ne, "inconsistent geometric stiffness size");
  }
  if (ne == 0) return;
  const double scale = std::max(1.0, K.cwiseAbs().maxCoeff());
  // Relative asymmetry allowed for matrices stored after a floating-point reduction.
  constexpr double kSymmetryTolerance = 1e-8;
  fail_if((K - K.transpose()).cwiseAbs().maxCoeff() > kSymmetryTolerance * scale,
          "expected a symmetric modal stiffness");
  // The modal mass of the dynamic modes must be positive definite; quasi-static modes have
  // none (MakeQuasiStatic).
  std::vector<int> dynamic;
  for (int j = 0; j < ne; ++j)
    if (!is_quasi_static(j)) dynamic.push_back(j);
  if (dynamic.empty()) return;
  const Eigen::MatrixXd Mee = Sbar[0] + Sbar[4] + Sbar[8];
  Eigen::MatrixXd Md(dynamic.size(), dynamic.size());
  for (std::size_t i = 0; i < dynamic.size(); ++i)
    for (std::size_t j = 0; j < dynamic.size(); ++j)
      Md(i, j) = 0.5 * (Mee(dynamic[i], dynamic[j]) + Mee(dynamic[j], dynamic[i]));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> em(Md);
  fail_if(!(em.eigenvalues().minCoeff() > 0.0), "expected a positive definite modal mass");
}

void ElasticModel::MakeQuasiStatic(const std::vector<bool>& flags, const std::string& name) {
  const int ne = num_modes();
  EMB_THROW_IF(static_cast<int>(flags.size()) != ne,
               "flexible body '" << name << "': expected " << ne << " quasi-static flags, got "
                                 << flags.size());
  for (int j = 0; j < ne; ++j) {
    if (!flags[j]) continue;
    EMB_THROW_IF(!(D(j, j) > 0.0),
                 "flexible body '" << name << "' (" << source << "): mode " << j + 1 << " ("
                                   << (j < frequencies_hz.size() ? frequencies_hz[j] : 0.0)
                                   << " Hz) cannot be quasi-static without damping: its rate "
                                      "comes from D eta' = loads - K eta (give the body file a "
                                      "modal damping > 0)");
    for (auto& S : Sbar) {
      S.row(j).setZero();
      S.col(j).setZero();
    }
  }
  quasi_static = flags;
}

void ElasticModel::AddRelaxationDamping(const std::vector<bool>& flags, double tau) {
  const int ne = num_modes();
  EMB_CHECK(static_cast<int>(flags.size()) == ne && tau >= 0.0);
  for (int i = 0; i < ne; ++i)
    for (int j = 0; j < ne; ++j)
      if (flags[i] && flags[j]) D(i, j) += tau * K(i, j);
}

int ElasticModel::num_quasi_static() const {
  int n = 0;
  for (bool f : quasi_static) n += f ? 1 : 0;
  return n;
}

ElasticModel ElasticModel::Subset(const std::vector<int>& keep) const {
  const int n = static_cast<int>(keep.size());
  for (int k : keep) EMB_CHECK(k >= 0 && k < num_modes());
  auto cols = [&](const Eigen::MatrixXd& A) {
    Eigen::MatrixXd out(A.rows(), n);
    for (int j = 0; j < n; ++j) out.col(j) = A.col(keep[j]);
    return out;
  };
  auto square = [&](const Eigen::MatrixXd& A) {
    Eigen::MatrixXd out(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) out(i, j) = A(keep[i], keep[j]);
    return out;
  };
  ElasticModel s = *this;
  s.St = cols(St);
  s.Ibar = cols(Ibar);
  for (int k = 0; k < 9; ++k) s.Sbar[k] = square(Sbar[k]);
  s.K = square(K);
  s.D = square(D);
  s.frequencies_hz.resize(n);
  for (int j = 0; j < n; ++j) s.frequencies_hz[j] = frequencies_hz[keep[j]];
  if (!quasi_static.empty()) {
    s.quasi_static.resize(n);
    for (int j = 0; j < n; ++j) s.quasi_static[j] = quasi_static[keep[j]];
  }
  if (geometric_stiffening) {
    for (auto& k : s.kg_centrifugal) k = square(k);
    for (auto& k : s.kg_translational) k = square(k);
  }
  return s;
}

ElasticModel ElasticModel::Transformed(const Eigen::MatrixXd& T) const {
  EMB_CHECK(T.rows() == num_modes());
  ElasticModel s = *this;
  s.St = St * T;
  s.Ibar = Ibar * T;
  for (int k = 0; k < 9; ++k) s.Sbar[k] = T.transpose() * Sbar[k] * T;
  s.K = T.transpose() * K * T;
  s.D = T.transpose() * D * T;
  s.K = 0.5 * (s.K + s.K.transpose());
  s.D = 0.5 * (s.D + s.D.transpose());
  if (geometric_stiffening) {
    for (auto& k : s.kg_centrifugal) k = T.transpose() * k * T;
    for (auto& k : s.kg_translational) k = T.transpose() * k * T;
  }
  s.quasi_static.clear();
  const Eigen::MatrixXd Mee = s.Sbar[0] + s.Sbar[4] + s.Sbar[8];
  s.frequencies_hz.resize(T.cols());
  for (Eigen::Index j = 0; j < T.cols(); ++j)
    s.frequencies_hz[j] =
        std::sqrt(std::max(0.0, s.K(j, j)) / std::max(Mee(j, j), 1e-300)) / (2.0 * std::numbers::pi);
  return s;
}

FlexibleTerms CalcFlexibleTerms(const ElasticModel& model, const Eigen::Vector3d& p_WB,
                                const Eigen::Matrix3d& R, const Eigen::Vector3d& v_WB,
                                const Eigen::Vector3d& w, const Eigen::VectorXd& eta,
                                const Eigen::VectorXd& eta_dot, const Eigen::Vector3d& g_W,
                                const Eigen::Vector3d& a_B, bool with_derivatives,
                                const Eigen::VectorXd* accel) {
  using Eigen::Matrix3d;
  using Eigen::MatrixXd;
  using Eigen::Vector3d;
  using Eigen::VectorXd;
  const int ne = model.num_modes();
  const int n = 6 + ne;
  const auto& S = model.Sbar;
  const double m = model.mass;

  // B_k(eta) = Ibar_k + sum_l eta_l Sbar(l, k) as rows 3i+j; c, A, J.
  MatrixXd Bm = model.Ibar;
  for (int r = 0; r < 9; ++r) Bm.row(r) += eta.transpose() * S[r];
  const Vector3d c = model.St * eta;
  Matrix3d A = model.second_moment;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) += eta.dot(model.Ibar.row(3 * j + i).transpose() +
                                                   Bm.row(3 * i + j).transpose());
  const Matrix3d J = A.trace() * Matrix3d::Identity() - A;
  const Eigen::Matrix<double, 3, Eigen::Dynamic> Mre = AxialRows(Bm);
  const MatrixXd Mee = S[0] + S[4] + S[8];
  const Eigen::RowVectorXd trB = Bm.row(0) + Bm.row(4) + Bm.row(8);

  FlexibleTerms t;
  t.mass.setZero(n, n);
  t.mass.block<3, 3>(0, 0) = m * Matrix3d::Identity();
  t.mass.block<3, 3>(0, 3) = -R * Skew(c);
  t.mass.block<3, 3>(3, 0) = Skew(c) * R.transpose();
  t.mass.block<3, 3>(3, 3) = J;
  t.mass.block(0, 6, 3, ne) = R * model.St;
  t.mass.block(6, 0, ne, 3) = (R * model.St).transpose();
  t.mass.block(3, 6, 3, ne) = Mre;
  t.mass.block(6, 3, ne, 3) = Mre.transpose();
  t.mass.block(6, 6, ne, ne) = Mee;

  const Vector3d g_B = R.transpose() * g_W;
  const Vector3d s = model.St * eta_dot;
  const MatrixXd G = w.x() * (S[5] - S[7]) + w.y() * (S[6] - S[2]) + w.z() * (S[1] - S[3]);
  // sum_l eta'_l B_l^T w and sum_l eta'_l tr B_l.
  const VectorXd Bd = Bm * eta_dot;  // row 3i+j: sum_l eta'_l B_l(i, j)
  Matrix3d H;                        // sum_l eta'_l B_l
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) H(i, j) = Bd[3 * i + j];
  const double trBd = trB.dot(eta_dot);
  Eigen::Matrix<double, 9, 1> ww;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) ww[3 * i + j] = w[i] * w[j];
  const double w2 = w.squaredNorm();

  t.force.setZero(n);
  const Vector3d wq = w.cross(w.cross(c)) + 2.0 * w.cross(s);
  t.force.head<3>() = m * g_W - R * wq;
  t.force.segment<3>(3) =
      c.cross(g_B) - w.cross(J * w) - 2.0 * (trBd * w - H.transpose() * w);
  const VectorXd centrifugal = Bm.transpose() * ww - w2 * trB.transpose();
  VectorXd fe = model.St.transpose() * g_B - centrifugal - 2.0 * G.transpose() * eta_dot -
                model.K * eta - model.D * eta_dot;
  MatrixXd KG;
  if (model.geometric_stiffening) {
    const auto cp = CentrifugalProducts(w);
    KG = MatrixXd::Zero(ne, ne);
    for (int p = 0; p < 6; ++p) KG += cp[p] * model.kg_centrifugal[p];
    for (int k = 0; k < 3; ++k) KG += a_B[k] * model.kg_translational[k];
    fe -= KG * eta;
  }
  t.force.tail(ne) = fe;

  Eigen::VectorXd V(n);
  V << v_WB, w, eta_dot;
  t.kinetic_energy = 0.5 * V.dot(t.mass * V);
  t.elastic_energy = 0.5 * eta.dot(model.K * eta);
  t.gravity_energy = -m * g_W.dot(p_WB) - g_W.dot(R * c);
  t.dissipated_power = eta_dot.dot(model.D * eta_dot);
  if (!with_derivatives) return t;

  // d f / d V.
  t.damping.setZero(n, n);
  t.damping.block<3, 3>(0, 3) =
      -R * (w * c.transpose() + w.dot(c) * Matrix3d::Identity() - 2.0 * c * w.transpose() -
            2.0 * Skew(s));
  t.damping.block(0, 6, 3, ne) = -2.0 * R * Skew(w) * model.St;
  t.damping.block<3, 3>(3, 3) = -(Skew(w) * J - Skew(J * w)) -
                                2.0 * (trBd * Matrix3d::Identity() - H.transpose());
  for (int l = 0; l < ne; ++l)
    t.damping.block<3, 1>(3, 6 + l) =
        -2.0 * (trB[l] * w - Block3(Bm, l).transpose() * w);
  MatrixXd dfe_dw(ne, 3);
  for (int k = 0; k < ne; ++k) {
    const Matrix3d Bk = Block3(Bm, k);
    dfe_dw.row(k) = -((Bk + Bk.transpose()) * w - 2.0 * trB[k] * w).transpose();
  }
  dfe_dw.col(0) -= 2.0 * (S[5] - S[7]).transpose() * eta_dot;
  dfe_dw.col(1) -= 2.0 * (S[6] - S[2]).transpose() * eta_dot;
  dfe_dw.col(2) -= 2.0 * (S[1] - S[3]).transpose() * eta_dot;
  if (model.geometric_stiffening) {
    const auto dc = CentrifugalProductsDerivative(w);
    for (int p = 0; p < 6; ++p) dfe_dw -= (model.kg_centrifugal[p] * eta) * dc.row(p);
  }
  t.damping.block(6, 3, ne, 3) = dfe_dw;
  t.damping.block(6, 6, ne, ne) = -2.0 * G.transpose() - model.D;

  // d f / d[delta p, delta pi, eta].
  t.stiffness.setZero(n, n);
  t.stiffness.block<3, 3>(0, 3) = R * Skew(wq);
  t.stiffness.block<3, 3>(3, 3) = Skew(c) * Skew(g_B);
  t.stiffness.block(6, 3, ne, 3) = model.St.transpose() * Skew(g_B);
  t.stiffness.block(0, 6, 3, ne) = -R * Skew(w) * Skew(w) * model.St;
  for (int k = 0; k < ne; ++k) {
    const Matrix3d Bk = Block3(Bm, k);
    const Matrix3d dJ = 2.0 * trB[k] * Matrix3d::Identity() - Bk - Bk.transpose();
    t.stiffness.block<3, 1>(3, 6 + k) =
        -Skew(g_B) * model.St.col(k) - w.cross(dJ * w);
  }
  MatrixXd dcent = -w2 * Mee;
  for (int r = 0; r < 9; ++r) dcent += ww[r] * S[r];
  MatrixXd Kee = -model.K - dcent.transpose();
  if (model.geometric_stiffening) Kee -= KG;
  t.stiffness.block(6, 6, ne, ne) = Kee;
  // The translational geometric stiffness -sum_k a_B,k K_a,k eta turns with the frame:
  // a_B = R^T (a - g), d a_B / d delta pi = [a_B x].
  MatrixXd Kae;
  if (model.geometric_stiffening) {
    Kae.resize(ne, 3);
    for (int k = 0; k < 3; ++k) Kae.col(k) = model.kg_translational[k] * eta;
    t.stiffness.block(6, 3, ne, 3) -= Kae * Skew(a_B);
  }
  if (accel == nullptr) return t;

  // d(M a)/dx at fixed a = [a_t, a_w, a_e] (see the header), and df/da.
  EMB_CHECK(accel->size() == n);
  const Vector3d a_t = accel->head<3>(), a_w = accel->segment<3>(3);
  const VectorXd a_e = accel->tail(ne);
  const Vector3d at_B = R.transpose() * a_t;
  t.inertia_stiffness.setZero(n, n);
  // Rows t: m a_t + R y, y = a_w x c + St a_e.
  const Vector3d y = a_w.cross(c) + model.St * a_e;
  t.inertia_stiffness.block<3, 3>(0, 3) = -R * Skew(y);
  t.inertia_stiffness.block(0, 6, 3, ne) = R * Skew(a_w) * model.St;
  // Rows w: [c x] R^T a_t + J a_w + Mre a_e.
  t.inertia_stiffness.block<3, 3>(3, 3) = Skew(c) * Skew(at_B);
  Eigen::Matrix<double, 9, Eigen::Dynamic> W(9, ne);  // W(r, l) = (S[r] a_e)_l
  for (int r = 0; r < 9; ++r) W.row(r) = (S[r] * a_e).transpose();
  Eigen::Matrix<double, 3, Eigen::Dynamic> dMre = AxialRows(W);
  for (int k = 0; k < ne; ++k) {
    const Matrix3d Bk = Block3(Bm, k);
    const Matrix3d dJ = 2.0 * trB[k] * Matrix3d::Identity() - Bk - Bk.transpose();
    dMre.col(k) += dJ * a_w;
  }
  t.inertia_stiffness.block(3, 6, 3, ne) = -Skew(at_B) * model.St + dMre;
  // Rows e: St^T R^T a_t + Mre^T a_w + Mee a_e.
  t.inertia_stiffness.block(6, 3, ne, 3) = model.St.transpose() * Skew(at_B);
  const MatrixXd Ga = a_w.x() * (S[5] - S[7]) + a_w.y() * (S[6] - S[2]) + a_w.z() * (S[1] - S[3]);
  t.inertia_stiffness.block(6, 6, ne, ne) = Ga.transpose();
  // The translational geometric stiffness through a_B = R^T (a_t - g): d/d a_t = R^T.
  t.force_accel.setZero(n, n);
  if (model.geometric_stiffening) t.force_accel.block(6, 0, ne, 3) = -Kae * R.transpose();
  return t;
}

}  // namespace emb::mbs
