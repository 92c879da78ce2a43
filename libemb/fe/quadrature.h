#pragma once
/// @file
/// Quadrature rules on the reference cells (gmsh's reference coordinates):
///   hexahedron [-1,1]³, tetrahedron {ξ,η,ζ ≥ 0, ξ+η+ζ ≤ 1} (volume 1/6),
///   wedge {ξ,η ≥ 0, ξ+η ≤ 1} × ζ∈[-1,1], triangle {ξ,η ≥ 0, ξ+η ≤ 1}, quadrilateral [-1,1]².
/// Simplex rules are collapsed (Duffy) products of Gauss–Jacobi rules: all weights positive,
/// all points inside, exact to any requested total degree.

#include <vector>

#include <Eigen/Core>

namespace emb {

struct QuadratureRule {
  std::vector<Eigen::Vector3d> points;  ///< reference coordinates (unused ones are 0)
  std::vector<double> weights;
  int size() const { return static_cast<int>(weights.size()); }
};

/// n-point Gauss–Jacobi rule on [-1,1] for the weight (1−x)^α (1+x)^β: exact for polynomials
/// of degree 2n−1 times the weight. Gauss–Legendre is α = β = 0. (Golub–Welsch.)
void GaussJacobi(int n, double alpha, double beta, Eigen::VectorXd& x, Eigen::VectorXd& w);

/// Tensor Gauss rule on [-1,1]³, n points per direction: exact for degree ≤ 2n−1 in each variable.
QuadratureRule HexRule(int n);
/// [-1,1]², n points per direction.
QuadratureRule QuadRule(int n);
/// Exact for every polynomial of total degree ≤ `degree` on the reference tetrahedron.
QuadratureRule TetRule(int degree);
/// Exact for total degree ≤ `degree` on the reference triangle.
QuadratureRule TriRule(int degree);
/// Triangle rule of total degree `tri_degree` × Gauss rule of `n_line` points in ζ.
QuadratureRule WedgeRule(int tri_degree, int n_line);

}  // namespace emb
