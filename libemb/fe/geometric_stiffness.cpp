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
  EMB_THROW_IF(it == end || *it != row, "geometric stiffness: the sparsity pattern has no entry ("
                                            << row << ", " << col
                                            << "); expected the stiffness K of the same mesh");
  return static_cast<int>(it - A.innerIndexPtr());
}

template <CellType T>
void GeometricBlock(const Mesh& mesh, const CellBlock& block, const Eigen::Matrix3d* sigma, int np,
                    SparseMatrix& KG) {
  using Element = SolidElement<T>;
  constexpr int kN = Element::kNodes;
  EMB_THROW_IF(np != Element::NumStressPoints(),
               "geometric stiffness: " << np << " stress points per " << Name(T)
                                       << " cell; expected " << Element::NumStressPoints());
  typename Element::ScalarMass s;
  double* val = KG.valuePtr();
  for (int c = 0; c < block.num_cells(); ++c) {
    const int* nodes = block.cell(c);
    const auto X = CellCoords<T>(mesh, nodes);
    const double det =
        Element::CalcGeometricStiffness(X, sigma + static_cast<std::size_t>(c) * np, s);
    CheckCell<T>(mesh, block, c, X, det);
    for (int b = 0; b < kN; ++b)
      for (int a = 0; a < kN; ++a) {
        // The three diagonal entries of block (a, b) lie at the same offset in the columns of
        // node b, as the pattern stores full 3×3 node blocks.
        const int first = Find(KG, 3 * nodes[a], 3 * nodes[b]);
        const int offset = first - KG.outerIndexPtr()[3 * nodes[b]];
        for (int i = 0; i < 3; ++i) val[KG.outerIndexPtr()[3 * nodes[b] + i] + offset + i] += s(a, b);
      }
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

SparseMatrix AssembleGeometricStiffness(const Mesh& mesh, const StressField& stress,
                                        const SparseMatrix& pattern) {
  const int n = 3 * mesh.num_nodes();
  EMB_THROW_IF(pattern.rows() != n || pattern.cols() != n || !pattern.isCompressed(),
               "geometric stiffness: pattern " << pattern.rows() << " x " << pattern.cols()
                                               << "; expected the compressed K of " << n
                                               << " unknowns");
  EMB_THROW_IF(stress.values.size() != mesh.blocks.size() ||
                   stress.points.size() != mesh.blocks.size(),
               "geometric stiffness: stresses for " << stress.values.size()
                                                    << " cell blocks; expected "
                                                    << mesh.blocks.size());
  SparseMatrix KG = pattern;
  std::fill(KG.valuePtr(), KG.valuePtr() + KG.nonZeros(), 0.0);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const CellBlock& block = mesh.blocks[b];
    EMB_THROW_IF(stress.values[b].size() !=
                     static_cast<std::size_t>(block.num_cells()) * stress.points[b],
                 "geometric stiffness: block " << b << " has " << stress.values[b].size()
                                               << " stresses; expected " << block.num_cells()
                                               << " cells x " << stress.points[b] << " points");
    DispatchSolid(block.type, [&](auto type) {
      GeometricBlock<decltype(type)::value>(mesh, block, stress.cell(static_cast<int>(b), 0),
                                            stress.points[b], KG);
    });
  }
  return KG;
}

}  // namespace emb
