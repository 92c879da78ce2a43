#include "libemb/mbs/constraints/dof_analysis.h"

#include <algorithm>

#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

DofReport AnalyzeDof(const System& system, const Eigen::VectorXd& q, double t,
                     ConstraintWorkspace* workspace, double rank_tolerance) {
  DofReport r;
  const StateLayout& L = system.layout();
  r.num_parts = system.num_bodies();
  r.num_equations = system.num_equations();
  r.gruebler_dof = 6 * (r.num_parts - 1) - r.num_equations;
  r.rank_tolerance = rank_tolerance;
  for (const auto& e : system.elements()) {
    std::string type = e.kind == ElementKind::kJoint    ? Name(e.type)
                       : e.kind == ElementKind::kMotion ? "motion"
                                                        : "coupler";
    r.elements.push_back({e.name, type, e.num_equations});
  }
  if (r.num_equations == 0 || L.num_moving() == 0) {
    r.true_dof = 6 * (r.num_parts - 1);
    return r;
  }
  const auto bodies = CalcBodyKinematics(system, q, Eigen::VectorXd());
  // The rigid-body columns only: modal coordinates of flexible bodies are extra freedoms
  // that the joints never remove (they deform the body instead).
  Eigen::MatrixXd C = Eigen::MatrixXd(CalcConstraints(system, bodies, t, workspace).jacobian)
                          .leftCols(StateLayout::kVPerBody * L.num_moving());
  // Characteristic length: the largest marker offset from its body's CM (at least 1 mm).
  double length = 1e-3;
  for (const auto& m : system.markers()) length = std::max(length, m.p_BM.norm());
  for (int b = 1; b < system.num_bodies(); ++b) C.middleCols<3>(L.angular_velocity(b)) /= length;

  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(C);
  const Eigen::VectorXd& s = svd.singularValues();
  const double smax = s.size() ? s[0] : 0.0;
  r.rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s[i] > rank_tolerance * smax) {
      ++r.rank;
      r.smallest_kept_singular_value = s[i] / smax;
    }
  r.true_dof = 6 * (r.num_parts - 1) - r.rank;

  // Sequential naming of the redundant equations.
  std::vector<Eigen::VectorXd> basis;
  for (int k = 0; k < r.num_equations; ++k) {
    Eigen::VectorXd row = C.row(k).transpose();
    const double norm0 = row.norm();
    for (int pass = 0; pass < 2; ++pass)
      for (const auto& b : basis) row -= b.dot(row) * b;
    // A row with nothing left beyond round-off of the largest singular value is dependent.
    if (row.norm() <= rank_tolerance * std::max(smax, norm0)) {
      r.redundant.push_back(k);
      r.redundant_names.push_back(system.EquationName(k));
    } else {
      basis.push_back(row / row.norm());
    }
  }
  return r;
}

}  // namespace emb::mbs
