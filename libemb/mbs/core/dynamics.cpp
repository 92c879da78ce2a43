#include "libemb/mbs/core/dynamics.h"

#include "libemb/mbs/core/system.h"

namespace emb::mbs {

FlexibleTerms CalcBodyFlexibleTerms(const System& system, const BodyKinematics& k, int b,
                                    const Eigen::VectorXd* vdot, bool with_derivatives,
                                    const Eigen::VectorXd* accel) {
  const RigidBody& body = system.body(b);
  const StateLayout& L = system.layout();
  Eigen::Vector3d a_B = -k.R_WB.transpose() * system.gravity();
  if (vdot != nullptr && vdot->size())
    a_B += k.R_WB.transpose() * vdot->segment<3>(L.velocity(b));
  return CalcFlexibleTerms(*body.elastic, k.p_WB, k.R_WB, k.v_WB, k.omega_B, k.eta, k.eta_dot,
                           system.gravity(), a_B, with_derivatives, accel);
}

namespace {

// Scatters a body's (6 + ne) vector or block into the global v-ordering.
void AddBodyVector(const StateLayout& L, int b, const Eigen::VectorXd& x, Eigen::VectorXd* out) {
  out->segment<6>(L.velocity(b)) += x.head<6>();
  const int ne = L.num_elastic(b);
  if (ne) out->segment(L.elastic_v(b), ne) += x.tail(ne);
}

}  // namespace

Eigen::MatrixXd CalcMassMatrix(const System& system, const std::vector<BodyKinematics>& bodies) {
  const StateLayout& L = system.layout();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(L.nv(), L.nv());
  for (int b = 1; b < system.num_bodies(); ++b) {
    if (L.num_elastic(b)) {
      const FlexibleTerms t = CalcBodyFlexibleTerms(system, bodies[b], b, nullptr, false);
      ForEachBodySubBlock(L, b, b, [&](int r, int c, int i0, int j0, int nr, int nc) {
        M.block(r, c, nr, nc) += t.mass.block(i0, j0, nr, nc);
      });
      continue;
    }
    M.block<3, 3>(L.velocity(b), L.velocity(b)) = system.body(b).mass * Eigen::Matrix3d::Identity();
    M.block<3, 3>(L.angular_velocity(b), L.angular_velocity(b)) = system.body(b).inertia_B;
  }
  return M;
}

Eigen::VectorXd CalcElementForces(const System& system, const std::vector<BodyKinematics>& bodies,
                                  double t, ConstraintWorkspace* workspace) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(system.layout().nv());
  std::vector<MarkerKinematics> markers;
  CalcAllMarkerKinematics(system, bodies, &markers);
  AddElementForces(system, bodies, markers, t, workspace, f);
  return f;
}

void AddElementForces(const System& system, const std::vector<BodyKinematics>& bodies,
                      const std::vector<MarkerKinematics>& markers, double t,
                      ConstraintWorkspace* workspace, Eigen::Ref<Eigen::VectorXd> f,
                      DomainFailure* failure, const double* z, const double* z_dot) {
  const auto& forces = system.force_elements();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    ForceContext ctx{&system, &bodies, t, workspace, system.force_angle_slot(static_cast<int>(k))};
    ctx.markers = &markers;
    ctx.failure = failure;
    const int offset = system.force_state_offset(static_cast<int>(k));
    if (z != nullptr && offset >= 0) ctx.z = z + offset, ctx.z_dot = z_dot + offset;
    forces[k]->AddForces(ctx, f);
  }
}

Eigen::VectorXd CalcGeneralizedForces(const System& system,
                                      const std::vector<BodyKinematics>& bodies, double t,
                                      ConstraintWorkspace* workspace, const Eigen::VectorXd* vdot) {
  const StateLayout& L = system.layout();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(L.nv());
  for (int b = 1; b < system.num_bodies(); ++b) {
    if (L.num_elastic(b)) {
      AddBodyVector(L, b, CalcBodyFlexibleTerms(system, bodies[b], b, vdot, false).force, &f);
      continue;
    }
    const RigidBody& body = system.body(b);
    f.segment<3>(L.velocity(b)) += body.mass * system.gravity();
    const Eigen::Vector3d& w = bodies[b].omega_B;
    f.segment<3>(L.angular_velocity(b)) -= w.cross(body.inertia_B * w);
  }
  if (!system.force_elements().empty()) f += CalcElementForces(system, bodies, t, workspace);
  return f;
}

Energies CalcEnergies(const System& system, const std::vector<BodyKinematics>& bodies, double t,
                      ConstraintWorkspace* workspace, const Eigen::VectorXd* z) {
  Energies e;
  const StateLayout& L = system.layout();
  for (int b = 1; b < system.num_bodies(); ++b) {
    const RigidBody& body = system.body(b);
    const BodyKinematics& k = bodies[b];
    if (L.num_elastic(b)) {
      const FlexibleTerms ft = CalcBodyFlexibleTerms(system, k, b, nullptr, false);
      e.kinetic += ft.kinetic_energy;
      e.gravity += ft.gravity_energy;
      e.elastic += ft.elastic_energy;
      e.dissipated_power += ft.dissipated_power;
      continue;
    }
    e.kinetic +=
        0.5 * body.mass * k.v_WB.squaredNorm() + 0.5 * k.omega_B.dot(body.inertia_B * k.omega_B);
    e.gravity -= body.mass * system.gravity().dot(k.p_WB);
  }
  const auto& forces = system.force_elements();
  std::vector<MarkerKinematics> markers;
  if (!forces.empty()) CalcAllMarkerKinematics(system, bodies, &markers);
  // The states' rates do not enter an energy or a power (a film's fill, a deflection do).
  const Eigen::VectorXd no_rates = Eigen::VectorXd::Zero(z ? z->size() : 0);
  for (std::size_t k = 0; k < forces.size(); ++k) {
    ForceContext ctx{&system, &bodies, t, workspace, system.force_angle_slot(static_cast<int>(k))};
    ctx.markers = &markers;
    const int offset = system.force_state_offset(static_cast<int>(k));
    if (offset >= 0 && z != nullptr) ctx.z = z->data() + offset, ctx.z_dot = no_rates.data() + offset;
    e.elastic += forces[k]->CalcPotentialEnergy(ctx);
    e.dissipated_power += forces[k]->CalcDissipatedPower(ctx);
  }
  return e;
}

}  // namespace emb::mbs
