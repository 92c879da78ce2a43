#pragma once
/// @file
/// Degrees of freedom and constraint bookkeeping (seed eq. 1.25 and the text around it):
///  - the Gruebler-Kutzbach count nDOF = 6 (n - 1) - sum C, n parts including the ground;
///  - the true DOF = 6 (n - 1) - rank(C) from the singular values of the constraint
///    Jacobian C at the assembled configuration;
///  - redundant (repeat) equations, found in element order: equation k is redundant when
///    its Jacobian row lies in the span of the rows of the non-redundant equations before
///    it (Gram-Schmidt with re-orthogonalisation). So the later joint is named, with the
///    primitive equation, e.g. "revolute 'D': parallel z_I.x_J".
/// Rows are compared with rotation columns scaled by a characteristic length (the largest
/// marker offset) so metres and radians weigh alike.

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace emb::mbs {

class System;
class ConstraintWorkspace;

struct DofReport {
  int num_parts{0};                          ///< n of eq. (1.25), including the ground
  int num_equations{0};                      ///< sum C of eq. (1.25)
  int gruebler_dof{0};                       ///< 6 (n - 1) - sum C
  int rank{0};                               ///< numerical rank of C
  int true_dof{0};                           ///< 6 (n - 1) - rank
  double rank_tolerance{0.0};                ///< relative singular-value threshold used
  double smallest_kept_singular_value{0.0};  ///< relative to the largest
  std::vector<int> redundant;                ///< equation indices
  std::vector<std::string> redundant_names;  ///< System::EquationName of each
  /// One line per constraint element: name, kind/type, equation count.
  struct Element {
    std::string name, type;
    int count{0};
  };
  std::vector<Element> elements;
};

/// Relative singular-value threshold for the rank of C: well above round-off of O(1)
/// entries (1e-16 * sqrt(m nv)), well below any geometric near-degeneracy we model.
inline constexpr double kRankTolerance = 1e-9;

/// The DOF report at configuration q (normally assembled) and time t.
DofReport AnalyzeDof(const System& system, const Eigen::VectorXd& q, double t,
                     ConstraintWorkspace* workspace, double rank_tolerance = kRankTolerance);

}  // namespace emb::mbs
