#pragma once
/// @file
/// Element matrices of an isoparametric linear-elastic solid (small strain, isotropic).
///
/// With G = ∂N/∂x = J⁻ᵀ ∂N/∂ξ at a quadrature point (J = Σ_a x_a ⊗ ∂N_a/∂ξ, w its weight),
/// the 3×3 stiffness block between nodes a and b is
///     K_ab = Σ_q w det J [ λ g_a g_bᵀ + μ g_b g_aᵀ + μ (g_a·g_b) I ],
/// which is Bᵀ D B of the textbook written out for isotropic D (fewer flops, no B).
/// The consistent mass is M_ab = m_ab I with m_ab = Σ_q w det J ρ N_a N_b.
/// The Jacobian must be positive at every quadrature point; the smallest det J is returned so
/// that the caller can name an inverted or degenerate element.
///
/// Prestress (geometric stiffness): from nodal displacements U (3 × kNodes), the small-strain
/// Cauchy stress at stiffness-rule point q is σ_q = λ tr(ε) I + 2μ ε, ε = ½(H + Hᵀ), H = U Gᵀ;
/// the initial-stress matrix of a stress field σ is K_σ,ab = s_ab I with
///     s_ab = Σ_q w det J g_aᵀ σ_q g_b      (g_a: column a of G)
/// i.e. ∫ Gᵀ S(σ) G dV with S = blockdiag(σ, σ, σ): the second variation of ∫ σ : E dV with the
/// Green–Lagrange strain, ½ ∫ σ_ij u_k,i u_k,j dV.

#include <Eigen/Core>
#include <Eigen/LU>

#include "libemb/fe/reference_element.h"

namespace emb {

template <CellType T>
class SolidElement {
 public:
  static constexpr int kNodes = ElementTraits<T>::kNodes;
  static constexpr int kDofs = 3 * kNodes;
  using NodeCoords = Eigen::Matrix<double, 3, kNodes>;
  using Stiffness = Eigen::Matrix<double, kDofs, kDofs>;
  using ScalarMass = Eigen::Matrix<double, kNodes, kNodes>;
  using NodalVectors = Eigen::Matrix<double, 3, kNodes>;

  /// Number of stiffness-rule quadrature points (where stresses live).
  static int NumStressPoints() { return StiffnessData().size; }

  /// Stiffness K_e (kDofs × kDofs, dof 3a+i = component i of node a) of the cell with node
  /// coordinates X [m]; λ, μ [Pa]. Returns min det J over the quadrature points; if it is
  /// ≤ 0 the cell is inverted and K_e must not be used.
  static double CalcStiffness(const NodeCoords& X, double lambda, double mu, Stiffness& K) {
    K.setZero();
    const double min_det = ForEachStiffnessPoint(X, [&](int, double c, const Gradient& G) {
      const Eigen::Matrix<double, kNodes, kNodes> S = c * mu * (G.transpose() * G);
      for (int b = 0; b < kNodes; ++b)
        for (int a = 0; a < kNodes; ++a)
          for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i)
              K(3 * a + i, 3 * b + j) +=
                  c * (lambda * G(i, a) * G(j, b) + mu * G(j, a) * G(i, b)) +
                  (i == j ? S(a, b) : 0.0);
    });
    // Exactly symmetric (the lower triangle mirrored; the products above are not commuted
    // alike for K_ab and K_ba): the assembled K then equals Kᵀ to the last bit, and a product
    // may read its columns as rows without an error of ε‖K‖‖x‖ (extended_product.h).
    K = K.template selfadjointView<Eigen::Lower>();
    return min_det;
  }

  /// Cauchy stress σ_q [Pa] at the NumStressPoints() stiffness-rule points of the cell with
  /// node coordinates X [m] and nodal displacements U [m]; λ, μ [Pa]. `sigma` must hold
  /// NumStressPoints() matrices. Returns min det J (≤ 0: inverted, σ not valid).
  static double CalcStresses(const NodeCoords& X, const NodalVectors& U, double lambda, double mu,
                             Eigen::Matrix3d* sigma) {
    return ForEachStiffnessPoint(X, [&](int p, double, const Gradient& G) {
      const Eigen::Matrix3d H = U * G.transpose();  // H_ij = ∂u_i/∂x_j
      const Eigen::Matrix3d eps = 0.5 * (H + H.transpose());
      sigma[p] = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2.0 * mu * eps;
    });
  }

  /// Scalar geometric (initial-stress) stiffness s_ab = Σ_q w det J g_aᵀ σ_q g_b [N/m] of the
  /// stresses σ_q at the stiffness-rule points (as CalcStresses returns them); the 3-D matrix
  /// is s ⊗ I₃. Returns min det J.
  static double CalcGeometricStiffness(const NodeCoords& X, const Eigen::Matrix3d* sigma,
                                       ScalarMass& s) {
    s.setZero();
    const double min_det = ForEachStiffnessPoint(X, [&](int p, double dv, const Gradient& G) {
      s.noalias() += dv * (G.transpose() * (sigma[p] * G));
    });
    s = s.template selfadjointView<Eigen::Lower>();  // exactly symmetric, as CalcStiffness
    return min_det;
  }

  /// Scalar consistent mass m_ab (kNodes × kNodes) with density ρ [kg/m³]; the 3-D mass is
  /// m ⊗ I₃. Returns min det J as CalcStiffness does.
  static double CalcScalarMass(const NodeCoords& X, double rho, ScalarMass& m) {
    const auto& q = MassData();
    m.setZero();
    double min_det = std::numeric_limits<double>::infinity();
    for (int p = 0; p < q.size; ++p) {
      const double det = (X * q.dN[p].transpose()).determinant();
      min_det = std::min(min_det, det);
      if (!(det > 0.0)) return min_det;
      m.template selfadjointView<Eigen::Lower>().rankUpdate(q.N[p], q.w[p] * det * rho);
    }
    // Exactly symmetric (the lower triangle mirrored): an FE mass matrix is then a ⊗ I₃ with a
    // symmetric a to the last bit, which kronecker_matrix.h needs for its fast product.
    m = m.template selfadjointView<Eigen::Lower>();
    return min_det;
  }

  /// Volume ∫ dV [m³], first moment ∫ x dV [m⁴] and second moment ∫ x xᵀ dV [m⁵] of the
  /// cell, *added* to the outputs (mass rule: exact for straight-sided cells).
  /// Returns min det J over the quadrature points.
  static double AddGeometricMoments(const NodeCoords& X, double& volume, Eigen::Vector3d& first,
                                    Eigen::Matrix3d& second) {
    const auto& q = MassData();
    double min_det = std::numeric_limits<double>::infinity();
    for (int p = 0; p < q.size; ++p) {
      const double det = (X * q.dN[p].transpose()).determinant();
      min_det = std::min(min_det, det);
      const double dv = q.w[p] * det;
      const Eigen::Vector3d x = X * q.N[p];
      volume += dv;
      first += dv * x;
      second += dv * x * x.transpose();
    }
    return min_det;
  }

 private:
  using Gradient = Eigen::Matrix<double, 3, kNodes>;
  // Calls f(p, w det J, G) at every stiffness-rule point p while det J > 0; returns min det J
  // (the first non-positive one stops the loop).
  template <typename F>
  static double ForEachStiffnessPoint(const NodeCoords& X, F&& f) {
    const auto& q = StiffnessData();
    double min_det = std::numeric_limits<double>::infinity();
    for (int p = 0; p < q.size; ++p) {
      const Eigen::Matrix3d J = X * q.dN[p].transpose();  // J_ij = ∂x_i/∂ξ_j
      const double det = J.determinant();
      min_det = std::min(min_det, det);
      if (!(det > 0.0)) return min_det;
      const Gradient G = J.transpose().inverse() * q.dN[p];
      f(p, q.w[p] * det, G);
    }
    return min_det;
  }

  // Shape functions tabulated at the quadrature points, once per type.
  struct Tabulated {
    int size{0};
    std::vector<double> w;
    std::vector<Eigen::Matrix<double, kNodes, 1>> N;
    std::vector<Eigen::Matrix<double, 3, kNodes>> dN;
  };
  static Tabulated Tabulate(const QuadratureRule& rule) {
    Tabulated t;
    t.size = rule.size();
    for (int p = 0; p < rule.size(); ++p) {
      t.w.push_back(rule.weights[p]);
      t.N.push_back(ShapeFunctions<T>::Eval(rule.points[p]));
      t.dN.push_back(ShapeFunctions<T>::EvalGradients(rule.points[p]));
    }
    return t;
  }
  static const Tabulated& StiffnessData() {
    static const Tabulated t = Tabulate(ElementTraits<T>::StiffnessRule());
    return t;
  }
  static const Tabulated& MassData() {
    static const Tabulated t = Tabulate(ElementTraits<T>::MassRule());
    return t;
  }
};

}  // namespace emb
