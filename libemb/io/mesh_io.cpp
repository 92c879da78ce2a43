#include "libemb/io/mesh_io.h"

#include "libemb/common/error.h"
#include "libemb/io/xdmf_writer.h"

namespace emb {

void WriteMesh(H5File& h5, const Mesh& mesh) {
  const std::uint64_t n = static_cast<std::uint64_t>(mesh.num_nodes());
  h5.Write("/mesh/nodes", mesh.nodes.data(), {n, 3});
  std::vector<std::uint64_t> tags(mesh.node_tags.begin(), mesh.node_tags.end());
  h5.Write("/mesh/node_tags", tags.data(), {tags.size()});
  for (const auto& b : mesh.blocks) {
    const std::string type(Name(b.type));
    const std::uint64_t c = static_cast<std::uint64_t>(b.num_cells());
    const std::uint64_t k = static_cast<std::uint64_t>(b.nodes_per_cell());
    h5.Write("/mesh/cells/" + type, b.connectivity.data(), {c, k});
    std::vector<std::uint64_t> ct(b.tags.begin(), b.tags.end());
    h5.Write("/mesh/cell_tags/" + type, ct.data(), {c});
    const std::vector<int> vtk = VtkOrderedConnectivity(b);
    h5.Write("/viz/" + type, vtk.data(), {c, k});
  }
  for (const auto& g : mesh.groups) {
    const std::string p = "/mesh/groups/" + g.name;
    h5.Write(p, g.nodes.data(), {g.nodes.size()});
    h5.SetAttribute(p, "dim", static_cast<long long>(g.dim));
  }
  h5.SetAttribute("/mesh", "source", mesh.source);
  h5.SetAttribute("/mesh", "hash", MeshHash(mesh));
}

Mesh ReadMeshSection(const H5File& h5) {
  Mesh mesh;
  const auto shape = h5.Shape("/mesh/nodes");
  EMB_THROW_IF(shape.size() != 2 || shape[1] != 3,
               "HDF5 file '" << h5.path() << "': /mesh/nodes: expected shape [n][3]");
  const std::vector<double> xyz = h5.ReadDoubles("/mesh/nodes");
  mesh.nodes = Eigen::Map<const Eigen::Matrix3Xd>(xyz.data(), 3, static_cast<Eigen::Index>(shape[0]));
  mesh.source = h5.ReadStringAttribute("/mesh", "source");
  for (const auto& type_name : h5.List("/mesh/cells")) {
    const auto type = CellTypeFromName(type_name);
    EMB_THROW_IF(!type, "HDF5 file '" << h5.path() << "': unknown cell type '" << type_name << "'");
    CellBlock b;
    b.type = *type;
    b.connectivity = h5.ReadInts("/mesh/cells/" + type_name);
    b.tags.resize(b.connectivity.size() / NumNodes(*type));
    for (std::size_t i = 0; i < b.tags.size(); ++i) b.tags[i] = i + 1;
    mesh.blocks.push_back(std::move(b));
  }
  if (h5.Exists("/mesh/groups"))
    for (const auto& name : h5.List("/mesh/groups")) {
      PhysicalGroup g;
      g.name = name;
      g.nodes = h5.ReadInts("/mesh/groups/" + name);
      g.dim = static_cast<int>(h5.ReadIntAttribute("/mesh/groups/" + name, "dim"));
      mesh.groups.push_back(std::move(g));
    }
  mesh.node_tags.resize(mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i) mesh.node_tags[i] = i + 1;
  return mesh;
}

void WriteProvenance(H5File& h5, const Provenance& p) {
  h5.SetAttribute("/provenance", "command", p.command);
  h5.SetAttribute("/provenance", "source", p.source);
  h5.SetAttribute("/provenance", "mesh_hash", p.mesh_hash);
  h5.SetAttribute("/provenance", "options", p.options);
}

}  // namespace emb
