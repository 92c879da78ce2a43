#include "libemb/mbs/parts/stress_probe.h"

#include <algorithm>
#include <limits>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/fe/stress_measures.h"

namespace emb::mbs {
namespace {

constexpr const char* kComponents[6] = {"xx", "yy", "zz", "xy", "yz", "zx"};

// The kept modes' columns of the body file's modal stresses `file` (6 m x all modes).
Eigen::MatrixXd KeptColumns(const FlexiblePart& part, const Eigen::MatrixXd& file,
                            const std::string& who, const std::string& name) {
  Eigen::MatrixXd rows(file.rows(), part.num_modes());
  for (int j = 0; j < part.num_modes(); ++j) {
    const int mode = part.kept_modes[static_cast<std::size_t>(j)];
    EMB_THROW_IF(mode >= file.cols(), who << ": stress group '" << name << "' has " << file.cols()
                                          << " modes; expected " << part.num_available_modes);
    rows.col(j) = file.col(mode);
  }
  return rows;
}

}  // namespace

StressProbe::StressProbe(std::string name, int body, std::vector<StressRows> groups,
                         std::vector<int> nodes, StressRows surface,
                         std::vector<std::string> labels)
    : Probe(std::move(name)),
      body_(body),
      groups_(std::move(groups)),
      nodes_(std::move(nodes)),
      labels_(std::move(labels)),
      surface_(std::move(surface)) {
  if (labels_.empty())
    for (int node : nodes_) labels_.push_back("n" + std::to_string(node));
  EMB_CHECK(labels_.size() == nodes_.size());
  EMB_CHECK(surface_.rows.rows() == 6 * static_cast<Eigen::Index>(surface_.nodes.size()));
  for (const StressRows& g : groups_) {
    EMB_CHECK(g.rows.rows() == 6 * static_cast<Eigen::Index>(g.nodes.size()));
    for (const char* c : {".von_mises", ".von_mises_node", ".max_principal", ".max_principal_node"})
      channels_.push_back(g.name + c);
  }
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const int node = nodes_[k];
    int slot_group = -1, slot = -1;
    for (std::size_t g = 0; g < groups_.size() && slot_group < 0; ++g) {
      const auto& n = groups_[g].nodes;
      const auto it = std::find(n.begin(), n.end(), node);
      if (it != n.end()) slot_group = static_cast<int>(g), slot = static_cast<int>(it - n.begin());
    }
    EMB_THROW_IF(slot_group < 0, "stress output '" << this->name() << "': node " << node
                                                   << " (0-based mesh index) is in none of its "
                                                      "groups; expected a node of a stress "
                                                      "group");
    node_slots_.emplace_back(slot_group, slot);
    const std::string prefix = labels_[k] + ".";
    for (const char* c : kComponents) channels_.push_back(prefix + c);
  }
}

std::shared_ptr<const Probe> StressProbe::WithElasticBasis(int body,
                                                           const Eigen::MatrixXd& T) const {
  if (body != body_) return nullptr;
  std::vector<StressRows> groups = groups_;
  for (StressRows& g : groups) {
    EMB_CHECK(g.rows.cols() == T.rows());
    g.rows = g.rows * T;
  }
  StressRows surface = surface_;
  if (has_surface()) {
    EMB_CHECK(surface.rows.cols() == T.rows());
    surface.rows = surface.rows * T;
  }
  return std::make_shared<StressProbe>(name(), body_, std::move(groups), nodes_,
                                       std::move(surface), labels_);
}

Eigen::MatrixXd StressProbe::SurfaceStresses(const Eigen::VectorXd& eta) const {
  EMB_CHECK(has_surface());
  const Eigen::VectorXd v = surface_.rows * eta;
  return Eigen::Map<const Eigen::MatrixXd>(v.data(), 6,
                                           static_cast<Eigen::Index>(surface_.nodes.size()));
}

Eigen::MatrixXd StressProbe::GroupStresses(int g, const Eigen::VectorXd& eta) const {
  const StressRows& s = groups_[static_cast<std::size_t>(g)];
  const Eigen::VectorXd v = s.rows * eta;
  return Eigen::Map<const Eigen::MatrixXd>(v.data(), 6, static_cast<Eigen::Index>(s.nodes.size()));
}

void StressProbe::Evaluate(const Eigen::VectorXd& eta, StressSnapshot* out) const {
  StressSnapshot& snapshot = *out;
  const std::size_t ng = groups_.size();
  snapshot.sigma.resize(ng);
  snapshot.von_mises.resize(ng);
  snapshot.max_principal.resize(ng);
  snapshot.min_principal.resize(ng);
  for (std::size_t g = 0; g < ng; ++g) {
    const Eigen::MatrixXd& sigma = snapshot.sigma[g] = GroupStresses(static_cast<int>(g), eta);
    const Eigen::Index m = sigma.cols();
    snapshot.von_mises[g].resize(m);
    snapshot.max_principal[g].resize(m);
    snapshot.min_principal[g].resize(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      const Voigt6 s = sigma.col(i);
      const Eigen::Vector3d p = PrincipalStresses(s);
      snapshot.von_mises[g][i] = VonMises(s);
      snapshot.max_principal[g][i] = p[0];
      snapshot.min_principal[g][i] = p[2];
    }
  }
}

void StressProbe::DoEval(const System&, const std::vector<BodyKinematics>& bodies,
                         const Eigen::VectorXd&, Eigen::Ref<Eigen::VectorXd> values) const {
  StressSnapshot snap;  // an output sample's work: the allocation is not in the residual
  Evaluate(bodies[static_cast<std::size_t>(body_)].eta, &snap);
  Eigen::Index k = 0;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    Eigen::Index vm_at = 0, p1_at = 0;
    const double vm_max = snap.von_mises[g].maxCoeff(&vm_at);
    const double p1_max = snap.max_principal[g].maxCoeff(&p1_at);
    values[k++] = vm_max;
    values[k++] = groups_[g].nodes[static_cast<std::size_t>(vm_at)];
    values[k++] = p1_max;
    values[k++] = groups_[g].nodes[static_cast<std::size_t>(p1_at)];
  }
  for (const auto& [g, i] : node_slots_)
    for (int c = 0; c < 6; ++c) values[k++] = snap.sigma[static_cast<std::size_t>(g)](c, i);
}

std::shared_ptr<StressProbe> MakeStressProbe(const FlexiblePart& part,
                                             const std::vector<ModalStressGroup>& file_groups,
                                             const StressProbeSpec& spec,
                                             const ModalStressSurface* file_surface) {
  const std::string who = "stress output '" + spec.name + "': part '" + part.name + "' (" +
                          part.source + ")";
  EMB_THROW_IF(!part.flexible, who << " is rigid: no elastic coordinates to recover stresses "
                                      "from; expected a flexible (cms) part");
  const bool has_surface = file_surface != nullptr && !file_surface->empty();
  EMB_THROW_IF(spec.surface && !has_surface,
               who << ": the body file has no modal stresses on the whole surface, which "
                      "surface_field_times need; reduce it with --stress-surface (emb reduce)");
  const bool surface_only =
      spec.surface && file_groups.empty() && spec.groups.empty() && spec.nodes.empty() &&
      spec.node_tags.empty();
  EMB_THROW_IF(file_groups.empty() && !surface_only,
               who << ": the body file has no modal stresses" << (has_surface ? " at groups" : "")
                   << "; reduce it with --stress-groups NAME,... (emb reduce)");
  std::vector<std::string> available;
  for (const auto& g : file_groups) available.push_back(g.name);
  std::string listed;
  for (const auto& n : available) listed += (listed.empty() ? "" : ", ") + n;
  const std::vector<std::string> names = spec.groups.empty() ? available : spec.groups;
  std::vector<StressRows> rows;
  for (const std::string& name : names) {
    const auto it = std::find_if(file_groups.begin(), file_groups.end(),
                                 [&](const ModalStressGroup& g) { return g.name == name; });
    EMB_THROW_IF(it == file_groups.end(), who << ": unknown stress group '" << name << "'"
                                              << DidYouMean(name, available)
                                              << "; the body file has: " << listed);
    rows.push_back({name, it->nodes, KeptColumns(part, it->stresses, who, name)});
  }
  // The fields file names the surface's field after the output like a group's: /<o>/surface.
  EMB_THROW_IF(spec.surface && std::find(names.begin(), names.end(), "surface") != names.end(),
               who << ": a stress group named 'surface' and surface_field_times would both be "
                      "written as field '" << spec.name << "/surface'; expected the group "
                      "renamed, or the output split in two");
  StressRows surface;
  if (spec.surface)
    surface = {"surface", file_surface->nodes,
               KeptColumns(part, file_surface->stresses, who, "surface")};
  // Nodes by the mesh file's tags: found through the chosen groups' stored tags.
  std::vector<int> nodes = spec.nodes;
  std::vector<std::string> labels;
  for (int n : spec.nodes) labels.push_back("n" + std::to_string(n));
  for (const long long tag : spec.node_tags) {
    int node = -1;
    bool tags_known = false;
    for (const std::string& name : names) {
      const auto g = std::find_if(file_groups.begin(), file_groups.end(),
                                  [&](const ModalStressGroup& x) { return x.name == name; });
      tags_known = tags_known || !g->node_tags.empty();
      const auto at = std::find(g->node_tags.begin(), g->node_tags.end(), tag);
      if (at != g->node_tags.end()) {
        node = g->nodes[static_cast<std::size_t>(at - g->node_tags.begin())];
        break;
      }
    }
    EMB_THROW_IF(!tags_known, who << ": node_tags: the body file holds no node tags for its "
                                     "stress groups (written by an older emb); expected it "
                                     "reduced again, or the nodes given as 0-based mesh "
                                     "indices (nodes:)");
    EMB_THROW_IF(node < 0, "stress output '" << spec.name << "': node tag " << tag
                                             << " (the mesh file's numbering) is in none of "
                                                "its groups; expected a node of a stress group");
    nodes.push_back(node);
    labels.push_back("tag" + std::to_string(tag));
  }
  return std::make_shared<StressProbe>(spec.name, part.body, std::move(rows), std::move(nodes),
                                       std::move(surface), std::move(labels));
}

}  // namespace emb::mbs
