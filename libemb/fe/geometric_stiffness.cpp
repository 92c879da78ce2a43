#include "libemb/fe/geometric_stiffness.h"

#include <algorithm>

#include "libemb/common/error.h"
#include "libemb/fe/cell_dispatch.h"
#include "libemb/fe/solid_element.h"

namespace emb {
namespace {

template <CellType T>
typename SolidElement<T>::NodeCoords CellCoords(const Mesh& mesh, const int* nodes) {
  typename SolidElement<T>::NodeCoords X;
  for (int a = 0; a < SolidElement<T>::kNodes; ++a) X.col(a) = mesh.nodes.col(nodes[a]);
  return X;
}

template <CellType T>
void CheckCell(const Mesh& mesh, const CellBlock& block, int c,
               const typename SolidElement<T>::NodeCoords& X, double min_det) {
  const double size = (X.rowwise().maxCoeff() - X.rowwise().minCoeff()).norm();
  CheckCellJacobian(mesh.source, T, block.tags[c], min_det, size);
}

template <CellType T>
void StressBlock(const Mesh& mesh, const CellBlock& block, const IsotropicMaterial& mat,
                 const Eigen::VectorXd& u, std::vector<Eigen::Matrix3d>& out) {
  using Element = SolidElement<T>;
  const int np = Element::NumStressPoints();
  out.resize(static_cast<std::size_t>(block.num_cells()) * np);
  typename Element::NodalVectors U;
  for (int c = 0; c < block.num_cells(); ++c) {
    const int* nodes = block.cell(c);
    const auto X = CellCoords<T>(mesh, nodes);
    for (int a = 0; a < Element::kNodes; ++a) U.col(a) = u.segment<3>(3 * nodes[a]);
    const double det = Element::CalcStresses(X, U, mat.lambda(), mat.mu(),
                                             out.data() + static_cast<std::size_t>(c) * np);
    CheckCell<T>(mesh, block, c, X, det);
  }
}

// Position of row `row` in column `col` of `A` (an entry of the pattern).
int Find(const SparseMatrix& A, int row, int col) {
  const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[col];
  const int* end = A.innerIndexPtr() + A.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  EMB_THROW_IF(it == end || *it != row, "geometric stiffness: the node pattern has no entry ("
                                            << row << ", " << col
                                            << "); expected the pattern of the same mesh");
  return static_cast<int>(it - A.innerIndexPtr());
}

template <CellType T>
void GeometricBlock(const Mesh& mesh, const CellBlock& block, const Eigen::Matrix3d* sigma, int np,
                    SparseMatrix& S) {
  using Element = SolidElement<T>;
  constexpr int kN = Element::kNodes;
  EMB_THROW_IF(np != Element::NumStressPoints(),
               "geometric stiffness: " << np << " stress points per " << Name(T)
                                       << " cell; expected " << Element::NumStressPoints());
  typename Element::ScalarMass s;
  double* val = S.valuePtr();
  for (int c = 0; c < block.num_cells(); ++c) {
    const int* nodes = block.cell(c);
    const auto X = CellCoords<T>(mesh, nodes);
    const double det =
        Element::CalcGeometricStiffness(X, sigma + static_cast<std::size_t>(c) * np, s);
    CheckCell<T>(mesh, block, c, X, det);
    for (int b = 0; b < kN; ++b)
      for (int a = 0; a < kN; ++a) val[Find(S, nodes[a], nodes[b])] += s(a, b);
  }
}

}  // namespace

StressField CalcStressField(const Mesh& mesh, const IsotropicMaterial& material,
                            const Eigen::VectorXd& u) {
  material.Validate();
  EMB_THROW_IF(u.size() != 3 * mesh.num_nodes(),
               "stress recovery: displacement of size " << u.size() << "; expected 3 x "
                                                        << mesh.num_nodes() << " nodes");
  StressField f;
  f.values.resize(mesh.blocks.size());
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    DispatchSolid(mesh.blocks[b].type, [&](auto type) {
      constexpr CellType T = decltype(type)::value;
      StressBlock<T>(mesh, mesh.blocks[b], material, u, f.values[b]);
      f.points.push_back(SolidElement<T>::NumStressPoints());
    });
  return f;
}

StressField UniformStressField(const Mesh& mesh, const Eigen::Matrix3d& sigma) {
  StressField f;
  for (const auto& block : mesh.blocks)
    DispatchSolid(block.type, [&](auto type) {
      const int np = SolidElement<decltype(type)::value>::NumStressPoints();
      f.points.push_back(np);
      f.values.emplace_back(static_cast<std::size_t>(block.num_cells()) * np, sigma);
    });
  return f;
}

SparseMatrix NodePattern(const SparseMatrix& K) {
  EMB_THROW_IF(K.rows() != K.cols() || K.rows() % 3 != 0 || !K.isCompressed(),
               "node pattern: expected a compressed square matrix of 3 x nodes rows, got "
                   << K.rows() << " x " << K.cols());
  const int n = static_cast<int>(K.rows() / 3);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(K.nonZeros() / 9);
  for (int b = 0; b < n; ++b)
    for (SparseMatrix::InnerIterator it(K, 3 * b); it; ++it)
      if (it.row() % 3 == 0) t.emplace_back(it.row() / 3, b, 0.0);
  SparseMatrix P(n, n);
  P.setFromTriplets(t.begin(), t.end());
  P.makeCompressed();
  return P;
}

SparseMatrix AssembleNodalGeometricStiffness(const Mesh& mesh, const StressField& stress,
                                             const SparseMatrix& node_pattern) {
  const int n = mesh.num_nodes();
  EMB_THROW_IF(node_pattern.rows() != n || node_pattern.cols() != n || !node_pattern.isCompressed(),
               "geometric stiffness: node pattern " << node_pattern.rows() << " x "
                                                    << node_pattern.cols()
                                                    << "; expected the compressed pattern of "
                                                    << n << " nodes");
  EMB_THROW_IF(stress.values.size() != mesh.blocks.size() ||
                   stress.points.size() != mesh.blocks.size(),
               "geometric stiffness: stresses for " << stress.values.size()
                                                    << " cell blocks; expected "
                                                    << mesh.blocks.size());
  SparseMatrix S = node_pattern;
  std::fill(S.valuePtr(), S.valuePtr() + S.nonZeros(), 0.0);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const CellBlock& block = mesh.blocks[b];
    EMB_THROW_IF(stress.values[b].size() !=
                     static_cast<std::size_t>(block.num_cells()) * stress.points[b],
                 "geometric stiffness: block " << b << " has " << stress.values[b].size()
                                               << " stresses; expected " << block.num_cells()
                                               << " cells x " << stress.points[b] << " points");
    DispatchSolid(block.type, [&](auto type) {
      GeometricBlock<decltype(type)::value>(mesh, block, stress.cell(static_cast<int>(b), 0),
                                            stress.points[b], S);
    });
  }
  return S;
}

SparseMatrix AssembleGeometricStiffness(const Mesh& mesh, const StressField& stress,
                                        const SparseMatrix& pattern) {
  const int N = 3 * mesh.num_nodes();
  EMB_THROW_IF(pattern.rows() != N || pattern.cols() != N,
               "geometric stiffness: pattern " << pattern.rows() << " x " << pattern.cols()
                                               << "; expected the K of " << N << " unknowns");
  const SparseMatrix S = AssembleNodalGeometricStiffness(mesh, stress, NodePattern(pattern));
  SparseMatrix KG = pattern;
  for (int col = 0; col < N; ++col)
    for (SparseMatrix::InnerIterator it(KG, col); it; ++it)
      it.valueRef() = it.row() % 3 == col % 3 ? S.coeff(it.row() / 3, col / 3) : 0.0;
  return KG;
}

}  // namespace emb
