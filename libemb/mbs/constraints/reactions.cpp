#include "libemb/mbs/constraints/reactions.h"

#include "libemb/mbs/constraints/primitive.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

Eigen::MatrixXd CalcJointReactions(const System& system, const std::vector<BodyKinematics>& bodies,
                                   const Eigen::VectorXd& lambda) {
  const StateLayout& L = system.layout();
  const auto& ports = system.reaction_ports();
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(ports.size()), 6);
  std::vector<MarkerKinematics> markers;
  CalcAllMarkerKinematics(system, bodies, &markers);
  for (std::size_t p = 0; p < ports.size(); ++p) {
    const ReactionPort& port = ports[p];
    const ConstraintElement& e = system.elements()[port.element];
    if (e.num_equations == 0) continue;
    const MarkerKinematics& I = markers[port.marker_i];
    const MarkerKinematics& J = markers[port.marker_j];
    // Generalised loads of this term of the element's equations on the bodies of I and J.
    Eigen::Matrix<double, 6, 1> Q_i = Eigen::Matrix<double, 6, 1>::Zero(), Q_j = Q_i;
    for (int k = e.first_equation; k < e.first_equation + e.num_equations; ++k) {
      const ScalarEquation& eq = system.equations()[k];
      if (port.term >= eq.num_terms) continue;
      const KernelEval g = EvalKernel(eq.kernel[port.term], I, J);
      Q_i -= lambda[k] * eq.coeff[port.term] * g.d_i.transpose();
      Q_j -= lambda[k] * eq.coeff[port.term] * g.d_j.transpose();
    }
    Eigen::Vector3d F_W = Eigen::Vector3d::Zero(), T_W = Eigen::Vector3d::Zero();
    if (!L.is_ground(I.body)) {
      F_W = Q_i.head<3>();
      T_W = I.R_WB * Q_i.tail<3>() - I.s_W.cross(F_W);
    } else if (!L.is_ground(J.body)) {
      const Eigen::Vector3d F_j = Q_j.head<3>();
      const Eigen::Vector3d T_jW = J.R_WB * Q_j.tail<3>() + (bodies[J.body].p_WB - I.p_WM).cross(F_j);
      F_W = -F_j;
      T_W = -T_jW;
    }
    out.block<1, 3>(p, 0) = (J.R_WM.transpose() * F_W).transpose();
    out.block<1, 3>(p, 3) = (J.R_WM.transpose() * T_W).transpose();
  }
  return out;
}

}  // namespace emb::mbs
