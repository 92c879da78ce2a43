#pragma once
// A pad in the middle of a face of a box mesh (libemb/mesh/box_mesh.h), as a surface group:
// an interface or stress group touching no other (test support).

#include <algorithm>
#include <string>

#include "libemb/mesh/mesh.h"

namespace emb {

// The faces of `from` whose nodes all lie at 0.2 ≤ x ≤ 0.4, as group `name` (a pad in the
// middle of a face, touching no other interface).
inline PhysicalGroup MiddlePad(const Mesh& m, const std::string& from, const std::string& name) {
  PhysicalGroup g;
  g.name = name;
  g.dim = 2;
  const CellBlock& all = m.group(from).faces[0];
  CellBlock pad;
  pad.type = all.type;
  for (int c = 0; c < all.num_cells(); ++c) {
    const int* v = all.cell(c);
    bool inside = true;
    for (int k = 0; k < all.nodes_per_cell(); ++k)
      inside &= m.nodes(0, v[k]) >= 0.2 - 1e-12 && m.nodes(0, v[k]) <= 0.4 + 1e-12;
    if (!inside) continue;
    pad.connectivity.insert(pad.connectivity.end(), v, v + all.nodes_per_cell());
    pad.tags.push_back(all.tags[c]);
    g.nodes.insert(g.nodes.end(), v, v + all.nodes_per_cell());
  }
  std::sort(g.nodes.begin(), g.nodes.end());
  g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
  g.faces.push_back(pad);
  return g;
}

}  // namespace emb
