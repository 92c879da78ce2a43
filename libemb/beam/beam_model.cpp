#include "libemb/beam/beam_model.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/common/skew.h"

namespace emb {
namespace {


bool AllFinite(const Eigen::MatrixXd& a) { return a.allFinite(); }

}  // namespace

BeamModel::BeamModel(std::string name, double stiffness_damping)
    : name_(std::move(name)), stiffness_damping_(stiffness_damping) {
  EMB_THROW_IF(!(std::isfinite(stiffness_damping) && stiffness_damping >= 0.0),
               "beam model '" << name_ << "': stiffness damping beta: expected >= 0 s, got "
                              << stiffness_damping);
}

void BeamModel::SetStiffnessDamping(double stiffness_damping) {
  EMB_THROW_IF(!(std::isfinite(stiffness_damping) && stiffness_damping >= 0.0),
               "beam model '" << name_ << "': stiffness damping beta: expected >= 0 s, got "
                              << stiffness_damping);
  stiffness_damping_ = stiffness_damping;
}

void BeamModel::CheckNode(int node, const std::string& what) const {
  EMB_THROW_IF(node < 0 || node >= num_nodes(),
               what << ": node index: expected 0.." << num_nodes() - 1 << ", got " << node);
}

int BeamModel::AddNode(const std::string& name, const Eigen::Vector3d& p_W) {
  EMB_THROW_IF(name.empty(), "beam model '" << name_ << "': node " << num_nodes()
                                            << ": expected a name, got an empty one");
  EMB_THROW_IF(std::any_of(nodes_.begin(), nodes_.end(),
                           [&](const BeamNode& n) { return n.name == name; }),
               "beam model '" << name_ << "': node '" << name << "' is defined twice");
  EMB_THROW_IF(!AllFinite(p_W), "beam node '" << name << "': position: expected finite, got ("
                                              << p_W.transpose() << ")");
  nodes_.push_back({name, p_W});
  return num_nodes() - 1;
}

int BeamModel::AddElement(const BeamElement& e) {
  const std::string what = "beam element '" + e.name + "'";
  CheckNode(e.node_a, what + " end a");
  CheckNode(e.node_b, what + " end b");
  EMB_THROW_IF(e.node_a == e.node_b, what << ": expected two different nodes, got node '"
                                          << nodes_[e.node_a].name << "' at both ends");
  EMB_THROW_IF(!AllFinite(e.offset_a_W) || !AllFinite(e.offset_b_W) || !AllFinite(e.reference_W),
               what << ": offsets and reference vector: expected finite values");
  elements_.push_back(e);
  try {
    const auto [pa, pb] = ElasticEnds(num_elements() - 1);
    const double L = (pb - pa).norm();
    EMB_THROW_IF(!(L > 0.0), what << " between nodes '" << nodes_[e.node_a].name << "' and '"
                                  << nodes_[e.node_b].name
                                  << "': length: expected > 0 m, got " << L << " m");
    MakeBeamElementProperties(L, e.section, e.material, e.shear_deformable, what);
    CalcBeamFrame(pa, pb, e.reference_W, what);
  } catch (...) {
    elements_.pop_back();
    throw;
  }
  return static_cast<int>(elements_.size()) - 1;
}

int BeamModel::AddRigidPart(const RigidPart& part) {
  const std::string what = "rigid part '" + part.name + "'";
  CheckNode(part.node, what);
  EMB_THROW_IF(!(std::isfinite(part.mass) && part.mass > 0.0),
               what << ": mass: expected > 0 kg, got " << part.mass);
  EMB_THROW_IF(!AllFinite(part.p_NC_W) || !AllFinite(part.I_C_W),
               what << ": centre of mass and inertia: expected finite values");
  const Eigen::Matrix3d& I = part.I_C_W;
  const double scale = I.cwiseAbs().maxCoeff();
  EMB_THROW_IF((I - I.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale,
               what << ": inertia about the centre of mass: expected a symmetric matrix");
  const double min_eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues()[0];
  // Round-off of a computed inertia may dip below zero by ~1e-12 of its size.
  EMB_THROW_IF(min_eig < -1e-9 * scale,
               what << ": inertia about the centre of mass: expected positive semi-definite, "
                       "got smallest principal moment "
                    << min_eig << " kg m^2");
  rigid_parts_.push_back(part);
  return static_cast<int>(rigid_parts_.size()) - 1;
}

int BeamModel::AddSpring(const PointSpring& spring) {
  const std::string what = "point spring '" + spring.name + "'";
  CheckNode(spring.node, what);
  for (int i = 0; i < kBeamNodeDofs; ++i)
    EMB_THROW_IF(!(std::isfinite(spring.stiffness[i]) && spring.stiffness[i] >= 0.0),
                 what << ": stiffness " << i << ": expected >= 0, got " << spring.stiffness[i]);
  springs_.push_back(spring);
  return static_cast<int>(springs_.size()) - 1;
}

int BeamModel::AddSupport(const Support& support) {
  const std::string what = "support '" + support.name + "'";
  CheckNode(support.node, what);
  EMB_THROW_IF(std::none_of(support.fixed.begin(), support.fixed.end(), [](bool b) { return b; }),
               what << ": expected at least one fixed unknown, got none");
  supports_.push_back(support);
  return static_cast<int>(supports_.size()) - 1;
}

int BeamModel::FindNode(const std::string& name) const {
  for (int i = 0; i < num_nodes(); ++i)
    if (nodes_[i].name == name) return i;
  std::string some;
  for (int i = 0; i < std::min(num_nodes(), 8); ++i) some += (i ? ", " : "") + nodes_[i].name;
  EMB_THROW(InputError, "beam model '" << name_ << "' has no node '" << name
                                       << "'; expected one of: " << some
                                       << (num_nodes() > 8 ? ", ..." : ""));
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> BeamModel::ElasticEnds(int e) const {
  const BeamElement& el = elements_.at(e);
  return {nodes_[el.node_a].p_W + el.offset_a_W, nodes_[el.node_b].p_W + el.offset_b_W};
}

BeamElementProperties BeamModel::ElementProperties(int e) const {
  const BeamElement& el = elements_.at(e);
  const auto [pa, pb] = ElasticEnds(e);
  return MakeBeamElementProperties((pb - pa).norm(), el.section, el.material,
                                   el.shear_deformable, "beam element '" + el.name + "'");
}

Eigen::Matrix3d BeamModel::ElementFrame(int e) const {
  const BeamElement& el = elements_.at(e);
  const auto [pa, pb] = ElasticEnds(e);
  return CalcBeamFrame(pa, pb, el.reference_W, "beam element '" + el.name + "'");
}

Matrix6d BeamModel::RigidPartMass(int r) const {
  const RigidPart& p = rigid_parts_.at(r);
  const Eigen::Matrix3d S = Skew(p.p_NC_W);
  Matrix6d M;  // about the node: −m [c×]² = ParallelAxisTerm(m, c)
  M << p.mass * Eigen::Matrix3d::Identity(), -p.mass * S,  //
      p.mass * S, p.I_C_W + ParallelAxisTerm(p.mass, p.p_NC_W);
  return M;
}

std::vector<int> BeamModel::FixedDofs() const {
  std::vector<int> dofs;
  for (const Support& s : supports_)
    for (int i = 0; i < kBeamNodeDofs; ++i)
      if (s.fixed[i]) dofs.push_back(Dof(s.node, static_cast<BeamDof>(i)));
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

double StiffnessDampingForRatio(double damping_ratio, double frequency_hz) {
  EMB_THROW_IF(!(std::isfinite(damping_ratio) && damping_ratio >= 0.0),
               "damping ratio: expected >= 0, got " << damping_ratio);
  EMB_THROW_IF(!(std::isfinite(frequency_hz) && frequency_hz > 0.0),
               "damping reference frequency: expected > 0 Hz, got " << frequency_hz);
  return 2.0 * damping_ratio / (2.0 * std::numbers::pi * frequency_hz);
}

MassProperties CalcBeamModelMassProperties(const BeamModel& model) {
  MassPropertiesSum sum;  // elements as prisms about their centres, and the rigid parts
  for (int e = 0; e < model.num_elements(); ++e) {
    const BeamElementProperties p = model.ElementProperties(e);
    const auto [pa, pb] = model.ElasticEnds(e);
    const double L = p.length, rho = p.density;
    const auto& s = p.section;
    const double me = rho * s.area * L;
    const Eigen::Vector3d I_B(rho * s.polar_moment() * L, rho * s.second_moment_y * L + me * L * L / 12,
                              rho * s.second_moment_z * L + me * L * L / 12);
    const Eigen::Matrix3d R = model.ElementFrame(e);
    sum.Add(me, 0.5 * (pa + pb), R * I_B.asDiagonal() * R.transpose(), s.area * L);
  }
  for (const RigidPart& r : model.rigid_parts())
    sum.Add(r.mass, model.nodes()[r.node].p_W + r.p_NC_W, r.I_C_W);
  return sum.Result();
}

}  // namespace emb
