// CalcFlexibleTerms (elastic_model.h): the floating-frame inertia, elastic, damping and
// geometric-stiffness terms of one flexible body, evaluated in place.
#include <cmath>

#include "libemb/common/error.h"
#include "libemb/mbs/core/elastic_model.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {
namespace {

// Column k of the 9 x ne matrix Bm as the 3 x 3 matrix B_k (row 3i+j = B_k(i, j)).
Eigen::Matrix3d Block3(const Eigen::MatrixXd& Bm, int k) {
  Eigen::Matrix3d B;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) B(i, j) = Bm(3 * i + j, k);
  return B;
}

// Rows of Bm that give the axial vector of B_k - B_k^T, i.e. the column k of ∫ρ u x Phi_k.
template <typename Rows9>
void AxialRows(const Eigen::MatrixBase<Rows9>& Bm, Eigen::MatrixXd* a) {
  a->resize(3, Bm.cols());
  a->row(0) = Bm.row(5) - Bm.row(7);
  a->row(1) = Bm.row(6) - Bm.row(2);
  a->row(2) = Bm.row(1) - Bm.row(3);
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

// The symmetric Q with w^T Q w = sum_p c_p(w) s_p for the products c_p of
// CentrifugalProducts: Q = [s0 s3/2 s5/2; s3/2 s1 s4/2; s5/2 s4/2 s2].
Eigen::Matrix3d ProductForm(const Eigen::Matrix<double, 6, 1>& s) {
  Eigen::Matrix3d Q;
  Q << s[0], 0.5 * s[3], 0.5 * s[5], 0.5 * s[3], s[1], 0.5 * s[4], 0.5 * s[5], 0.5 * s[4], s[2];
  return Q;
}

}  // namespace

void CalcFlexibleTerms(const ElasticModel& model, const Eigen::Vector3d& p_WB,
                       const Eigen::Matrix3d& R, const Eigen::Vector3d& v_WB,
                       const Eigen::Vector3d& w, const Eigen::Ref<const Eigen::VectorXd>& eta,
                       const Eigen::Ref<const Eigen::VectorXd>& eta_dot,
                       const Eigen::Vector3d& g_W, const Eigen::Vector3d& a_B, unsigned parts,
                       const Eigen::Ref<const Eigen::VectorXd>* accel, FlexibleTerms* out) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  FlexibleTerms& t = *out;
  FlexibleTerms::Scratch& x = t.scratch;
  const bool derivatives = (parts & kFlexibleDerivatives) != 0;
  const bool want_mass = derivatives || (parts & (kFlexibleMass | kFlexibleEnergies)) != 0;
  const bool want_force = derivatives || (parts & kFlexibleForce) != 0;
  const int ne = model.num_modes();
  const int n = 6 + ne;
  // The inertia (Sbar) lives in the leading nd coordinates; the trailing quasi-static ones
  // have none (ElasticModel::MakeQuasiStatic), so every Sbar product runs over nd only.
  const int nd = model.num_leading_dynamic();
  const auto& S = model.Sbar;
  auto Sd = [&](int r) { return S[r].topLeftCorner(nd, nd); };
  const double m = model.mass;

  // B_k(eta) = Ibar_k + sum_l eta_l Sbar(l, k) as rows 3i+j; c, A, J.
  x.Bm = model.Ibar;
  for (int r = 0; r < 9; ++r)
    x.Bm.row(r).head(nd).noalias() += eta.head(nd).transpose() * Sd(r);
  const Vector3d c = model.St * eta;
  Matrix3d A = model.second_moment;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      A(i, j) += eta.dot(model.Ibar.row(3 * j + i).transpose() + x.Bm.row(3 * i + j).transpose());
  const Matrix3d J = A.trace() * Matrix3d::Identity() - A;
  AxialRows(x.Bm, &x.Mre);
  x.Mee = Sd(0) + Sd(4) + Sd(8);
  x.trB = (x.Bm.row(0) + x.Bm.row(4) + x.Bm.row(8)).transpose();

  const bool kg = model.geometric_stiffening;
  const Eigen::Matrix<double, 6, 1> cp = CentrifugalProducts(w);
  // The centrifugal stiffening as kinetic energy (the foreshortening of a bent body moves
  // its mass towards the spin axis): T_G = -1/2 eta^T K_G(w) eta = -1/2 w^T Q(eta) w with
  // Q = ProductForm(s), s_p = eta^T K_p eta. Its Lagrange equations give the force
  // -K_G(w) eta on eta and, on the rotation, the mass J - Q and the force
  // w x (Q w) + Q' w (Q' = ProductForm(s'), s'_p = 2 eta'^T K_p eta). With the force on eta
  // alone the stiffening did work whenever w had a part that follows eta' (a frame held at
  // an elastic interface): a bent, spinning cantilever's torsion mode grew from round-off.
  x.Kc.resize(ne, 6);
  Eigen::Matrix<double, 6, 1> s_kg = Eigen::Matrix<double, 6, 1>::Zero(), sd_kg = s_kg;
  if (kg) {
    for (int p = 0; p < 6; ++p) {
      x.Kc.col(p).noalias() = model.kg_centrifugal[p] * eta;
      s_kg[p] = eta.dot(x.Kc.col(p));
      sd_kg[p] = 2.0 * eta_dot.dot(x.Kc.col(p));
    }
  }
  const Matrix3d Q = ProductForm(s_kg), Qd = ProductForm(sd_kg);

  if (want_mass) {
    t.mass.setZero(n, n);
    t.mass.block<3, 3>(0, 0) = m * Matrix3d::Identity();
    t.mass.block<3, 3>(0, 3) = -R * Skew(c);
    t.mass.block<3, 3>(3, 0) = Skew(c) * R.transpose();
    t.mass.block<3, 3>(3, 3) = J - Q;
    t.mass.block(0, 6, 3, ne).noalias() = R * model.St;
    t.mass.block(6, 0, ne, 3) = t.mass.block(0, 6, 3, ne).transpose();
    t.mass.block(3, 6, 3, ne) = x.Mre;
    t.mass.block(6, 3, ne, 3) = x.Mre.transpose();
    t.mass.block(6, 6, nd, nd) = x.Mee;
  }

  const Vector3d g_B = R.transpose() * g_W;
  const Vector3d s = model.St * eta_dot;
  // G(w) = w_x (S_yz - S_zy) + w_y (S_zx - S_xz) + w_z (S_xy - S_yx), over nd.
  x.G = w.x() * (Sd(5) - Sd(7)) + w.y() * (Sd(6) - Sd(2)) + w.z() * (Sd(1) - Sd(3));
  Eigen::Matrix<double, 9, 1> Bd;  // row 3i+j: sum_l eta'_l B_l(i, j)
  Bd.noalias() = x.Bm * eta_dot;
  Matrix3d H;  // sum_l eta'_l B_l
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) H(i, j) = Bd[3 * i + j];
  const double trBd = x.trB.dot(eta_dot);
  Eigen::Matrix<double, 9, 1> ww;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) ww[3 * i + j] = w[i] * w[j];
  const double w2 = w.squaredNorm();

  if (want_force) {
    t.force.resize(n);
    const Vector3d wq = w.cross(w.cross(c)) + 2.0 * w.cross(s);
    t.force.head<3>() = m * g_W - R * wq;
    t.force.segment<3>(3) = c.cross(g_B) - w.cross((J - Q) * w) -
                            2.0 * (trBd * w - H.transpose() * w) + Qd * w;
    // f_e = St^T g_B - (Bm^T ww - |w|^2 trB) - 2 G^T eta' - K eta - D eta' - K_G eta.
    auto fe = t.force.tail(ne);
    fe.noalias() = model.St.transpose() * g_B;
    fe.noalias() -= x.Bm.transpose() * ww;
    fe += w2 * x.trB;
    fe.head(nd).noalias() -= 2.0 * (x.G.transpose() * eta_dot.head(nd));
    fe.noalias() -= model.K * eta;
    fe.noalias() -= model.D * eta_dot;
    if (kg) {
      fe.noalias() -= x.Kc * cp;
      for (int k = 0; k < 3; ++k) {
        x.Kg_eta.noalias() = model.kg_translational[k] * eta;
        fe -= a_B[k] * x.Kg_eta;
      }
    }
  }

  if ((parts & kFlexibleEnergies) != 0) {
    x.tmp.resize(n);
    x.tmp << v_WB, w, eta_dot;
    t.kinetic_energy = 0.5 * x.tmp.dot(t.mass * x.tmp);
    t.elastic_energy = 0.5 * eta.dot(model.K * eta);
    t.gravity_energy = -m * g_W.dot(p_WB) - g_W.dot(R * c);
    t.dissipated_power = eta_dot.dot(model.D * eta_dot);
  }
  if (!derivatives) return;

  // d f / d V.
  t.damping.setZero(n, n);
  t.damping.block<3, 3>(0, 3) =
      -R * (w * c.transpose() + w.dot(c) * Matrix3d::Identity() - 2.0 * c * w.transpose() -
            2.0 * Skew(s));
  t.damping.block(0, 6, 3, ne).noalias() = (-2.0 * R * Skew(w)) * model.St;
  t.damping.block<3, 3>(3, 3) = -(Skew(w) * (J - Q) - Skew((J - Q) * w)) -
                                2.0 * (trBd * Matrix3d::Identity() - H.transpose()) + Qd;
  for (int l = 0; l < ne; ++l)
    t.damping.block<3, 1>(3, 6 + l) = -2.0 * (x.trB[l] * w - Block3(x.Bm, l).transpose() * w);
  auto dfe_dw = t.damping.block(6, 3, ne, 3);
  for (int k = 0; k < ne; ++k) {
    const Matrix3d Bk = Block3(x.Bm, k);
    dfe_dw.row(k) = -((Bk + Bk.transpose()) * w - 2.0 * x.trB[k] * w).transpose();
  }
  // One product per matrix (a difference of matrices would be a temporary).
  const int pairs[3][2] = {{5, 7}, {6, 2}, {1, 3}};
  for (int k = 0; k < 3; ++k) {
    dfe_dw.col(k).head(nd).noalias() -= 2.0 * (Sd(pairs[k][0]).transpose() * eta_dot.head(nd));
    dfe_dw.col(k).head(nd).noalias() += 2.0 * (Sd(pairs[k][1]).transpose() * eta_dot.head(nd));
  }
  // d(Q' w)/d eta' = P = sum_p (d c_p/d w)^T (K_p eta)^T (as d c_p / d w = 2 E_p w with
  // w^T E_p w = c_p): the transpose of the stiffening's d f_e / d w = -P^T.
  const Eigen::Matrix<double, 6, 3> dc = CentrifugalProductsDerivative(w);
  if (kg) {
    x.P.noalias() = dc.transpose() * x.Kc.transpose();
    dfe_dw.noalias() -= x.P.transpose();
    t.damping.block(3, 6, 3, ne) += x.P;
  }
  t.damping.block(6, 6, ne, ne) = -model.D;
  t.damping.block(6, 6, nd, nd) -= 2.0 * x.G.transpose();

  // d f / d[delta p, delta pi, eta].
  const Vector3d wq = w.cross(w.cross(c)) + 2.0 * w.cross(s);
  t.stiffness.setZero(n, n);
  t.stiffness.block<3, 3>(0, 3) = R * Skew(wq);
  t.stiffness.block<3, 3>(3, 3) = Skew(c) * Skew(g_B);
  t.stiffness.block(6, 3, ne, 3).noalias() = model.St.transpose() * Skew(g_B);
  t.stiffness.block(0, 6, 3, ne).noalias() = (-R * Skew(w) * Skew(w)) * model.St;
  for (int k = 0; k < ne; ++k) {
    const Matrix3d Bk = Block3(x.Bm, k);
    const Matrix3d dJ = 2.0 * x.trB[k] * Matrix3d::Identity() - Bk - Bk.transpose();
    t.stiffness.block<3, 1>(3, 6 + k) = -Skew(g_B) * model.St.col(k) - w.cross(dJ * w);
  }
  if (kg) {
    // d(w x Q w + Q' w)/d eta: d(Q w)/d eta = P, d(Q' w)/d eta = sum_p dc_p^T (K_p eta')^T.
    x.Kcd.resize(ne, 6);
    for (int p = 0; p < 6; ++p) x.Kcd.col(p).noalias() = model.kg_centrifugal[p] * eta_dot;
    t.stiffness.block(3, 6, 3, ne).noalias() += Skew(w) * x.P;
    t.stiffness.block(3, 6, 3, ne).noalias() += dc.transpose() * x.Kcd.transpose();
  }
  auto Kee = t.stiffness.block(6, 6, ne, ne);
  Kee = -model.K;
  // -(d centrifugal / d eta)^T = -(sum_r ww_r S_r - |w|^2 Mee)^T, over nd.
  x.W = -w2 * x.Mee;
  for (int r = 0; r < 9; ++r) x.W += ww[r] * Sd(r);
  Kee.topLeftCorner(nd, nd) -= x.W.transpose();
  if (kg) {
    x.KG.setZero(ne, ne);
    for (int p = 0; p < 6; ++p) x.KG += cp[p] * model.kg_centrifugal[p];
    for (int k = 0; k < 3; ++k) x.KG += a_B[k] * model.kg_translational[k];
    Kee -= x.KG;
    // The translational geometric stiffness -sum_k a_B,k K_a,k eta turns with the frame:
    // a_B = R^T (a - g), d a_B / d delta pi = [a_B x].
    x.Kae.resize(ne, 3);
    for (int k = 0; k < 3; ++k) x.Kae.col(k).noalias() = model.kg_translational[k] * eta;
    t.stiffness.block(6, 3, ne, 3).noalias() -= x.Kae * Skew(a_B);
    t.force_accel.setZero(n, n);
    if (accel != nullptr)
      t.force_accel.block(6, 0, ne, 3).noalias() = x.Kae * (-R.transpose());
  } else {
    t.force_accel.setZero(n, n);
  }
  if (accel == nullptr) return;

  // d(M a)/dx at fixed a = [a_t, a_w, a_e] (see the header).
  EMB_CHECK(accel->size() == n);
  const Vector3d a_t = accel->head<3>(), a_w = accel->segment<3>(3);
  const auto a_e = accel->tail(ne);
  const Vector3d at_B = R.transpose() * a_t;
  t.inertia_stiffness.setZero(n, n);
  // Rows t: m a_t + R y, y = a_w x c + St a_e.
  const Vector3d y = a_w.cross(c) + model.St * a_e;
  t.inertia_stiffness.block<3, 3>(0, 3) = -R * Skew(y);
  t.inertia_stiffness.block(0, 6, 3, ne).noalias() = (R * Skew(a_w)) * model.St;
  // Rows w: [c x] R^T a_t + J a_w + Mre a_e.
  t.inertia_stiffness.block<3, 3>(3, 3) = Skew(c) * Skew(at_B);
  // Wa(r, l) = (S[r] a_e)_l, kept transposed (column r) so each product fills a column.
  x.WaT.setZero(ne, 9);
  for (int r = 0; r < 9; ++r) x.WaT.col(r).head(nd).noalias() = Sd(r) * a_e.head(nd);
  AxialRows(x.WaT.transpose(), &x.dMre);
  for (int k = 0; k < ne; ++k) {
    const Matrix3d Bk = Block3(x.Bm, k);
    const Matrix3d dJ = 2.0 * x.trB[k] * Matrix3d::Identity() - Bk - Bk.transpose();
    x.dMre.col(k) += dJ * a_w;
  }
  t.inertia_stiffness.block(3, 6, 3, ne) = x.dMre;
  t.inertia_stiffness.block(3, 6, 3, ne).noalias() -= Skew(at_B) * model.St;
  // Rows w also hold -Q(eta) a_w: d/d eta = -sum_p (d c_p/d w at a_w)^T (K_p eta)^T.
  if (kg)
    t.inertia_stiffness.block(3, 6, 3, ne).noalias() -=
        CentrifugalProductsDerivative(a_w).transpose() * x.Kc.transpose();
  // Rows e: St^T R^T a_t + Mre^T a_w + Mee a_e.
  t.inertia_stiffness.block(6, 3, ne, 3).noalias() = model.St.transpose() * Skew(at_B);
  t.inertia_stiffness.block(6, 6, nd, nd) =
      (a_w.x() * (Sd(5) - Sd(7)) + a_w.y() * (Sd(6) - Sd(2)) + a_w.z() * (Sd(1) - Sd(3)))
          .transpose();
}

}  // namespace emb::mbs
