#include "libemb/cms/coupled_model.h"

#include "libemb/linalg/extended_product.h"
#include "libemb/linalg/submatrix.h"

namespace emb {
namespace {

// Pᵀ A P for A = K or M: the interior block as it is, the reference blocks in extended
// precision from A P_q.
SparseMatrix Project(const SparseMatrix& A, const CoupledModel& m, const Eigen::MatrixXd& Pq) {
  const std::vector<int>& interior = m.partition.interior;
  const int ni = static_cast<int>(interior.size());
  const int nq2 = static_cast<int>(Pq.cols());
  const Eigen::MatrixXd APq = MultiplyExtended(A, Pq);
  const Eigen::MatrixXd Aqq = TransposeProductExtended(Pq, APq);
  const SparseMatrix AII = ExtractSubmatrix(A, interior, interior);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(AII.nonZeros() + std::size_t(nq2) * nq2);
  for (int c = 0; c < AII.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(AII, c); it; ++it) t.emplace_back(it.row(), c, it.value());
  for (int k = 0; k < ni; ++k)
    for (int c = 0; c < nq2; ++c)
      if (const double v = APq(interior[k], c); v != 0.0) {
        t.emplace_back(k, ni + c, v);
        t.emplace_back(ni + c, k, v);
      }
  for (int a = 0; a < nq2; ++a)
    for (int c = 0; c < nq2; ++c) t.emplace_back(ni + a, ni + c, 0.5 * (Aqq(a, c) + Aqq(c, a)));
  SparseMatrix Ay(ni + nq2, ni + nq2);
  Ay.setFromTriplets(t.begin(), t.end());
  Ay.makeCompressed();
  return Ay;
}

}  // namespace

Eigen::MatrixXd CoupledModel::InterfaceReader(int j) const {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(6, size());
  if (q_column[j] >= 0) {
    D.middleCols(q_column[j], 6).setIdentity();
  } else {
    const SparseMatrix rows = partition.C.middleRows(partition.rbe3_row[j], 6);
    D.leftCols(num_interior()) = Eigen::MatrixXd(rows);
  }
  return D;
}

CoupledModel BuildCoupledModel(const Mesh& mesh, const SystemMatrices& sys,
                               const std::vector<Interface>& itfs) {
  CoupledModel m;
  m.partition = PartitionByInterfaces(mesh, itfs);
  const InterfacePartition& part = m.partition;
  const int N = sys.num_dofs();
  const int nb = static_cast<int>(itfs.size());
  const int ni = m.num_interior();
  m.q_column.assign(nb, -1);
  int ny = ni;
  for (int j = 0; j < nb; ++j)
    if (itfs[j].coupling == Coupling::kRbe2) {
      m.q_column[j] = ny;
      ny += 6;
    }
  Eigen::MatrixXd Pq = Eigen::MatrixXd::Zero(N, ny - ni);
  for (size_t k = 0; k < part.slaved.size(); ++k)
    for (int j = 0; j < nb; ++j)
      if (m.q_column[j] >= 0)
        Pq.block(part.slaved[k], m.q_column[j] - ni, 1, 6) = part.TS.block(k, 6 * j, 1, 6);
  std::vector<Eigen::Triplet<double>> pt;
  for (int k = 0; k < ni; ++k) pt.emplace_back(part.interior[k], k, 1.0);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < Pq.cols(); ++c)
      if (Pq(r, c) != 0.0) pt.emplace_back(r, ni + c, Pq(r, c));
  m.P.resize(N, ny);
  m.P.setFromTriplets(pt.begin(), pt.end());
  m.K = Project(sys.K, m, Pq);
  m.M = Project(sys.M, m, Pq);

  m.rigid = Eigen::MatrixXd::Zero(ny, 6);
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const auto Rn = ReferenceRigidMotions(mesh.nodes.col(i));
    for (int c = 0; c < 3; ++c)
      if (part.interior_position[Dof(i, c)] >= 0) m.rigid.row(part.interior_position[Dof(i, c)]) = Rn.row(c);
  }
  for (int j = 0; j < nb; ++j)
    if (m.q_column[j] >= 0) m.rigid.middleRows(m.q_column[j], 6) = ReferenceRigidMotions(itfs[j].point);
  return m;
}

}  // namespace emb
