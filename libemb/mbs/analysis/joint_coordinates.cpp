#include "libemb/mbs/analysis/joint_coordinates.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "libemb/mbs/constraints/primitive.h"

namespace emb::mbs {

bool HasJointCoordinate(const ConstraintElement& e, JointCoordinate c) {
  if (e.kind != ElementKind::kJoint) return false;
  if (c == JointCoordinate::kRotation)
    return e.type == JointType::kRevolute || e.type == JointType::kCylindrical;
  return e.type == JointType::kTranslational || e.type == JointType::kCylindrical;
}

Eigen::MatrixXd CalcJointCoordinates(const System& system,
                                     const std::vector<BodyKinematics>& bodies) {
  const auto& elements = system.elements();
  Eigen::MatrixXd x = Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(elements.size()),
                                                kJointCoordinateColumns,
                                                std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const ConstraintElement& e = elements[k];
    const bool rotates = HasJointCoordinate(e, JointCoordinate::kRotation);
    const bool slides = HasJointCoordinate(e, JointCoordinate::kTranslation);
    if (!rotates && !slides) continue;
    const MarkerKinematics I = CalcMarkerKinematics(system, bodies, e.marker_i);
    const MarkerKinematics J = CalcMarkerKinematics(system, bodies, e.marker_j);
    const auto row = static_cast<Eigen::Index>(k);
    if (rotates) {
      const KernelEval g =
          EvalKernel(CoordinateKernel(e.type, JointCoordinate::kRotation, e.name), I, J);
      x(row, kJointAngle) = g.value;
      x(row, kJointAngleRate) = g.rate;
    }
    if (slides) {
      const KernelEval g =
          EvalKernel(CoordinateKernel(e.type, JointCoordinate::kTranslation, e.name), I, J);
      x(row, kJointTravel) = g.value;
      x(row, kJointTravelRate) = g.rate;
    }
  }
  return x;
}

void UnwrapJointAngles(const Eigen::MatrixXd& previous, double t_previous, double t_current,
                       Eigen::MatrixXd* current) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const double dt = t_current - t_previous;
  for (Eigen::Index k = 0; k < current->rows(); ++k) {
    const double theta = (*current)(k, kJointAngle);
    if (!std::isfinite(theta) || !std::isfinite(previous(k, kJointAngle))) continue;
    const double predicted =
        previous(k, kJointAngle) +
        0.5 * (previous(k, kJointAngleRate) + (*current)(k, kJointAngleRate)) * dt;
    if (!std::isfinite(predicted)) continue;
    (*current)(k, kJointAngle) = theta + kTwoPi * std::round((predicted - theta) / kTwoPi);
  }
}

}  // namespace emb::mbs
