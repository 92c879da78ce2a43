#include "libemb/cms/inertia_invariants.h"

#include "libemb/common/error.h"
#include "libemb/common/mass_properties.h"
#include "libemb/linalg/kronecker_matrix.h"
#include "libemb/linalg/sparse_dense_product.h"

namespace emb {

Eigen::Matrix3d InertiaInvariants::InertiaAboutCom() const {
  const Eigen::Vector3d c = CenterOfMass();
  const Eigen::Matrix3d Jc = second_moment - mass * c * c.transpose();
  return InertiaFromSecondMoment(Jc);
}

InertiaInvariants CalcInertiaInvariants(const Eigen::Matrix3Xd& nodes, const SparseMatrix& M,
                                        const Eigen::MatrixXd& modes) {
  const int n = static_cast<int>(nodes.cols());
  EMB_THROW_IF(M.rows() != 3 * n || modes.rows() != 3 * n,
               "inertia invariants: expected a " << 3 * n << "-unknown mass matrix and modes, got "
                                                 << M.rows() << " and " << modes.rows());
  const auto kron = KroneckerIdentityMatrix::Detect(M, 3);
  EMB_THROW_IF(!kron, "inertia invariants: expected a consistent mass matrix of the form m (x) I3");
  const SparseMatrix& ms = kron->scalar();
  const int ne = static_cast<int>(modes.cols());

  // F = [1, X̄, Φ_x, Φ_y, Φ_z] (n × (4 + 3 ne)) and m_s F.
  Eigen::MatrixXd F(n, 4 + 3 * ne);
  F.col(0).setOnes();
  F.middleCols(1, 3) = nodes.transpose();
  for (int l = 0; l < 3; ++l)
    for (int i = 0; i < n; ++i) F.block(i, 4 + l * ne, 1, ne) = modes.row(3 * i + l);
  const Eigen::MatrixXd mF = MultiplySymmetric(ms, F);  // m_s is symmetric, as M is

  InertiaInvariants inv;
  const Eigen::MatrixXd head = F.leftCols(4).transpose() * mF;  // 4 × (4 + 3 ne)
  inv.mass = head(0, 0);
  inv.first_moment = head.block<1, 3>(0, 1).transpose();
  inv.second_moment = head.block<3, 3>(1, 1);
  inv.St.resize(3, ne);
  inv.Ibar.resize(9, ne);
  for (int l = 0; l < 3; ++l) {
    inv.St.row(l) = head.block(0, 4 + l * ne, 1, ne);
    for (int k = 0; k < 3; ++k) inv.Ibar.row(3 * k + l) = head.block(1 + k, 4 + l * ne, 1, ne);
  }
  for (int k = 0; k < 3; ++k)
    for (int l = k; l < 3; ++l) {
      inv.Sbar[3 * k + l] = F.middleCols(4 + k * ne, ne).transpose() * mF.middleCols(4 + l * ne, ne);
      if (l != k) inv.Sbar[3 * l + k] = inv.Sbar[3 * k + l].transpose();  // (no self-aliasing)
    }
  return inv;
}

}  // namespace emb
