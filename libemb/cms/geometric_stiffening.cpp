#include "libemb/cms/geometric_stiffening.h"

#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/parallel.h"
#include "libemb/fe/geometric_stiffness.h"
#include "libemb/linalg/blas.h"
#include "libemb/linalg/sparse_dense_product.h"

namespace emb {

Eigen::Matrix<double, 6, 1> CentrifugalProducts(const Eigen::Vector3d& w) {
  Eigen::Matrix<double, 6, 1> c;
  c << w.x() * w.x(), w.y() * w.y(), w.z() * w.z(), w.x() * w.y(), w.y() * w.z(), w.z() * w.x();
  return c;
}

Eigen::MatrixXd GeometricStiffness::Combine(const Eigen::Vector3d& omega,
                                            const Eigen::Vector3d& a) const {
  EMB_THROW_IF(!present, "geometric stiffness: expected the body's stiffening data, but the "
                         "body has none (reduced with --no-geometric-stiffness, or an old file)");
  const Eigen::Matrix<double, 6, 1> c = CentrifugalProducts(omega);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(centrifugal[0].rows(), centrifugal[0].cols());
  for (int p = 0; p < 6; ++p) K += c[p] * centrifugal[p];
  for (int k = 0; k < 3; ++k) K += a[k] * translational[k];
  return K;
}

std::string GeometricStiffness::Describe() const {
  if (!present) return "none";
  std::ostringstream o;
  o << "9 matrices " << centrifugal[0].rows() << " x " << centrifugal[0].cols()
    << " (6 centrifugal, 3 translational), " << support << ", about (" << reference_point.x()
    << ", " << reference_point.y() << ", " << reference_point.z() << ") m";
  return o.str();
}

Eigen::MatrixXd InertialLoadFields(const Mesh& mesh, const Eigen::Vector3d& reference_point) {
  const int n = mesh.num_nodes();
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3 * n, 9);
  for (int a = 0; a < n; ++a) {
    const Eigen::Vector3d r = mesh.nodes.col(a) - reference_point;
    auto b = [&](int p) { return B.block<3, 1>(3 * a, p); };
    b(0) << 0.0, r.y(), r.z();
    b(1) << r.x(), 0.0, r.z();
    b(2) << r.x(), r.y(), 0.0;
    b(3) << -r.y(), -r.x(), 0.0;
    b(4) << 0.0, -r.z(), -r.y();
    b(5) << -r.z(), 0.0, -r.x();
    for (int k = 0; k < 3; ++k) b(6 + k) = -Eigen::Vector3d::Unit(k);
  }
  return B;
}

GeometricStiffness ReduceGeometricStiffness(const Mesh& mesh, const IsotropicMaterial& material,
                                            const SparseMatrix& pattern,
                                            const Eigen::MatrixXd& responses,
                                            const Eigen::MatrixXd& Phi) {
  const int N = 3 * mesh.num_nodes();
  EMB_THROW_IF(responses.rows() != N || responses.cols() != 9 || Phi.rows() != N,
               "geometric stiffness: expected 9 responses and mode shapes of " << N
                   << " unknowns, got " << responses.rows() << " x " << responses.cols()
                   << " and " << Phi.rows() << " x " << Phi.cols());
  // K_σ = S ⊗ I₃, so Φᵀ K_σ Φ = Σ_c Φ_cᵀ S Φ_c with Φ_c the rows of component c: a third of
  // the sparse work of the 3-D matrix, whose off-diagonal block entries are zeros. P = [Φ_x Φ_y
  // Φ_z] (n × 3ne) is multiplied by the symmetric S on row-major panels
  // (sparse_dense_product.h) and the three products Φ_cᵀ (S Φ_c) go through the BLAS (blas.h:
  // its AVX kernels; Eigen's, compiled for baseline x86-64, took ~3× longer).
  const int n = mesh.num_nodes(), ne = static_cast<int>(Phi.cols());
  Eigen::MatrixXd P(n, 3 * ne);
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < ne; ++k)
      for (int a = 0; a < n; ++a) P(a, c * ne + k) = Phi(3 * a + c, k);
  const SparseMatrix node_pattern = NodePattern(pattern);
  GeometricStiffness g;
  UseOneBlasThread();  // the load cases call the BLAS concurrently
  // The nine load cases are independent, each writing its own matrix: run concurrently.
  ParallelFor(9, [&](int p) {
    const SparseMatrix S = AssembleNodalGeometricStiffness(
        mesh, CalcStressField(mesh, material, responses.col(p)), node_pattern);
    const Eigen::MatrixXd SP = MultiplySymmetric(S, P);
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(ne, ne);
    for (int c = 0; c < 3; ++c)
      Gemm(true, 1.0, P.middleCols(c * ne, ne), SP.middleCols(c * ne, ne), 1.0, A);
    Eigen::MatrixXd& out = p < 6 ? g.centrifugal[p] : g.translational[p - 6];
    out = 0.5 * (A + A.transpose());
  });
  g.present = true;
  return g;
}

}  // namespace emb
