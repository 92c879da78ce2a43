#include "libemb/mbs/dynamics.h"

#include "libemb/mbs/system.h"

namespace emb::mbs {

Eigen::MatrixXd CalcMassMatrix(const System& system) {
  const StateLayout& L = system.layout();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(L.nv(), L.nv());
  for (int b = 1; b < system.num_bodies(); ++b) {
    M.block<3, 3>(L.velocity(b), L.velocity(b)) = system.body(b).mass * Eigen::Matrix3d::Identity();
    M.block<3, 3>(L.angular_velocity(b), L.angular_velocity(b)) = system.body(b).inertia_B;
  }
  return M;
}

Eigen::VectorXd CalcElementForces(const System& system, const std::vector<BodyKinematics>& bodies,
                                  double t, ConstraintWorkspace* workspace) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(system.layout().nv());
  const auto& forces = system.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const ForceContext ctx{&system, &bodies, t, workspace,
                           system.force_angle_slot(static_cast<int>(k))};
    forces[k]->AddForces(ctx, f);
  }
  return f;
}

Eigen::VectorXd CalcGeneralizedForces(const System& system,
                                      const std::vector<BodyKinematics>& bodies, double t,
                                      ConstraintWorkspace* workspace) {
  const StateLayout& L = system.layout();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(L.nv());
  for (int b = 1; b < system.num_bodies(); ++b) {
    const RigidBody& body = system.body(b);
    f.segment<3>(L.velocity(b)) += body.mass * system.gravity();
    const Eigen::Vector3d& w = bodies[b].omega_B;
    f.segment<3>(L.angular_velocity(b)) -= w.cross(body.inertia_B * w);
  }
  if (!system.force_elements().empty()) f += CalcElementForces(system, bodies, t, workspace);
  return f;
}

Energies CalcEnergies(const System& system, const std::vector<BodyKinematics>& bodies, double t,
                      ConstraintWorkspace* workspace) {
  Energies e;
  for (int b = 1; b < system.num_bodies(); ++b) {
    const RigidBody& body = system.body(b);
    const BodyKinematics& k = bodies[b];
    e.kinetic +=
        0.5 * body.mass * k.v_WB.squaredNorm() + 0.5 * k.omega_B.dot(body.inertia_B * k.omega_B);
    e.gravity -= body.mass * system.gravity().dot(k.p_WB);
  }
  const auto& forces = system.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const ForceContext ctx{&system, &bodies, t, workspace,
                           system.force_angle_slot(static_cast<int>(k))};
    e.elastic += forces[k]->CalcPotentialEnergy(ctx);
    e.dissipated_power += forces[k]->CalcDissipatedPower(ctx);
  }
  return e;
}

}  // namespace emb::mbs
