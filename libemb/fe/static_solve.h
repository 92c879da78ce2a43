#pragma once
/// @file
/// Linear static analysis K u = f with prescribed (Dirichlet) unknowns, by elimination:
///   K_ff u_f = f_f − K_fc u_c,   reactions r_c = K_cf u_f + K_cc u_c − f_c.

#include <vector>

#include "libemb/linalg/sparse_cholesky.h"
#include "libemb/linalg/sparse_types.h"

namespace emb {

struct StaticSolution {
  Eigen::VectorXd u;          ///< all unknowns (prescribed ones included)
  Eigen::VectorXd reactions;  ///< K u − f (nonzero only at prescribed unknowns)
  FactorInfo factor;          ///< factorisation of K_ff; !ok() means K_ff is singular
  double relative_residual{0.0};  ///< ‖K_ff u_f − rhs‖ / ‖rhs‖
  bool ok() const { return factor.ok(); }
};

/// Solves K u = f with u[fixed[k]] = values[k] (values empty → zeros).
/// `fixed` may be in any order but must not repeat an index.
/// @throws InputError on size mismatch, out-of-range or repeated indices.
/// A singular K_ff (model not restrained) is reported in factor, with the failing unknown.
StaticSolution SolveStatic(const SparseMatrix& K, const Eigen::VectorXd& f,
                           std::vector<int> fixed, const Eigen::VectorXd& values = {});

}  // namespace emb
