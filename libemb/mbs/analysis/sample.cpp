// MakeSample: the output of one instant of any analysis (analysis.h).
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/analysis/joint_coordinates.h"
#include "libemb/mbs/constraints/reactions.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {

Sample MakeSample(const System& system, double t, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                  const Eigen::VectorXd& lambda, ConstraintWorkspace* workspace,
                  const Eigen::VectorXd* z) {
  Sample s;
  s.t = t;
  s.q = q;
  s.v = v;
  s.vdot = vdot;
  s.lambda = lambda;
  const auto bodies = CalcBodyKinematics(system, q, v);
  std::vector<MarkerKinematics> markers;
  CalcAllMarkerKinematics(system, bodies, &markers);
  ConstraintEval c;
  CalcConstraints(system, markers, t, workspace, &c);
  s.reactions = CalcJointReactions(system, bodies, lambda);
  const auto& forces = system.force_elements();
  s.force_loads.setConstant(static_cast<Eigen::Index>(forces.size()), 6,
                            std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < forces.size(); ++k) {
    ForceContext ctx{&system, &bodies, t, workspace, system.force_angle_slot(static_cast<int>(k))};
    ctx.markers = &markers;
    // The rates are not needed for a load; the states are (a film's fill, a deflection).
    const int offset = system.force_state_offset(static_cast<int>(k));
    const Eigen::VectorXd no_rates = Eigen::VectorXd::Zero(offset >= 0 && z ? z->size() : 0);
    if (offset >= 0 && z != nullptr) ctx.z = z->data() + offset, ctx.z_dot = no_rates.data() + offset;
    Eigen::Matrix<double, 6, 1> load;
    if (forces[k]->CalcLoad(ctx, &load)) s.force_loads.row(static_cast<Eigen::Index>(k)) = load;
    const int n_out = static_cast<int>(forces[k]->outputs().size());
    if (n_out == 0) continue;
    Eigen::VectorXd out(n_out);
    if (!forces[k]->CalcOutputs(ctx, out)) out.setConstant(std::numeric_limits<double>::quiet_NaN());
    s.force_outputs.conservativeResize(s.force_outputs.size() + n_out);
    s.force_outputs.tail(n_out) = out;
  }
  const auto& sensors = system.sensors();
  s.sensors.resize(static_cast<Eigen::Index>(sensors.size()), 6);
  for (std::size_t k = 0; k < sensors.size(); ++k) {
    const MarkerKinematics& I = markers[sensors[k].marker_i];
    const MarkerKinematics& J = markers[sensors[k].marker_j];
    s.sensors.row(static_cast<Eigen::Index>(k)) << (J.R_WM.transpose() * (I.p_WM - J.p_WM)).transpose(),
        RotationVectorFromRotation(J.R_WM.transpose() * I.R_WM).transpose();
  }
  s.joints = CalcJointCoordinates(system, bodies);
  s.probes.resize(system.num_probe_channels());
  int offset = 0;
  for (const auto& probe : system.probes()) {
    probe->Eval(system, bodies, vdot, s.probes.segment(offset, probe->num_channels()));
    offset += probe->num_channels();
  }
  s.energies = CalcEnergies(system, bodies, t, workspace, z);
  if (c.phi.size()) {
    s.position_residual = c.phi.cwiseAbs().maxCoeff();
    s.velocity_residual = (c.jacobian * v + c.phi_t).cwiseAbs().maxCoeff();
  }
  return s;
}


}  // namespace emb::mbs
