#pragma once
/// @file
/// Homogeneous linear constraints C x = 0 on n unknowns, eliminated master–slave style: each
/// independent row makes one unknown (its slave) a combination of the others, so that
///     x = T v,   C T = 0,
/// with v the remaining (master) unknowns. A generalized eigenproblem K x = λ M x under the
/// constraints becomes (Tᵀ K T) v = λ (Tᵀ M T) v, symmetric, positive semi-definite, with no
/// multipliers (so it stays factorable by Cholesky).
///
/// Rows are processed in order. Each is first rewritten in terms of the current masters (the
/// slaves chosen before it are substituted); its slave is then its preferred unknown if that
/// survived with at least kPreferredPivotRatio of the largest coefficient, else the unknown
/// with the largest coefficient (partial pivoting). A row whose coefficients all cancel, to
/// `tolerance` of the sum of the magnitudes that were added together, is a linear combination
/// of the rows before it: it is not used and is listed in `dependent_rows`.
/// Cost: O(Σ terms of the substituted rows); a row over a whole surface (an RBE3 average) makes
/// its slave depend on every unknown of that surface, which fills Tᵀ K T over the surface.

#include <string>
#include <utility>
#include <vector>

#include "libemb/linalg/sparse_types.h"

namespace emb {

/// One row Σ_k a_k x_{j_k} = 0.
struct LinearConstraint {
  std::vector<std::pair<int, double>> terms;  ///< (unknown j, coefficient a); j repeated adds
  int preferred_slave{-1};                    ///< unknown to eliminate if possible, or −1
};

/// A preferred slave is used while its coefficient is at least this fraction of the row's
/// largest (a rigid link u_s − B_s q has 1 on u_s; lever arms in B_s may exceed 1).
inline constexpr double kPreferredPivotRatio = 1e-3;

struct ConstraintElimination {
  SparseMatrix T;                   ///< n × m, x = T v; T(masters[k], k) = 1
  std::vector<int> masters;         ///< the m unknowns kept, ascending
  std::vector<int> slaves;          ///< eliminated unknowns, ascending
  std::vector<int> dependent_rows;  ///< rows that were combinations of earlier rows (unused)
  int num_unknowns() const { return static_cast<int>(T.rows()); }
};

/// Eliminates `rows` on `n` unknowns. `tolerance` is relative (see the file comment).
/// @throws InputError if a row names an unknown outside [0, n) or has a non-finite coefficient.
ConstraintElimination EliminateConstraints(int n, const std::vector<LinearConstraint>& rows,
                                           double tolerance = 1e-10);

}  // namespace emb
