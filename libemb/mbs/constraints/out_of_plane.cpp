#include "libemb/mbs/constraints/out_of_plane.h"

#include <algorithm>

#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

std::vector<int> EquationsWithInPlaneTerms(const System& system, const Eigen::VectorXd& q,
                                           double t, const std::vector<int>& equations,
                                           const Eigen::Vector3d& n_W,
                                           ConstraintWorkspace* workspace) {
  std::vector<int> in_plane;
  if (equations.empty()) return in_plane;
  const StateLayout& L = system.layout();
  const auto bodies = CalcBodyKinematics(system, q, Eigen::VectorXd());
  const Eigen::MatrixXd C(CalcConstraints(system, bodies, t, workspace).jacobian);
  double length = 1e-3;  // as AnalyzeDof: the largest marker offset, at least 1 mm
  for (const auto& m : system.markers()) length = std::max(length, m.p_BM.norm());
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n_W * n_W.transpose();
  for (int k : equations) {
    double largest = 0.0, in_plane_part = 0.0;
    for (int b = 1; b < system.num_bodies(); ++b) {
      const Eigen::Vector3d c_v = C.row(k).segment<3>(L.velocity(b)).transpose();
      const Eigen::Vector3d c_w = C.row(k).segment<3>(L.angular_velocity(b)).transpose() / length;
      const Eigen::Vector3d n_B = bodies[b].R_WB.transpose() * n_W;
      largest = std::max({largest, c_v.cwiseAbs().maxCoeff(), c_w.cwiseAbs().maxCoeff()});
      in_plane_part = std::max({in_plane_part, (P * c_v).norm(), std::abs(c_w.dot(n_B))});
    }
    if (in_plane_part > kOutOfPlaneTolerance * largest) in_plane.push_back(k);
  }
  return in_plane;
}

}  // namespace emb::mbs
