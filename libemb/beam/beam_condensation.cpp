#include "libemb/beam/beam_condensation.h"

#include <algorithm>

#include "libemb/common/error.h"

namespace emb {

using Eigen::Matrix3d;
using Eigen::Vector3d;

std::vector<MassProperties> CalcBeamNodeLumps(const BeamModel& model) {
  std::vector<MassPropertiesSum> sums(static_cast<std::size_t>(model.num_nodes()));
  for (int e = 0; e < model.num_elements(); ++e) {
    const BeamElement& el = model.elements()[e];
    const Vector12d d = CalcBeamLumpedMass(model.ElementProperties(e));
    const Matrix3d R = model.ElementFrame(e);
    const auto [pa, pb] = model.ElasticEnds(e);
    sums[el.node_a].Add(d[kUx], pa, R * d.segment<3>(kThetaX).asDiagonal() * R.transpose());
    sums[el.node_b].Add(d[6 + kUx], pb,
                        R * d.segment<3>(6 + kThetaX).asDiagonal() * R.transpose());
  }
  for (const RigidPart& r : model.rigid_parts())
    sums[r.node].Add(r.mass, model.nodes()[r.node].p_W + r.p_NC_W, r.I_C_W);
  std::vector<MassProperties> lumps;
  lumps.reserve(sums.size());
  for (const MassPropertiesSum& s : sums) lumps.push_back(s.Result());
  return lumps;
}

std::vector<int> CondensationNodes(const GeneratedBeamModel& generated) {
  const BeamModel& model = generated.model;
  std::vector<int> nodes;
  for (const RigidPart& r : model.rigid_parts()) nodes.push_back(r.node);
  for (const BeamInterface& i : generated.interfaces) nodes.push_back(i.node);
  for (const PointSpring& s : model.springs()) nodes.push_back(s.node);
  for (const Support& s : model.supports()) nodes.push_back(s.node);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

namespace {

// Γ(p − b_e) R_e C_e R_eᵀ Γ(p − b_e)ᵀ: element e's share of the compliance at point p.
Matrix6d ElementComplianceAt(const BeamModel& model, int e, const Vector3d& p) {
  Matrix6d R6 = Matrix6d::Zero();
  R6.topLeftCorner<3, 3>() = R6.bottomRightCorner<3, 3>() = model.ElementFrame(e);
  const Matrix6d G = CalcRigidTransfer(p - model.ElasticEnds(e).second);
  return G * R6 * CalcBeamEndCompliance(model.ElementProperties(e)) * R6.transpose() *
         G.transpose();
}

}  // namespace

CondensedBeamModel CondenseBeamModel(const BeamModel& model, std::vector<int> keep) {
  const std::string what = "beam model '" + model.name() + "'";
  const int n = model.num_nodes();
  EMB_THROW_IF(keep.empty(), what << ": condensation: expected at least one node to keep");
  // Incident elements per node.
  std::vector<std::vector<int>> incident(static_cast<std::size_t>(n));
  for (int e = 0; e < model.num_elements(); ++e) {
    incident[model.elements()[e].node_a].push_back(e);
    incident[model.elements()[e].node_b].push_back(e);
  }
  std::vector<bool> kept(static_cast<std::size_t>(n), false);
  for (int k : keep) {
    EMB_THROW_IF(k < 0 || k >= n, what << ": condensation: node " << k
                                       << " does not exist; expected 0.." << n - 1);
    kept[k] = true;
  }
  // Branch points and nodes on no element stay.
  for (int i = 0; i < n; ++i)
    if (incident[i].empty() || incident[i].size() > 2) kept[i] = true;

  CondensedBeamModel out;
  out.lumped_to.assign(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i)
    if (kept[i]) out.kept.push_back(i), out.lumped_to[i] = i;
  const auto other = [&](int e, int node) {
    const BeamElement& el = model.elements()[e];
    return el.node_a == node ? el.node_b : el.node_a;
  };
  std::vector<bool> used(static_cast<std::size_t>(model.num_elements()), false);
  for (int a : out.kept) {
    for (int first : incident[a]) {
      if (used[first]) continue;
      // Walk from a through condensed nodes to a kept node or a free end.
      std::vector<int> elements{first}, inner;
      std::vector<double> along;  // path length from a to each inner node [m]
      used[first] = true;
      int node = other(first, a), prev_e = first;
      double s = (model.nodes()[node].p_W - model.nodes()[a].p_W).norm();
      while (!kept[node] && incident[node].size() == 2) {
        inner.push_back(node);
        along.push_back(s);
        const int e = incident[node][0] == prev_e ? incident[node][1] : incident[node][0];
        EMB_THROW_IF(used[e], what << ": condensation: element '" << model.elements()[e].name
                                   << "' closes a loop of condensed nodes; expected a tree");
        used[e] = true;
        elements.push_back(e);
        const int next = other(e, node);
        s += (model.nodes()[next].p_W - model.nodes()[node].p_W).norm();
        node = next, prev_e = e;
      }
      const bool free_end = !kept[node];
      if (free_end) {
        inner.push_back(node);
        along.push_back(s);
        out.num_dropped_elements += static_cast<int>(elements.size());
      }
      for (std::size_t k = 0; k < inner.size(); ++k)
        out.lumped_to[inner[k]] = free_end || along[k] <= s - along[k] ? a : node;
      if (free_end) continue;
      EMB_THROW_IF(node == a, what << ": condensation: the elements from node '"
                                   << model.nodes()[a].name
                                   << "' return to it; expected a tree");
      BeamLink link;
      link.name = model.nodes()[a].name + "~" + model.nodes()[node].name;
      link.node_a = a;
      link.node_b = node;
      link.elements = elements;
      for (int e : elements) link.compliance += ElementComplianceAt(model, e, model.nodes()[node].p_W);
      link.compliance = 0.5 * (link.compliance + link.compliance.transpose()).eval();
      out.links.push_back(std::move(link));
    }
  }
  for (int e = 0; e < model.num_elements(); ++e)
    EMB_THROW_IF(!used[e], what << ": condensation: element '" << model.elements()[e].name
                                << "' joins no kept node (a loop of condensed nodes); expected "
                                   "a tree");
  const std::vector<MassProperties> node_lumps = CalcBeamNodeLumps(model);
  std::vector<MassPropertiesSum> sums(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    if (node_lumps[i].mass > 0.0) sums[out.lumped_to[i]].Add(node_lumps[i]);
  for (int k : out.kept) out.lumps.push_back(sums[k].Result());
  return out;
}

}  // namespace emb
