#include "libemb/mbs/parts/surface_mesh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>

#include "libemb/common/error.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/io/mesh_io.h"

namespace emb::mbs {
namespace {

// Corner faces of the solid types in gmsh's corner numbering, each in cyclic order.
struct FaceTable {
  int corners;
  std::vector<std::vector<int>> faces;
};

FaceTable FacesOf(CellType t) {
  switch (t) {
    case CellType::kTet4:
    case CellType::kTet10:
      return {4, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};
    case CellType::kHex8:
    case CellType::kHex20:
      return {8,
              {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
    case CellType::kWedge6:
    case CellType::kWedge15:
      return {6, {{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}};
    default:
      return {0, {}};
  }
}

// The vector area of a flat polygon through `p` (cyclic): half the sum of cross products.
Eigen::Vector3d VectorArea(const std::vector<Eigen::Vector3d>& p) {
  if (p.size() == 3) return 0.5 * (p[1] - p[0]).cross(p[2] - p[0]);
  return 0.5 * (p[2] - p[0]).cross(p[3] - p[1]);
}

struct Face {
  std::vector<int> nodes;  // corners, then mid-side nodes
  Eigen::Vector3d area;    // outward vector area
  int count{0};            // cells sharing the face
};

}  // namespace

BodyMeshShapes ReadBodyMeshShapes(const std::string& path, const std::string& part) {
  const std::string who = "part '" + part + "': body file '" + path + "'";
  const H5File h5(path, H5File::Mode::kRead);
  EMB_THROW_IF(!h5.Exists("/mesh/nodes") || !h5.Exists("/modes/mesh_shapes"),
               who << " has no mesh and mesh shapes, which output points need; reduce the "
                      "part again without --no-mesh-shapes");
  BodyMeshShapes out;
  out.mesh = ReadMeshSection(h5);
  const auto dims = h5.Shape("/modes/mesh_shapes");
  const auto n = static_cast<std::uint64_t>(out.mesh.num_nodes());
  EMB_THROW_IF(dims.size() != 3 || dims[1] != n || dims[2] != 3,
               who << ": /modes/mesh_shapes: expected shape [ne][" << n << "][3]");
  const std::string recorded = h5.ReadStringAttribute("/provenance", "mesh_hash");
  const std::string actual = MeshHash(out.mesh);
  EMB_THROW_IF(recorded != actual, who << ": its /mesh (hash " << actual
                                       << ") is not the mesh it was reduced from (" << recorded
                                       << "); the file was modified");
  const std::vector<double> data = h5.ReadDoubles("/modes/mesh_shapes");
  // [ne][n][3] row-major: mode j is a contiguous block of 3 n values.
  out.shapes = Eigen::Map<const Eigen::MatrixXd>(data.data(), static_cast<Eigen::Index>(3 * n),
                                                 static_cast<Eigen::Index>(dims[0]));
  return out;
}

SurfacePatch GroupSurface(const Mesh& mesh, const std::string& group) {
  const PhysicalGroup& g = mesh.group(group);  // throws listing the groups
  std::vector<char> in(static_cast<std::size_t>(mesh.num_nodes()), 0);
  for (int i : g.nodes) in[static_cast<std::size_t>(i)] = 1;
  auto node = [&](int i) -> Eigen::Vector3d { return mesh.nodes.col(i); };
  std::map<std::vector<int>, Face> faces;  // by sorted corners
  for (const CellBlock& b : mesh.blocks) {
    const FaceTable table = FacesOf(b.type);
    const int nn = b.nodes_per_cell();
    for (int c = 0; c < b.num_cells(); ++c) {
      const int* cell = b.cell(c);
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int k = 0; k < table.corners; ++k) centroid += node(cell[k]);
      centroid /= table.corners;
      for (const auto& f : table.faces) {
        if (!std::all_of(f.begin(), f.end(), [&](int k) { return in[cell[k]] != 0; })) continue;
        std::vector<int> key;
        std::vector<Eigen::Vector3d> p;
        for (int k : f) {
          key.push_back(cell[k]);
          p.push_back(node(cell[k]));
        }
        std::sort(key.begin(), key.end());
        Face& face = faces[key];
        if (++face.count > 1) continue;
        face.nodes.assign(key.begin(), key.end());
        face.area = VectorArea(p);
        Eigen::Vector3d mid = Eigen::Vector3d::Zero();
        for (const auto& q : p) mid += q / static_cast<double>(p.size());
        if (face.area.dot(mid - centroid) < 0) face.area = -face.area;
        // Mid-side nodes: those whose nearest corner-pair midpoint is an edge of this face.
        for (int m = table.corners; m < nn; ++m) {
          double best = std::numeric_limits<double>::infinity();
          std::array<int, 2> edge{-1, -1};
          for (int a = 0; a < table.corners; ++a)
            for (int b2 = a + 1; b2 < table.corners; ++b2) {
              const double d = (node(cell[m]) - 0.5 * (node(cell[a]) + node(cell[b2]))).norm();
              if (d < best) best = d, edge = {a, b2};
            }
          if (std::find(f.begin(), f.end(), edge[0]) != f.end() &&
              std::find(f.begin(), f.end(), edge[1]) != f.end())
            face.nodes.push_back(cell[m]);
        }
      }
    }
  }
  std::map<int, std::pair<double, Eigen::Vector3d>> acc;  // node -> weight, summed areas
  for (const auto& [key, face] : faces) {
    if (face.count != 1) continue;  // interior
    const double share = face.area.norm() / static_cast<double>(face.nodes.size());
    for (int i : face.nodes) {
      auto& a = acc.try_emplace(i, 0.0, Eigen::Vector3d::Zero()).first->second;
      a.first += share;
      a.second += face.area;
    }
  }
  EMB_THROW_IF(acc.empty(), "group '" << group << "' of mesh '" << mesh.source
                                      << "' bounds no cell face; expected a surface group (e.g. "
                                         "outer), got "
                                      << (g.dim == 3 ? "a volume group" : "no boundary face"));
  SurfacePatch s;
  s.weights.resize(static_cast<Eigen::Index>(acc.size()));
  s.normals.resize(3, static_cast<Eigen::Index>(acc.size()));
  Eigen::Index k = 0;
  for (const auto& [i, a] : acc) {
    s.nodes.push_back(i);
    s.weights[k] = a.first;
    s.normals.col(k) = a.second.normalized();
    ++k;
  }
  return s;
}

}  // namespace emb::mbs
