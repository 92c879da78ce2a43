#include "libemb/mesh/boundary_surface.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

#include "libemb/common/error.h"

namespace emb {
namespace {

// The faces of a solid type by their corners (local gmsh indices, counter-clockwise seen from
// outside; -1 pads a triangle), and its mid-edge nodes by the corners of their edge.
struct SolidFaces {
  std::vector<std::array<int, 4>> corners;
  std::vector<std::array<int, 3>> edges;  // (corner a, corner b, mid-edge node)
};

const SolidFaces& FacesOf(CellType t) {
  static const SolidFaces tet{{{0, 2, 1, -1}, {0, 1, 3, -1}, {0, 3, 2, -1}, {1, 2, 3, -1}},
                              {{0, 1, 4}, {1, 2, 5}, {2, 0, 6}, {3, 0, 7}, {3, 2, 8}, {3, 1, 9}}};
  static const SolidFaces hex{
      {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}},
      {{0, 1, 8}, {0, 3, 9}, {0, 4, 10}, {1, 2, 11}, {1, 5, 12}, {2, 3, 13}, {2, 6, 14},
       {3, 7, 15}, {4, 5, 16}, {4, 7, 17}, {5, 6, 18}, {6, 7, 19}}};
  static const SolidFaces wedge{
      {{0, 2, 1, -1}, {3, 4, 5, -1}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}},
      {{0, 1, 6}, {0, 2, 7}, {0, 3, 8}, {1, 2, 9}, {1, 4, 10}, {2, 5, 11}, {3, 4, 12},
       {3, 5, 13}, {4, 5, 14}}};
  switch (t) {
    case CellType::kTet4: case CellType::kTet10: return tet;
    case CellType::kHex8: case CellType::kHex20: return hex;
    case CellType::kWedge6: case CellType::kWedge15: return wedge;
    default: break;
  }
  EMB_THROW(InputError, "boundary surface: expected a solid cell type, got " << Name(t));
}

bool IsQuadratic(CellType t) {
  return t == CellType::kTet10 || t == CellType::kHex20 || t == CellType::kWedge15;
}

// Block order of the face types in BoundarySurface::faces.
int FaceSlot(int corners, bool quadratic) { return (corners == 4 ? 2 : 0) + (quadratic ? 1 : 0); }
constexpr CellType kFaceTypes[4] = {CellType::kTri3, CellType::kTri6, CellType::kQuad4,
                                    CellType::kQuad8};

// One face of one cell: its sorted corners (the key; -1 padding sorts first) and where it is.
struct FaceRef {
  std::array<int, 4> key;
  int block, cell, face;
};

// The face's nodes in gmsh face order (corners, then the mid-edge nodes of its edges).
std::vector<int> FaceNodes(const CellBlock& b, int c, int f) {
  const SolidFaces& sf = FacesOf(b.type);
  const auto& k = sf.corners[static_cast<std::size_t>(f)];
  const int n = k[3] < 0 ? 3 : 4;
  const int* cell = b.cell(c);
  std::vector<int> out;
  for (int i = 0; i < n; ++i) out.push_back(cell[k[i]]);
  if (!IsQuadratic(b.type)) return out;
  for (int i = 0; i < n; ++i) {
    const int a = k[i], z = k[(i + 1) % n];
    const auto e = std::find_if(sf.edges.begin(), sf.edges.end(), [&](const auto& e) {
      return (e[0] == a && e[1] == z) || (e[0] == z && e[1] == a);
    });
    EMB_CHECK(e != sf.edges.end());
    out.push_back(cell[(*e)[2]]);
  }
  return out;
}

}  // namespace

int BoundarySurface::num_faces() const {
  int n = 0;
  for (const CellBlock& b : faces) n += b.num_cells();
  return n;
}

BoundarySurface ExtractBoundarySurface(const Mesh& mesh) {
  std::vector<FaceRef> refs;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const CellBlock& block = mesh.blocks[b];
    const SolidFaces& sf = FacesOf(block.type);
    for (int c = 0; c < block.num_cells(); ++c)
      for (std::size_t f = 0; f < sf.corners.size(); ++f) {
        FaceRef r{{-1, -1, -1, -1}, static_cast<int>(b), c, static_cast<int>(f)};
        for (int i = 0; i < 4; ++i)
          if (sf.corners[f][i] >= 0) r.key[i] = block.cell(c)[sf.corners[f][i]];
        std::sort(r.key.begin(), r.key.end());
        refs.push_back(r);
      }
  }
  std::vector<std::size_t> order(refs.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return refs[i].key < refs[j].key; });
  std::vector<char> boundary(refs.size(), 0);
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && refs[order[j]].key == refs[order[i]].key) ++j;
    if (j - i > 2) {
      const FaceRef& r = refs[order[i]];
      EMB_THROW(InputError, "boundary surface of mesh '"
                                << mesh.source << "': the face with corner nodes " << r.key[0]
                                << " " << r.key[1] << " " << r.key[2] << " " << r.key[3]
                                << " (-1: none) belongs to " << j - i
                                << " cells; expected at most 2 (a duplicated or non-manifold "
                                   "cell)");
    }
    if (j - i == 1) boundary[order[i]] = 1;
    i = j;
  }
  BoundarySurface out;
  out.faces.resize(4);
  for (int s = 0; s < 4; ++s) out.faces[static_cast<std::size_t>(s)].type = kFaceTypes[s];
  std::vector<char> on(static_cast<std::size_t>(mesh.num_nodes()), 0);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    if (!boundary[i]) continue;
    const FaceRef& r = refs[i];
    const CellBlock& block = mesh.blocks[static_cast<std::size_t>(r.block)];
    const std::vector<int> nodes = FaceNodes(block, r.cell, r.face);
    CellBlock& dst = out.faces[static_cast<std::size_t>(
        FaceSlot(r.key[0] < 0 ? 3 : 4, IsQuadratic(block.type)))];
    dst.connectivity.insert(dst.connectivity.end(), nodes.begin(), nodes.end());
    dst.tags.push_back(block.tags[static_cast<std::size_t>(r.cell)]);
    for (int n : nodes) on[static_cast<std::size_t>(n)] = 1;
  }
  out.faces.erase(std::remove_if(out.faces.begin(), out.faces.end(),
                                 [](const CellBlock& b) { return b.num_cells() == 0; }),
                  out.faces.end());
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (on[static_cast<std::size_t>(n)]) out.nodes.push_back(n);
  return out;
}

BoundarySurface SelectFaces(const BoundarySurface& surface, const std::vector<int>& nodes) {
  BoundarySurface out;
  for (const CellBlock& b : surface.faces) {
    CellBlock kept;
    kept.type = b.type;
    for (int c = 0; c < b.num_cells(); ++c) {
      const int* f = b.cell(c);
      if (!std::all_of(f, f + b.nodes_per_cell(), [&](int n) {
            return std::binary_search(nodes.begin(), nodes.end(), n);
          }))
        continue;
      kept.connectivity.insert(kept.connectivity.end(), f, f + b.nodes_per_cell());
      kept.tags.push_back(b.tags[static_cast<std::size_t>(c)]);
    }
    if (kept.num_cells() > 0) out.faces.push_back(std::move(kept));
  }
  std::vector<int> used;
  for (const CellBlock& b : out.faces) used.insert(used.end(), b.connectivity.begin(), b.connectivity.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  out.nodes = std::move(used);
  return out;
}

}  // namespace emb
