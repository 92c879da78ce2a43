#pragma once
/// @file
/// A beam model as a chain of transfer matrices (transfer_matrix.h), the boundary matrix
/// whose determinant vanishes at its natural frequencies, and an exact count of those below
/// a frequency.
///
/// The model must be a serial chain (each node on at most two elements, one path through all
/// nodes). Walking it from one end node to the other, each node contributes a point matrix
/// (springs − λ·rigid parts) and its supports; each element the fields
///   rigid offset (node → elastic end) · point (lumped end mass) · elastic field (C_W)
///   · point (lumped end mass) · rigid offset (elastic end → next node),
/// so the chain is exactly the beam FE model with the *lumped* mass (BeamMassType::kLumped).
///
/// Boundary matrix B(λ). Unknowns a: the free motions of the first node and one reaction per
/// supported unknown. The state is propagated as z = Z(λ) a. Conditions: every supported
/// unknown beyond the first node is zero, and the loads after the last node are zero. B is
/// square, its entries are polynomials in λ (massless fields), so det B has no poles and its
/// roots, with their multiplicities, are the eigenvalues of the lumped FE model.
///
/// Count (Sturm / Wittrick–Williams). K − λM of the same lumped model is block tridiagonal
/// along the chain; its block LDLᵀ (S_0 = D_00, S_k = D_kk − D_k,k−1 S_{k−1}⁻¹ D_k−1,k) has as
/// many negative eigenvalues in its pivots S_k as the pencil has eigenvalues below λ
/// (Sylvester's law of inertia). A multiple root shows up as a jump of the count by its
/// multiplicity, which no sign change of det B can show.
///
/// Motion sets (TmmMotion): the full 12-state vector, or a subset of a model that does not
/// couple it to the rest (checked): torsion about x (θ_x, M_x: Holzer), axial (u_x, F_x),
/// bending in the x–y plane (u_y, θ_z, F_y, M_z) or x–z plane (u_z, θ_y, F_z, M_y)
/// (Myklestad–Prohl).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/transfer_matrix.h"

namespace emb {

enum class TmmMotion {
  kFull,       ///< all 12 states
  kTorsionX,   ///< θ_x, M_x
  kAxialX,     ///< u_x, F_x
  kBendingXY,  ///< u_y, θ_z, F_y, M_z
  kBendingXZ,  ///< u_z, θ_y, F_z, M_y
};

/// "full", "torsion x", "axial x", "bending x-y", "bending x-z".
const char* Name(TmmMotion motion);

class TmmChain {
 public:
  /// @throws InputError naming the node or element if the model is not one serial chain, and
  ///         naming the coupling (node or element, components, size) if a subset motion is
  ///         asked of a model that couples it to other motions.
  TmmChain(const BeamModel& model, TmmMotion motion);

  TmmMotion motion() const { return motion_; }
  /// Nodes from one end of the chain to the other.
  const std::vector<int>& node_order() const { return node_order_; }
  /// The node components (BeamDof) of the motion set, ascending.
  const std::vector<int>& components() const { return components_; }
  /// Size of the boundary matrix.
  int num_unknowns() const { return num_unknowns_; }
  /// The lumped FE model the chain is equivalent to.
  const BeamSystem& lumped_system() const { return lumped_; }

  /// B(λ), num_unknowns() square. Cost O(steps · |states|² · num_unknowns).
  Eigen::MatrixXd CalcBoundaryMatrix(double lambda) const;

  /// Row and column scales (reciprocal max-abs) of a boundary matrix.
  struct Scaling {
    Eigen::VectorXd row, col;
  };
  /// Scaling of B(λ); a zero row or column is given scale 1.
  Scaling CalcScaling(const Eigen::MatrixXd& B) const;
  /// det(diag(row) B(λ) diag(col)) with `scaling` (or B(λ)'s own when null). The scales are
  /// positive, so the sign and the roots are those of det B; a fixed scaling keeps it a
  /// polynomial in λ (smooth for root refinement).
  double CalcScaledDeterminant(double lambda, const Scaling* scaling = nullptr) const;

  /// Node motions (6 × num_nodes, W; zero outside the motion set) for unknowns `a` at λ.
  Eigen::MatrixXd CalcNodeMotions(double lambda, const Eigen::VectorXd& a) const;

  /// Number of eigenvalues of the lumped FE model on the motion set below λ (see the file
  /// comment). Cost O(nodes · 6³).
  int CountEigenvaluesBelow(double lambda) const;

 private:
  // One step of the chain, its matrices already restricted to the motion set.
  struct Step {
    enum Kind { kNode, kPoint, kField } kind{kNode};
    int node{-1};                 // kNode: the node reached
    Eigen::MatrixXd stiffness;    // kPoint: K_p on the set's components (W)
    Eigen::MatrixXd mass;         // kPoint: M_p on the set's components (W)
    Eigen::MatrixXd field;        // kField: the transfer matrix on the set's states
  };
  void BuildOrder(const BeamModel& model);
  void BuildSteps(const BeamModel& model);
  void CheckDecoupled(const BeamModel& model) const;
  void AddPoint(const Matrix6d& stiffness, const Matrix6d& mass);
  void AddField(const TransferMatrix& field);
  // Runs the chain; fills B (if not null) and the node motions for `a` (if not null).
  void Propagate(double lambda, Eigen::MatrixXd* B, const Eigen::VectorXd* a,
                 Eigen::MatrixXd* motions) const;

  TmmMotion motion_;
  int num_nodes_{0};
  std::vector<int> node_order_;
  std::vector<int> components_;  // motion components (0..5)
  std::vector<int> states_;      // components_ then components_ + 6
  std::vector<std::vector<int>> fixed_components_;  // per node: supported components in set
  std::vector<Step> steps_;
  int num_unknowns_{0};
  BeamSystem lumped_;
  std::vector<std::vector<int>> count_dofs_;  // per chain position: free unknowns in the set
};

}  // namespace emb
