#pragma once
/// @file
/// Reference elements in gmsh's node ordering and reference coordinates, with their shape
/// functions built from a monomial basis:
///   N_i(ξ) = Σ_j A_ij p_j(ξ),   A = V⁻ᵀ,   V_kj = p_j(ξ_k)   (so N_i(ξ_k) = δ_ik).
/// The bases are the standard ones: complete P1/P2 for simplices, Q1 for Hex8, the 20-term
/// serendipity space for Hex20, {P2(ξ,η)}⊗{1,ζ} + ζ²{1,ξ,η} for Wedge15.
/// Fixed-size Eigen, no virtual functions: these sit in the innermost loops.

#include <array>

#include <Eigen/Core>
#include <Eigen/LU>

#include "libemb/fe/quadrature.h"
#include "libemb/mesh/cell_type.h"

namespace emb {

template <CellType T>
struct ElementTraits;

#define EMB_ELEMENT_TRAITS(TYPE, NODES, DIM)       \
  template <>                                      \
  struct ElementTraits<CellType::TYPE> {           \
    static constexpr int kNodes = NODES;           \
    static constexpr int kDim = DIM;               \
    static const std::array<std::array<double, 3>, NODES> kNodeCoords; \
    static const std::array<std::array<int, 3>, NODES> kMonomials;     \
    static QuadratureRule StiffnessRule();         \
    static QuadratureRule MassRule();              \
  };
EMB_ELEMENT_TRAITS(kTri3, 3, 2)
EMB_ELEMENT_TRAITS(kTri6, 6, 2)
EMB_ELEMENT_TRAITS(kQuad4, 4, 2)
EMB_ELEMENT_TRAITS(kQuad8, 8, 2)
EMB_ELEMENT_TRAITS(kTet4, 4, 3)
EMB_ELEMENT_TRAITS(kTet10, 10, 3)
EMB_ELEMENT_TRAITS(kHex8, 8, 3)
EMB_ELEMENT_TRAITS(kHex20, 20, 3)
EMB_ELEMENT_TRAITS(kWedge6, 6, 3)
EMB_ELEMENT_TRAITS(kWedge15, 15, 3)
#undef EMB_ELEMENT_TRAITS

/// Shape functions of the reference element of type T.
template <CellType T>
class ShapeFunctions {
 public:
  static constexpr int kNodes = ElementTraits<T>::kNodes;
  using Values = Eigen::Matrix<double, kNodes, 1>;
  using Gradients = Eigen::Matrix<double, 3, kNodes>;  ///< ∂N_i/∂ξ_d in column i

  /// N_i(ξ) for all nodes i.
  static Values Eval(const Eigen::Vector3d& xi) { return Coefficients() * Basis(xi); }

  /// ∂N_i/∂ξ (3 × kNodes; the third row is zero for surface cells).
  static Gradients EvalGradients(const Eigen::Vector3d& xi) {
    Eigen::Matrix<double, kNodes, 3> dp;
    const auto& m = ElementTraits<T>::kMonomials;
    for (int j = 0; j < kNodes; ++j)
      for (int d = 0; d < 3; ++d) {
        const int e = m[j][d];
        if (e == 0) {
          dp(j, d) = 0.0;
          continue;
        }
        double v = e;
        for (int dd = 0; dd < 3; ++dd) v *= Power(xi[dd], m[j][dd] - (dd == d ? 1 : 0));
        dp(j, d) = v;
      }
    return (Coefficients() * dp).transpose();
  }

  /// Reference coordinates of node i.
  static Eigen::Vector3d Node(int i) {
    const auto& c = ElementTraits<T>::kNodeCoords[i];
    return {c[0], c[1], c[2]};
  }

 private:
  static double Power(double x, int e) {
    double r = 1.0;
    for (int k = 0; k < e; ++k) r *= x;
    return r;
  }
  static Values Basis(const Eigen::Vector3d& xi) {
    Values p;
    const auto& m = ElementTraits<T>::kMonomials;
    for (int j = 0; j < kNodes; ++j)
      p[j] = Power(xi[0], m[j][0]) * Power(xi[1], m[j][1]) * Power(xi[2], m[j][2]);
    return p;
  }
  static const Eigen::Matrix<double, kNodes, kNodes>& Coefficients() {
    static const Eigen::Matrix<double, kNodes, kNodes> A = [] {
      Eigen::Matrix<double, kNodes, kNodes> V;
      for (int k = 0; k < kNodes; ++k) V.row(k) = Basis(Node(k)).transpose();
      return Eigen::Matrix<double, kNodes, kNodes>(V.inverse().transpose());
    }();
    return A;
  }
};

}  // namespace emb
