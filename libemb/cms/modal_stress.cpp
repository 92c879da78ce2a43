#include "libemb/cms/modal_stress.h"

#include <algorithm>
#include <limits>
#include <regex>
#include <sstream>

#include "libemb/cms/body_codec.h"
#include "libemb/common/error.h"
#include "libemb/fe/nodal_stress.h"

namespace emb {
namespace {

const PhysicalGroup& SurfaceGroup(const Mesh& mesh, const std::string& name) {
  const PhysicalGroup& g = mesh.group(name);  // throws listing the groups
  EMB_THROW_IF(g.dim != 2, "stress group '" << name << "' of mesh '" << mesh.source
                                            << "': expected a surface group, got dimension "
                                            << g.dim);
  EMB_THROW_IF(g.nodes.empty(), "stress group '" << name << "' of mesh '" << mesh.source
                                                 << "' has no nodes");
  return g;
}

void CheckDistinct(const std::vector<std::string>& groups) {
  for (std::size_t i = 0; i < groups.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      EMB_THROW_IF(groups[i] == groups[j],
                   "stress groups: '" << groups[i] << "' is given twice; expected each once");
}

}  // namespace

std::vector<std::string> DefaultStressGroups(const Mesh& mesh) {
  static const std::regex fillet(R"(^(crankpin|journal)_fillet_\d+$)");
  std::vector<std::string> out;
  for (const PhysicalGroup& g : mesh.groups)
    if (g.dim == 2 && std::regex_match(g.name, fillet)) out.push_back(g.name);
  return out;
}

SparseMatrix BuildGroupStressOperator(const Mesh& mesh, const IsotropicMaterial& material,
                                      const std::vector<std::string>& groups) {
  CheckDistinct(groups);
  std::vector<int> nodes;
  for (const std::string& name : groups) {
    const PhysicalGroup& g = SurfaceGroup(mesh, name);
    nodes.insert(nodes.end(), g.nodes.begin(), g.nodes.end());
  }
  return BuildNodalStressOperator(mesh, material, nodes);
}

std::vector<ModalStressGroup> CalcModalStresses(const Mesh& mesh, const IsotropicMaterial& material,
                                                const Eigen::MatrixXd& Phi,
                                                const std::vector<std::string>& groups) {
  CheckDistinct(groups);
  EMB_THROW_IF(Phi.rows() != 3 * mesh.num_nodes(),
               "modal stresses: mode shapes with " << Phi.rows() << " rows; expected 3 x "
                                                   << mesh.num_nodes() << " nodes");
  std::vector<ModalStressGroup> out;
  for (const std::string& name : groups) {
    ModalStressGroup g;
    g.name = name;
    g.nodes = SurfaceGroup(mesh, name).nodes;
    if (!mesh.node_tags.empty()) {
      for (int n : g.nodes) {
        const std::size_t tag = mesh.node_tags[static_cast<std::size_t>(n)];
        EMB_THROW_IF(tag > static_cast<std::size_t>(std::numeric_limits<int>::max()),
                     "stress group '" << name << "': node tag " << tag
                                      << " does not fit the body file's 32-bit tags; expected "
                                         "node tags below 2^31");
        g.node_tags.push_back(static_cast<int>(tag));
      }
    }
    g.stresses = BuildNodalStressOperator(mesh, material, g.nodes) * Phi;
    out.push_back(std::move(g));
  }
  return out;
}

ModalStressCheck CheckModalStresses(const std::vector<ModalStressGroup>& groups,
                                    const Eigen::MatrixXd& full_stresses,
                                    const Eigen::MatrixXd& reduced_z, const Eigen::MatrixXd& X,
                                    const Eigen::MatrixXd& Mhat, const std::string& note) {
  ModalStressCheck out;
  out.note = note;
  if (groups.empty() || reduced_z.cols() == 0) return out;
  EMB_CHECK(full_stresses.cols() == reduced_z.cols() && X.rows() == reduced_z.rows());
  const Eigen::MatrixXd xi = X.transpose() * (Mhat * reduced_z);  // elastic part of z
  Eigen::Index row = 0;
  for (const ModalStressGroup& g : groups) {
    const Eigen::Index rows = g.stresses.rows();
    EMB_CHECK(row + rows <= full_stresses.rows());
    const Eigen::MatrixXd full = full_stresses.middleRows(row, rows);
    const Eigen::MatrixXd red = g.stresses * xi;
    // Per kind of load (forces: columns 6j..6j+2, moments: 6j+3..6j+5), the largest error
    // over the loads of that kind against the largest stress they cause in the group: a load
    // that does not reach the group (statically, a free end beyond the load carries no
    // stress) leaves only round-off there, which is no scale to divide by.
    double err = 0.0, peak = 0.0;
    for (int kind = 0; kind < 2; ++kind) {
      double diff = 0.0, scale = 0.0;
      for (Eigen::Index k = 0; k < full.cols(); ++k) {
        if ((k % 6 < 3) != (kind == 0)) continue;
        scale = std::max(scale, full.col(k).cwiseAbs().maxCoeff());
        diff = std::max(diff, (red.col(k) - full.col(k)).cwiseAbs().maxCoeff());
      }
      peak = std::max(peak, scale);
      if (scale > 0.0) err = std::max(err, diff / scale);
    }
    out.groups.push_back(g.name);
    out.errors.push_back(err);
    out.peak_stress.push_back(peak);
    out.max_error = std::max(out.max_error, err);
    row += rows;
  }
  out.run = true;
  out.num_loads = static_cast<int>(reduced_z.cols());
  return out;
}

void TransferModalStresses(body_codec::Codec& c, std::vector<ModalStressGroup>& groups,
                           ModalStressSurface& surface, Eigen::Index ne) {
  const std::string root = kStressGroup;
  H5File& h5 = c.h5();
  if (c.writing()) {
    if (groups.empty() && surface.empty()) return;
    std::vector<std::string> names;
    for (const auto& g : groups) names.push_back(g.name);
    if (!names.empty()) h5.Write(root + "/names", names);
    h5.SetAttribute(root, "components", std::string(kStressComponentNames));
    h5.SetAttribute(root, "recovery",
                    std::string("nodal average over the cells sharing the node of the stress "
                                "evaluated at the node (fe/nodal_stress.h); mesh axes"));
    h5.SetAttribute(root, "units", std::string("Pa per unit elastic coordinate"));
  } else {
    groups.clear();
    if (c.Exists(root + "/names"))
      for (const std::string& name : h5.ReadStrings(root + "/names"))
        groups.push_back({name, {}, {}});
  }
  for (ModalStressGroup& g : groups) {
    c.Text(g.name);
    const std::string base = root + "/" + g.name;
    c.Ints(base + "/nodes", g.nodes);
    c.Matrix(base + "/modal", g.stresses);
    c.ExpectShape(base + "/modal", g.stresses, 6 * static_cast<Eigen::Index>(g.nodes.size()), ne);
    // Optional (files before it have none): present or absent alike in the digest, so a
    // node_tags dataset removed or added afterwards changes the digest.
    if (c.writing() ? !g.node_tags.empty() : c.Exists(base + "/node_tags")) {
      c.Ints(base + "/node_tags", g.node_tags);
      EMB_THROW_IF(g.node_tags.size() != g.nodes.size(),
                   "body file: " << base << "/node_tags holds " << g.node_tags.size()
                                 << " tags for " << g.nodes.size() << " nodes");
    }
  }
  TransferSurfaceStresses(c, surface, ne);
}

}  // namespace emb
