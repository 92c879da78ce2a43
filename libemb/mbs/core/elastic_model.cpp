#include "libemb/mbs/core/elastic_model.h"

#include <cmath>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::mbs {

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

int ElasticModel::num_leading_dynamic() const {
  const int ne = num_modes();
  if (quasi_static.empty()) return ne;
  int nd = 0;
  while (nd < ne && !quasi_static[nd]) ++nd;
  for (int j = nd; j < ne; ++j)
    if (!quasi_static[j]) return ne;  // not a trailing run
  return nd;
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
  FlexibleTerms t;
  const unsigned parts = kFlexibleMass | kFlexibleForce | kFlexibleEnergies |
                         (with_derivatives ? kFlexibleDerivatives : 0u);
  if (accel != nullptr) {
    const Eigen::Ref<const Eigen::VectorXd> a(*accel);
    CalcFlexibleTerms(model, p_WB, R, v_WB, w, eta, eta_dot, g_W, a_B, parts, &a, &t);
  } else {
    CalcFlexibleTerms(model, p_WB, R, v_WB, w, eta, eta_dot, g_W, a_B, parts, nullptr, &t);
  }
  return t;
}

}  // namespace emb::mbs
