#pragma once
/// @file
/// Supports of a modal analysis resolved on a mesh, as homogeneous linear constraints on the
/// extended unknowns x = (u, q): u the 3·nodes displacements [m], q the six coordinates
/// (translation [m], small rotation [rad], global axes) of every RBE2 reference node.
///
/// Rows, in this order (libemb/linalg/constraint_elimination.h eliminates them):
///  1. held components (`--fixed`, axis-aligned `--symmetry`): u_{a,i} = 0;
///  2. RBE2 links, one per surface node s and axis i: u_{s,i} − (B_s q)_i = 0 (slave u_{s,i});
///  3. held RBE2 reference components: q_c = 0;
///  4. held RBE3 reference components: (W u_surface)_c = 0, W the averaging operator;
///  5. oblique symmetry planes: n·u_a = 0;
///  6. equations between nodes: Σ a_i u_{N_i,c_i} = 0.
/// The modal problem is then solved on x = T v (ModalOptions::basis = T's u rows).
///
/// Rigid-body modes the supports leave: 6 − rank(C R), R the six rigid motions of x (a
/// reference node moves as a point of the body at p, rotating with it): the count a modal
/// analysis must find at zero frequency (ModalResult::expected_rigid_modes).

#include <string>
#include <vector>

#include "libemb/cms/interface.h"
#include "libemb/cms/support_spec.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/linalg/constraint_elimination.h"

namespace emb {

struct Supports {
  int num_dofs{0};                     ///< n = 3·nodes
  std::vector<Interface> references;   ///< RBE2/RBE3 reference supports, in option order
  std::vector<std::array<bool, 6>> reference_held;
  std::vector<int> reference_column;   ///< first of the six q unknowns of an RBE2 in x; −1 RBE3
  std::vector<LinearConstraint> rows;  ///< C x = 0 (see the file comment for the order)
  std::vector<std::string> row_source; ///< per row: the option (and node) it comes from
  ConstraintElimination elimination;   ///< x = T v
  int num_held_components{0};          ///< rows of kind 1 (distinct held u unknowns)
  int num_redundant_rows{0};           ///< symmetry rows implied by the others (not used)
  int expected_rigid_modes{6};         ///< 6 − rank(C R)
  std::string description;             ///< e.g. "fixed x0:x; rbe3 x1:y,z"; empty = free-free

  int num_unknowns() const { return static_cast<int>(elimination.masters.size()); }
  /// True when the supports only hold unknowns (no couplings): then HeldDofs() is the whole
  /// story and the fast selection path applies.
  bool IsSelection() const;
  std::vector<int> HeldDofs() const;
  /// The first num_dofs rows of T: u = T_u v.
  SparseMatrix DofBasis() const;
  /// `options` with the supports applied (fixed_dofs or basis, expected_rigid_modes).
  ModalOptions Apply(ModalOptions options) const;
};

/// Resolves `specs` on `mesh`.
/// @throws InputError naming the option for: an unknown group (listing those present), a group
///   without nodes, `A&B` with no common node, a symmetry group that is not planar (or not
///   normal to the axis given), a node held by a support and slaved by an RBE2 (hold the
///   reference node's components instead), overlapping or repeated reference groups, an RBE3
///   component or equation implied by the supports before it, an unknown node tag, and
///   supports that leave no unknown free.
Supports BuildSupports(const Mesh& mesh, const SupportSpecs& specs);

/// The largest constraint violation of the modes, max over rows r and modes k of
/// |c_r·x_k| / (Σ_j |c_rj| · ‖x_k‖∞), x_k = T v_k (or the full vectors on the selection path):
/// round-off (~1e-16) when the elimination is right.
double ConstraintResidual(const Supports& supports, const ModalResult& modes);

/// A constraint residual above this is a failed check: 1e8 × double round-off, far above
/// what summing a few hundred terms can lose.
inline constexpr double kConstraintResidualLimit = 1e-8;

}  // namespace emb
