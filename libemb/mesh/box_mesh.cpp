#include "libemb/mesh/box_mesh.h"

#include <Eigen/Dense>
#include <algorithm>
#include <map>
#include <utility>

#include "libemb/common/error.h"

namespace emb {
namespace {

// Edges (pairs of vertex positions) in gmsh's order of the mid-edge nodes.
const std::vector<std::pair<int, int>>& QuadraticEdges(CellType linear) {
  static const std::vector<std::pair<int, int>> tet{{0, 1}, {1, 2}, {2, 0}, {3, 0}, {2, 3}, {1, 3}};
  static const std::vector<std::pair<int, int>> hex{{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                                                    {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  static const std::vector<std::pair<int, int>> wedge{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4},
                                                      {2, 5}, {3, 4}, {3, 5}, {4, 5}};
  switch (linear) {
    case CellType::kTet4: return tet;
    case CellType::kHex8: return hex;
    case CellType::kWedge6: return wedge;
    default: EMB_THROW(InputError, "expected a linear solid (Tet4, Hex8, Wedge6), got " << Name(linear));
  }
}

CellType QuadraticOf(CellType linear) {
  switch (linear) {
    case CellType::kTet4: return CellType::kTet10;
    case CellType::kHex8: return CellType::kHex20;
    case CellType::kWedge6: return CellType::kWedge15;
    default: EMB_THROW(InputError, "expected a linear solid (Tet4, Hex8, Wedge6), got " << Name(linear));
  }
}

CellType LinearOf(CellType t) {
  switch (t) {
    case CellType::kTet4: case CellType::kTet10: return CellType::kTet4;
    case CellType::kHex8: case CellType::kHex20: return CellType::kHex8;
    case CellType::kWedge6: case CellType::kWedge15: return CellType::kWedge6;
    default: EMB_THROW(InputError, "expected a solid cell type, got " << Name(t));
  }
}

// Signed volume measure of a tetrahedron a,b,c,d.
double TetVolume6(const Eigen::Matrix3Xd& x, int a, int b, int c, int d) {
  Eigen::Matrix3d m;
  m << x.col(b) - x.col(a), x.col(c) - x.col(a), x.col(d) - x.col(a);
  return m.determinant();
}

// Tri3 → Tri6, Quad4 → Quad8 with the mid-edge nodes of `mid` (gmsh order: the edges
// 0–1, 1–2, ... around the face). A face edge without a mid node (e.g. the diagonal of a split
// brick face) is an internal error: faces are built on cell edges.
CellBlock QuadraticFaces(const CellBlock& linear, const std::map<std::pair<int, int>, int>& mid) {
  EMB_CHECK(linear.type == CellType::kTri3 || linear.type == CellType::kQuad4);
  CellBlock q;
  q.type = linear.type == CellType::kTri3 ? CellType::kTri6 : CellType::kQuad8;
  q.tags = linear.tags;
  const int nc = linear.nodes_per_cell();
  for (int c = 0; c < linear.num_cells(); ++c) {
    const int* v = linear.cell(c);
    q.connectivity.insert(q.connectivity.end(), v, v + nc);
    for (int e = 0; e < nc; ++e) {
      auto it = mid.find(std::minmax(v[e], v[(e + 1) % nc]));
      EMB_CHECK(it != mid.end());
      q.connectivity.push_back(it->second);
    }
  }
  return q;
}

}  // namespace

Mesh MakeQuadratic(const Mesh& linear) {
  Mesh out;
  out.source = linear.source;
  std::map<std::pair<int, int>, int> mid;
  std::vector<Eigen::Vector3d> extra;
  const int n0 = linear.num_nodes();
  for (const auto& b : linear.blocks) {
    const auto& edges = QuadraticEdges(b.type);
    CellBlock q;
    q.type = QuadraticOf(b.type);
    q.tags = b.tags;
    for (int c = 0; c < b.num_cells(); ++c) {
      const int* v = b.cell(c);
      q.connectivity.insert(q.connectivity.end(), v, v + b.nodes_per_cell());
      for (auto [i, j] : edges) {
        auto key = std::minmax(v[i], v[j]);
        auto [it, inserted] = mid.try_emplace(key, n0 + static_cast<int>(extra.size()));
        if (inserted) extra.push_back(0.5 * (linear.nodes.col(v[i]) + linear.nodes.col(v[j])));
        q.connectivity.push_back(it->second);
      }
    }
    out.blocks.push_back(std::move(q));
  }
  out.nodes.resize(3, n0 + static_cast<int>(extra.size()));
  out.nodes.leftCols(n0) = linear.nodes;
  for (size_t k = 0; k < extra.size(); ++k) out.nodes.col(n0 + k) = extra[k];
  out.node_tags.resize(out.nodes.cols());
  for (size_t k = 0; k < out.node_tags.size(); ++k) out.node_tags[k] = k + 1;
  for (const auto& g : linear.groups) {
    PhysicalGroup q = g;
    std::vector<char> in(n0, 0);
    for (int i : g.nodes) in[i] = 1;
    for (const auto& [edge, m] : mid)
      if (in[edge.first] && in[edge.second]) q.nodes.push_back(m);
    if (g.dim == 3) {  // every node of a volume group
      q.nodes.resize(out.nodes.cols());
      for (int i = 0; i < out.nodes.cols(); ++i) q.nodes[i] = i;
    }
    std::sort(q.nodes.begin(), q.nodes.end());
    q.nodes.erase(std::unique(q.nodes.begin(), q.nodes.end()), q.nodes.end());
    q.faces.clear();
    for (const auto& fb : g.faces) q.faces.push_back(QuadraticFaces(fb, mid));
    out.groups.push_back(std::move(q));
  }
  return out;
}

Mesh MakeBoxMesh(const Eigen::Vector3d& size, const Eigen::Vector3i& cells, CellType type) {
  EMB_THROW_IF((size.array() <= 0.0).any(), "box size: expected positive lengths, got "
                                                << size.transpose());
  EMB_THROW_IF((cells.array() <= 0).any(), "box cells: expected positive counts, got "
                                               << cells.transpose());
  const CellType lin = LinearOf(type);
  const int nx = cells.x(), ny = cells.y(), nz = cells.z();
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  Mesh m;
  m.source = "box";
  m.nodes.resize(3, (nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        m.nodes.col(id(i, j, k)) << size.x() * i / nx, size.y() * j / ny, size.z() * k / nz;
  m.node_tags.resize(m.nodes.cols());
  for (size_t k = 0; k < m.node_tags.size(); ++k) m.node_tags[k] = k + 1;

  CellBlock b;
  b.type = lin;
  std::size_t tag = 1;
  auto add = [&](std::initializer_list<int> v) {
    b.connectivity.insert(b.connectivity.end(), v);
    b.tags.push_back(tag++);
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int h[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                          id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                          id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        if (lin == CellType::kHex8) {
          add({h[0], h[1], h[2], h[3], h[4], h[5], h[6], h[7]});
        } else if (lin == CellType::kWedge6) {
          add({h[0], h[1], h[2], h[4], h[5], h[6]});
          add({h[0], h[2], h[3], h[4], h[6], h[7]});
        } else {
          // Kuhn split around the diagonal 0–6; orient every tet positively.
          const int ring[7] = {1, 2, 3, 7, 4, 5, 1};
          for (int t = 0; t < 6; ++t) {
            int a = h[0], p = h[ring[t]], q = h[ring[t + 1]], d = h[6];
            if (TetVolume6(m.nodes, a, p, q, d) < 0) std::swap(p, q);
            add({a, p, q, d});
          }
        }
      }
  m.blocks.push_back(std::move(b));

  const char* names[6] = {"x0", "x1", "y0", "y1", "z0", "z1"};
  for (int f = 0; f < 6; ++f) {
    PhysicalGroup g;
    g.name = names[f];
    g.dim = 2;
    const int axis = f / 2;
    const double value = (f % 2) ? size[axis] : 0.0;
    for (int i = 0; i < m.num_nodes(); ++i)
      if (m.nodes(axis, i) == value) g.nodes.push_back(i);
    // Quad4 faces on the grid squares of the plane, numbered counter-clockwise seen from
    // outside (their edges are brick edges, so every cell type has their mid nodes).
    CellBlock faces;
    faces.type = CellType::kQuad4;
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    for (int j = 0; j < cells[a2]; ++j)
      for (int i = 0; i < cells[a1]; ++i) {
        auto node = [&](int di, int dj) {
          Eigen::Vector3i ijk;
          ijk[axis] = (f % 2) ? cells[axis] : 0;
          ijk[a1] = i + di;
          ijk[a2] = j + dj;
          return id(ijk.x(), ijk.y(), ijk.z());
        };
        int quad[4] = {node(0, 0), node(1, 0), node(1, 1), node(0, 1)};
        if (f % 2 == 0) std::swap(quad[1], quad[3]);
        faces.connectivity.insert(faces.connectivity.end(), quad, quad + 4);
        faces.tags.push_back(faces.tags.size() + 1);
      }
    g.faces.push_back(std::move(faces));
    m.groups.push_back(std::move(g));
  }
  PhysicalGroup vol;
  vol.name = "box";
  vol.dim = 3;
  for (int i = 0; i < m.num_nodes(); ++i) vol.nodes.push_back(i);
  m.groups.push_back(std::move(vol));

  if (type != lin) m = MakeQuadratic(m);
  m.source = "box";
  return m;
}

}  // namespace emb
