#include "libemb/beam/tmm_chain.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "libemb/common/error.h"

namespace emb {
namespace {

constexpr const char* kComponentNames[6] = {"u_x", "u_y", "u_z", "theta_x", "theta_y", "theta_z"};

std::vector<int> Components(TmmMotion motion) {
  switch (motion) {
    case TmmMotion::kFull: return {kUx, kUy, kUz, kThetaX, kThetaY, kThetaZ};
    case TmmMotion::kTorsionX: return {kThetaX};
    case TmmMotion::kAxialX: return {kUx};
    case TmmMotion::kBendingXY: return {kUy, kThetaZ};
    case TmmMotion::kBendingXZ: return {kUz, kThetaY};
  }
  return {};
}

// Coupling of a symmetric PSD matrix A (blocks of 6 per node) between the components `in`
// and the others, |A_ij| / √(A_ii A_jj) ≤ 1. Returns the largest and where it is.
struct Coupling {
  double size{0.0};
  int i{0}, j{0};
};
Coupling LargestCoupling(const Eigen::MatrixXd& A, const std::vector<int>& in) {
  Coupling c;
  const int n = static_cast<int>(A.rows());
  for (int i = 0; i < n; ++i) {
    if (std::find(in.begin(), in.end(), i % 6) == in.end()) continue;
    for (int j = 0; j < n; ++j) {
      if (std::find(in.begin(), in.end(), j % 6) != in.end()) continue;
      const double d = std::sqrt(std::abs(A(i, i) * A(j, j)));
      const double v = std::abs(A(i, j));
      const double s = d > 0.0 ? v / d : (v > 0.0 ? 1.0 : 0.0);
      if (s > c.size) c = {s, i, j};
    }
  }
  return c;
}

}  // namespace

const char* Name(TmmMotion motion) {
  switch (motion) {
    case TmmMotion::kFull: return "full";
    case TmmMotion::kTorsionX: return "torsion x";
    case TmmMotion::kAxialX: return "axial x";
    case TmmMotion::kBendingXY: return "bending x-y";
    case TmmMotion::kBendingXZ: return "bending x-z";
  }
  return "?";
}

TmmChain::TmmChain(const BeamModel& model, TmmMotion motion)
    : motion_(motion), num_nodes_(model.num_nodes()), components_(Components(motion)) {
  EMB_THROW_IF(model.num_nodes() == 0,
               "TMM of beam model '" << model.name() << "': expected nodes, got none");
  const int nu = static_cast<int>(components_.size());
  for (int c : components_) states_.push_back(c);
  for (int c : components_) states_.push_back(c + TmmState::kLoad);
  BuildOrder(model);
  if (motion_ != TmmMotion::kFull) CheckDecoupled(model);

  fixed_components_.assign(num_nodes_, {});
  for (const Support& s : model.supports())
    for (int i = 0; i < nu; ++i)
      if (s.fixed[components_[i]] &&
          std::find(fixed_components_[s.node].begin(), fixed_components_[s.node].end(), i) ==
              fixed_components_[s.node].end())
        fixed_components_[s.node].push_back(i);
  for (auto& f : fixed_components_) std::sort(f.begin(), f.end());
  num_unknowns_ = nu - static_cast<int>(fixed_components_[node_order_.front()].size());
  for (const auto& f : fixed_components_) num_unknowns_ += static_cast<int>(f.size());

  BuildSteps(model);
  lumped_ = AssembleBeamSystem(model, BeamMassType::kLumped);
  for (int n : node_order_) {
    std::vector<int> dofs;
    for (int i = 0; i < nu; ++i)
      if (std::find(fixed_components_[n].begin(), fixed_components_[n].end(), i) ==
          fixed_components_[n].end())
        dofs.push_back(BeamModel::Dof(n, static_cast<BeamDof>(components_[i])));
    count_dofs_.push_back(std::move(dofs));
  }
}

void TmmChain::BuildOrder(const BeamModel& model) {
  const int n = model.num_nodes();
  const std::string what = "TMM of beam model '" + model.name() + "'";
  if (model.num_elements() == 0) {
    EMB_THROW_IF(n != 1, what << ": expected one serial chain of elements, got " << n
                              << " nodes and no element");
    node_order_ = {0};
    return;
  }
  std::vector<std::vector<int>> on(n);  // elements at each node
  for (int e = 0; e < model.num_elements(); ++e) {
    on[model.elements()[e].node_a].push_back(e);
    on[model.elements()[e].node_b].push_back(e);
  }
  std::vector<int> ends;
  for (int i = 0; i < n; ++i) {
    const auto& name = model.nodes()[i].name;
    EMB_THROW_IF(on[i].empty(), what << ": node '" << name
                                     << "' is on no element; expected one serial chain");
    if (on[i].size() > 2) {
      std::string list;
      for (int e : on[i]) list += (list.empty() ? "'" : ", '") + model.elements()[e].name + "'";
      EMB_THROW(InputError, what << ": node '" << name << "' joins " << on[i].size()
                                 << " elements (" << list
                                 << "); expected a serial chain (at most 2 per node)");
    }
    if (on[i].size() == 1) ends.push_back(i);
  }
  EMB_THROW_IF(ends.size() != 2, what << ": the elements form a closed loop; expected a "
                                         "serial chain with two end nodes");
  std::vector<char> seen(n, 0);
  int node = ends[0], prev_element = -1;
  while (true) {
    seen[node] = 1;
    node_order_.push_back(node);
    int next_element = -1;
    for (int e : on[node])
      if (e != prev_element) next_element = e;
    if (next_element < 0) break;
    const BeamElement& el = model.elements()[next_element];
    const int next = el.node_a == node ? el.node_b : el.node_a;
    EMB_THROW_IF(seen[next], what << ": element '" << el.name
                                  << "' closes a loop; expected a serial chain");
    prev_element = next_element;
    node = next;
  }
  for (int i = 0; i < n; ++i)
    EMB_THROW_IF(!seen[i], what << ": node '" << model.nodes()[i].name
                                << "' is not connected to node '"
                                << model.nodes()[ends[0]].name
                                << "'; expected one serial chain");
}

void TmmChain::CheckDecoupled(const BeamModel& model) const {
  // Round-off of frames and offsets on an axis-aligned model stays far below this; any real
  // coupling (an offset, an off-axis centre of mass, a skew beam) is far above.
  constexpr double kCouplingTol = 1e-9;
  auto check = [&](const Eigen::MatrixXd& A, const std::string& where, const char* matrix,
                   const std::vector<int>& nodes) {
    const Coupling c = LargestCoupling(A, components_);
    if (c.size <= kCouplingTol) return;
    EMB_THROW(InputError,
              "TMM " << Name(motion_) << " of beam model '" << model.name() << "': " << where
                     << " couples " << kComponentNames[c.i % 6] << " (node '"
                     << model.nodes()[nodes[c.i / 6]].name << "') with "
                     << kComponentNames[c.j % 6] << " (node '"
                     << model.nodes()[nodes[c.j / 6]].name << "') in its " << matrix
                     << " (normalised coupling " << c.size << "); expected a model that "
                     << "does not couple these motions to others — use the full TMM");
  };
  for (int e = 0; e < model.num_elements(); ++e) {
    const BeamElement& el = model.elements()[e];
    const std::string where = "element '" + el.name + "'";
    check(CalcElementStiffnessInWorld(model, e), where, "stiffness", {el.node_a, el.node_b});
    check(CalcElementMassInWorld(model, e, BeamMassType::kLumped), where, "lumped mass",
          {el.node_a, el.node_b});
  }
  for (int r = 0; r < static_cast<int>(model.rigid_parts().size()); ++r)
    check(model.RigidPartMass(r), "rigid part '" + model.rigid_parts()[r].name + "'", "mass",
          {model.rigid_parts()[r].node});
}

void TmmChain::AddPoint(const Matrix6d& stiffness, const Matrix6d& mass) {
  Step s;
  s.kind = Step::kPoint;
  s.stiffness = stiffness(components_, components_);
  s.mass = mass(components_, components_);
  steps_.push_back(std::move(s));
}

void TmmChain::AddField(const TransferMatrix& field) {
  Step s;
  s.kind = Step::kField;
  s.field = field(states_, states_);
  steps_.push_back(std::move(s));
}

void TmmChain::BuildSteps(const BeamModel& model) {
  std::vector<Matrix6d> node_stiffness(num_nodes_, Matrix6d::Zero());
  std::vector<Matrix6d> node_mass(num_nodes_, Matrix6d::Zero());
  for (const PointSpring& s : model.springs()) node_stiffness[s.node].diagonal() += s.stiffness;
  for (int r = 0; r < static_cast<int>(model.rigid_parts().size()); ++r)
    node_mass[model.rigid_parts()[r].node] += model.RigidPartMass(r);

  for (size_t k = 0; k < node_order_.size(); ++k) {
    const int node = node_order_[k];
    Step reach;
    reach.node = node;
    steps_.push_back(std::move(reach));
    if (!node_stiffness[node].isZero(0.0) || !node_mass[node].isZero(0.0))
      AddPoint(node_stiffness[node], node_mass[node]);
    if (k + 1 == node_order_.size()) break;

    // The element to the next node, walked from its end at `node`.
    const int next = node_order_[k + 1];
    int e = 0;
    while (!((model.elements()[e].node_a == node && model.elements()[e].node_b == next) ||
             (model.elements()[e].node_b == node && model.elements()[e].node_a == next)))
      ++e;
    const BeamElement& el = model.elements()[e];
    const bool forward = el.node_a == node;
    const Eigen::Vector3d off_left = forward ? el.offset_a_W : el.offset_b_W;
    const Eigen::Vector3d off_right = forward ? el.offset_b_W : el.offset_a_W;
    const Eigen::Vector3d p_left = model.nodes()[node].p_W + off_left;
    const Eigen::Vector3d p_right = model.nodes()[next].p_W + off_right;
    const Eigen::Matrix3d R_WB = CalcBeamFrame(p_left, p_right, el.reference_W, el.name);
    const BeamElementProperties p = model.ElementProperties(e);
    const Matrix6d C_W = RotateBlocks(CalcBeamEndCompliance(p), R_WB);
    // Both ends carry the same lumped mass; a reversed frame flips two axes, which leaves the
    // rotated diagonal unchanged.
    const Matrix6d M_end =
        RotateBlocks(Matrix6d(CalcBeamLumpedMass(p).head<6>().asDiagonal()), R_WB);
    if (!off_left.isZero(0.0)) AddField(CalcRigidTransferMatrix(off_left));
    AddPoint(Matrix6d::Zero(), M_end);
    AddField(CalcFieldTransferMatrix(0.5 * (C_W + C_W.transpose()), p_right - p_left));
    AddPoint(Matrix6d::Zero(), M_end);
    if (!off_right.isZero(0.0)) AddField(CalcRigidTransferMatrix(-off_right));
  }
}

void TmmChain::Propagate(double lambda, Eigen::MatrixXd* B, const Eigen::VectorXd* a,
                         Eigen::MatrixXd* motions) const {
  const int nu = static_cast<int>(components_.size());
  const int n = num_unknowns_;
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(2 * nu, n);
  int col = 0, row = 0;
  const auto& first_fixed = fixed_components_[node_order_.front()];
  for (int i = 0; i < nu; ++i)
    if (std::find(first_fixed.begin(), first_fixed.end(), i) == first_fixed.end())
      Z(i, col++) = 1.0;
  if (B) B->setZero(n, n);
  if (motions) motions->setZero(kBeamNodeDofs, num_nodes_);
  for (const Step& s : steps_) {
    switch (s.kind) {
      case Step::kNode: {
        const bool first = s.node == node_order_.front();
        for (int i : fixed_components_[s.node]) {
          if (!first && B) B->row(row) = Z.row(i);
          if (!first) ++row;
          Z(nu + i, col++) -= 1.0;  // the support's reaction
        }
        if (motions)
          for (int i = 0; i < nu; ++i) (*motions)(components_[i], s.node) = Z.row(i).dot(*a);
        break;
      }
      case Step::kPoint:
        Z.bottomRows(nu) += (s.stiffness - lambda * s.mass) * Z.topRows(nu);
        break;
      case Step::kField:
        Z = (s.field * Z).eval();
        break;
    }
  }
  for (int i = 0; i < nu; ++i) {
    if (B) B->row(row) = Z.row(nu + i);
    ++row;
  }
  EMB_CHECK(row == n && col == n);
}

Eigen::MatrixXd TmmChain::CalcBoundaryMatrix(double lambda) const {
  Eigen::MatrixXd B;
  Propagate(lambda, &B, nullptr, nullptr);
  return B;
}

TmmChain::Scaling TmmChain::CalcScaling(const Eigen::MatrixXd& B) const {
  Scaling s;
  s.row = B.cwiseAbs().rowwise().maxCoeff();
  for (int i = 0; i < s.row.size(); ++i) s.row[i] = s.row[i] > 0.0 ? 1.0 / s.row[i] : 1.0;
  const Eigen::MatrixXd Br = s.row.asDiagonal() * B;
  s.col = Br.cwiseAbs().colwise().maxCoeff().transpose();
  for (int j = 0; j < s.col.size(); ++j) s.col[j] = s.col[j] > 0.0 ? 1.0 / s.col[j] : 1.0;
  return s;
}

double TmmChain::CalcScaledDeterminant(double lambda, const Scaling* scaling) const {
  const Eigen::MatrixXd B = CalcBoundaryMatrix(lambda);
  const Scaling own = scaling ? Scaling{} : CalcScaling(B);
  const Scaling& s = scaling ? *scaling : own;
  const Eigen::MatrixXd Bs = s.row.asDiagonal() * B * s.col.asDiagonal();
  return Bs.fullPivLu().determinant();
}

Eigen::MatrixXd TmmChain::CalcNodeMotions(double lambda, const Eigen::VectorXd& a) const {
  EMB_THROW_IF(a.size() != num_unknowns_, "TMM node motions: expected " << num_unknowns_
                                                                       << " unknowns, got "
                                                                       << a.size());
  Eigen::MatrixXd motions;
  Propagate(lambda, nullptr, &a, &motions);
  return motions;
}

int TmmChain::CountEigenvaluesBelow(double lambda) const {
  int count = 0;
  Eigen::MatrixXd S_inv;  // S_{k−1}⁻¹
  const std::vector<int>* prev = nullptr;
  for (size_t k = 0; k < count_dofs_.size(); ++k) {
    const std::vector<int>& dofs = count_dofs_[k];
    if (dofs.empty()) {
      prev = nullptr;
      continue;
    }
    Eigen::MatrixXd S = lumped_.K(dofs, dofs) - lambda * lumped_.M(dofs, dofs);
    if (prev) {
      const Eigen::MatrixXd C = lumped_.K(dofs, *prev) - lambda * lumped_.M(dofs, *prev);
      S -= C * S_inv * C.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (S + S.transpose()));
    Eigen::VectorXd d = es.eigenvalues();
    // A pivot that is exactly zero (λ on an eigenvalue of the leading part of the chain) is
    // counted as positive; any perturbation of λ would decide it one way or the other.
    const double tiny = 1e-300 + 1e-15 * d.cwiseAbs().maxCoeff();
    for (int i = 0; i < d.size(); ++i) {
      if (d[i] < 0.0 && -d[i] > tiny) ++count;
      if (std::abs(d[i]) <= tiny) d[i] = tiny;
    }
    S_inv = es.eigenvectors() * d.cwiseInverse().asDiagonal() * es.eigenvectors().transpose();
    prev = &dofs;
  }
  return count;
}

}  // namespace emb
