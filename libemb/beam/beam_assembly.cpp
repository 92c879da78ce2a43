#include "libemb/beam/beam_assembly.h"

#include "libemb/common/error.h"

namespace emb {
namespace {

// E = diag(Γ(o_a), Γ(o_b)): node unknowns → elastic-end unknowns.
Matrix12d OffsetTransfer(const BeamElement& el) {
  Matrix12d E = Matrix12d::Zero();
  E.topLeftCorner<6, 6>() = CalcRigidTransfer(el.offset_a_W);
  E.bottomRightCorner<6, 6>() = CalcRigidTransfer(el.offset_b_W);
  return E;
}

Matrix12d ToNodesInWorld(const BeamModel& model, int e, const Matrix12d& A_B) {
  const Matrix12d A_W = RotateBlocks(A_B, model.ElementFrame(e));
  const Matrix12d E = OffsetTransfer(model.elements()[e]);
  const Matrix12d A = E.transpose() * A_W * E;
  return 0.5 * (A + A.transpose());
}

void ScatterElement(const BeamElement& el, const Matrix12d& A, Eigen::MatrixXd& out) {
  const int base[2] = {BeamModel::Dof(el.node_a, kUx), BeamModel::Dof(el.node_b, kUx)};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      out.block<6, 6>(base[i], base[j]) += A.block<6, 6>(6 * i, 6 * j);
}

}  // namespace

const char* Name(BeamMassType type) {
  return type == BeamMassType::kConsistent ? "consistent" : "lumped";
}

Matrix12d CalcElementStiffnessInWorld(const BeamModel& model, int e) {
  return ToNodesInWorld(model, e, CalcBeamStiffness(model.ElementProperties(e)));
}

Matrix12d CalcElementMassInWorld(const BeamModel& model, int e, BeamMassType mass_type) {
  const BeamElementProperties p = model.ElementProperties(e);
  const Matrix12d M_B = mass_type == BeamMassType::kConsistent
                            ? CalcBeamConsistentMass(p)
                            : Matrix12d(CalcBeamLumpedMass(p).asDiagonal());
  return ToNodesInWorld(model, e, M_B);
}

BeamSystem AssembleBeamSystem(const BeamModel& model, BeamMassType mass_type) {
  EMB_THROW_IF(model.num_nodes() == 0,
               "beam model '" << model.name() << "': expected at least one node, got none");
  const int n = model.num_dofs();
  BeamSystem sys;
  sys.mass_type = mass_type;
  sys.stiffness_damping = model.stiffness_damping();
  sys.K = Eigen::MatrixXd::Zero(n, n);
  sys.M = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e < model.num_elements(); ++e) {
    const BeamElement& el = model.elements()[e];
    ScatterElement(el, CalcElementStiffnessInWorld(model, e), sys.K);
    ScatterElement(el, CalcElementMassInWorld(model, e, mass_type), sys.M);
  }
  sys.D = model.stiffness_damping() * sys.K;
  for (int r = 0; r < static_cast<int>(model.rigid_parts().size()); ++r) {
    const int base = BeamModel::Dof(model.rigid_parts()[r].node, kUx);
    sys.M.block<6, 6>(base, base) += model.RigidPartMass(r);
  }
  for (const PointSpring& s : model.springs()) {
    const int base = BeamModel::Dof(s.node, kUx);
    sys.K.block<6, 6>(base, base).diagonal() += s.stiffness;
  }
  sys.fixed_dofs = model.FixedDofs();
  std::vector<char> fixed(n, 0);
  for (int d : sys.fixed_dofs) fixed[d] = 1;
  for (int d = 0; d < n; ++d)
    if (!fixed[d]) sys.free_dofs.push_back(d);
  return sys;
}

Eigen::MatrixXd CalcRigidBodyModes(const BeamModel& model) {
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Zero(model.num_dofs(), 6);
  for (int i = 0; i < model.num_nodes(); ++i) {
    // Γ(p_Wi) carries the motion of W's origin to node i.
    Phi.block<6, 6>(BeamModel::Dof(i, kUx), 0) = CalcRigidTransfer(model.nodes()[i].p_W);
  }
  return Phi;
}

MassProperties CalcRigidBodyMassProperties(const BeamModel& model, const Eigen::MatrixXd& M) {
  EMB_THROW_IF(M.rows() != model.num_dofs() || M.cols() != model.num_dofs(),
               "rigid-body mass of beam model '" << model.name() << "': expected a "
                                                 << model.num_dofs() << "x" << model.num_dofs()
                                                 << " mass matrix, got " << M.rows() << "x"
                                                 << M.cols());
  const Eigen::MatrixXd Phi = CalcRigidBodyModes(model);
  return MassPropertiesFromRigidMass(Phi.transpose() * M * Phi);
}

}  // namespace emb
