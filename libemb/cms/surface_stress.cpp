#include "libemb/cms/surface_stress.h"

#include <algorithm>
#include <numeric>

#include "libemb/cms/body_codec.h"
#include "libemb/common/error.h"
#include "libemb/fe/nodal_stress.h"
#include "libemb/mesh/boundary_surface.h"

namespace emb {

int ModalStressSurface::num_faces() const {
  int n = 0;
  for (const CellBlock& b : faces) n += b.num_cells();
  return n;
}

ModalStressSurface CalcSurfaceModalStresses(const Mesh& mesh, const IsotropicMaterial& material,
                                            const Eigen::MatrixXd& Phi) {
  EMB_THROW_IF(Phi.rows() != 3 * mesh.num_nodes(),
               "surface modal stresses: mode shapes with " << Phi.rows() << " rows; expected 3 x "
                                                           << mesh.num_nodes() << " nodes");
  const BoundarySurface b = ExtractBoundarySurface(mesh);
  ModalStressSurface s;
  s.nodes = b.nodes;
  s.coordinates.resize(s.num_nodes(), 3);
  std::vector<int> local(static_cast<std::size_t>(mesh.num_nodes()), -1);
  for (int i = 0; i < s.num_nodes(); ++i) {
    const int n = s.nodes[static_cast<std::size_t>(i)];
    local[static_cast<std::size_t>(n)] = i;
    s.coordinates.row(i) = mesh.nodes.col(n).transpose();
  }
  for (CellBlock f : b.faces) {
    for (int& n : f.connectivity) n = local[static_cast<std::size_t>(n)];
    std::iota(f.tags.begin(), f.tags.end(), std::size_t{0});
    s.faces.push_back(std::move(f));
  }
  s.stresses = BuildNodalStressOperator(mesh, material, s.nodes) * Phi;
  return s;
}

void TransferSurfaceStresses(body_codec::Codec& c, ModalStressSurface& s, Eigen::Index ne) {
  const std::string root = "/stress/surface";
  H5File& h5 = c.h5();
  std::vector<std::string> types;
  if (c.writing()) {
    if (s.empty()) return;
    for (const CellBlock& b : s.faces) types.emplace_back(Name(b.type));
    h5.Write(root + "/face_types", types);
    h5.SetAttribute(root, "units", std::string("Pa per unit elastic coordinate"));
    h5.SetAttribute(root, "precision", std::string("modal: float32"));
  } else {
    s = ModalStressSurface{};
    if (!c.Exists(root)) return;
    types = h5.ReadStrings(root + "/face_types");
    for (const std::string& t : types) {
      const auto type = CellTypeFromName(t);
      EMB_THROW_IF(!type || Dimension(*type) != 2,
                   "'" << h5.path() << "': " << root << "/face_types: expected Tri3, Tri6, "
                       << "Quad4 or Quad8, got '" << t << "'");
      CellBlock b;
      b.type = *type;
      s.faces.push_back(std::move(b));
    }
  }
  for (const std::string& t : types) c.Text(t);
  c.Ints(root + "/nodes", s.nodes);
  const auto num = static_cast<Eigen::Index>(s.nodes.size());
  c.Matrix(root + "/coordinates", s.coordinates);
  c.ExpectShape(root + "/coordinates", s.coordinates, num, 3);
  for (CellBlock& b : s.faces) {
    const std::string path = root + "/faces/" + std::string(Name(b.type));
    c.IntTable(path, b.connectivity, static_cast<std::uint64_t>(b.nodes_per_cell()));
    b.tags.resize(b.connectivity.size() / static_cast<std::size_t>(b.nodes_per_cell()));
    std::iota(b.tags.begin(), b.tags.end(), std::size_t{0});
    EMB_THROW_IF(std::any_of(b.connectivity.begin(), b.connectivity.end(),
                             [&](int n) { return n < 0 || n >= num; }),
                 "'" << h5.path() << "': " << path << ": expected indices 0.." << num - 1
                     << " into " << root << "/nodes");
  }
  c.Matrix<float>(root + "/modal", s.stresses);
  c.ExpectShape(root + "/modal", s.stresses, 6 * num, ne);
  EMB_THROW_IF(!c.writing() && !(s.stresses.allFinite() && s.coordinates.allFinite()),
               "'" << h5.path() << "': " << root << ": holds a non-finite value (NaN or inf)");
}

}  // namespace emb
