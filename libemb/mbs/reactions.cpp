#include "libemb/mbs/reactions.h"

#include "libemb/mbs/system.h"

namespace emb::mbs {

Eigen::MatrixXd CalcJointReactions(const System& system, const std::vector<BodyKinematics>& bodies,
                                   const Eigen::MatrixXd& C, const Eigen::VectorXd& lambda) {
  const StateLayout& L = system.layout();
  const auto& elements = system.elements();
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(elements.size()), 6);
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const ConstraintElement& e = elements[k];
    if (e.num_equations == 0) continue;
    const MarkerKinematics I = CalcMarkerKinematics(system, bodies, e.marker_i);
    const MarkerKinematics J = CalcMarkerKinematics(system, bodies, e.marker_j);
    const auto lam = lambda.segment(e.first_equation, e.num_equations);
    Eigen::Vector3d F_W = Eigen::Vector3d::Zero(), T_W = Eigen::Vector3d::Zero();
    if (!L.is_ground(I.body)) {
      const auto rows = C.middleRows(e.first_equation, e.num_equations);
      F_W = -rows.middleCols<3>(L.velocity(I.body)).transpose() * lam;
      const Eigen::Vector3d n_B = -rows.middleCols<3>(L.angular_velocity(I.body)).transpose() * lam;
      T_W = I.R_WB * n_B - I.s_W.cross(F_W);
    } else if (!L.is_ground(J.body)) {
      // Marker I on the ground: report the opposite of the load on J's body, moved to I.
      const auto rows = C.middleRows(e.first_equation, e.num_equations);
      const Eigen::Vector3d F_j = -rows.middleCols<3>(L.velocity(J.body)).transpose() * lam;
      const Eigen::Vector3d n_B = -rows.middleCols<3>(L.angular_velocity(J.body)).transpose() * lam;
      const Eigen::Vector3d T_jW = J.R_WB * n_B + (bodies[J.body].p_WB - I.p_WM).cross(F_j);
      F_W = -F_j;
      T_W = -T_jW;
    }
    out.block<1, 3>(k, 0) = (J.R_WM.transpose() * F_W).transpose();
    out.block<1, 3>(k, 3) = (J.R_WM.transpose() * T_W).transpose();
  }
  return out;
}

}  // namespace emb::mbs
