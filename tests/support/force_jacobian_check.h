#pragma once
// Central-difference stiffness df/dx and damping df/dv of one force element, to check its
// analytic AddForceJacobian.

#include <Eigen/Dense>

#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs::testing {

struct NumericForceJacobian {
  Eigen::MatrixXd stiffness, damping;
};

// Force element k of `sys` at (q, v, t), perturbations of size h (ApplyDisplacement for x).
inline NumericForceJacobian CentralDifferenceJacobian(const System& sys, int k,
                                                      const Eigen::VectorXd& q,
                                                      const Eigen::VectorXd& v, double t,
                                                      double h, ConstraintWorkspace* ws) {
  const StateLayout& L = sys.layout();
  const ForceElement& fe = *sys.force_elements()[k];
  const int slot = sys.force_angle_slot(k);
  auto forces = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv) {
    const auto bodies = CalcBodyKinematics(sys, qq, vv);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(L.nv());
    fe.AddForces({&sys, &bodies, t, ws, slot}, f);
    return f;
  };
  NumericForceJacobian out{Eigen::MatrixXd(L.nv(), L.nv()), Eigen::MatrixXd(L.nv(), L.nv())};
  for (int j = 0; j < L.nv(); ++j) {
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(L.nv());
    dx[j] = h;
    out.stiffness.col(j) =
        (forces(ApplyDisplacement(sys, q, dx), v) - forces(ApplyDisplacement(sys, q, -dx), v)) /
        (2 * h);
    out.damping.col(j) = (forces(q, v + dx) - forces(q, v - dx)) / (2 * h);
  }
  return out;
}

}  // namespace emb::mbs::testing
