#include "libemb/io/xdmf_writer.h"

#include <sstream>

#include "libemb/common/error.h"

namespace emb {
namespace {

// For VTK position v, the gmsh position of the same node.
const std::vector<int>& GmshIndexOfVtk(CellType t) {
  static const std::vector<int> tet10{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
  static const std::vector<int> hex20{0, 1, 2,  3,  4,  5,  6,  7,  8,  11,
                                      13, 9, 16, 18, 19, 17, 10, 12, 14, 15};
  static const std::vector<int> wedge15{0, 1, 2, 3, 4, 5, 6, 9, 7, 12, 14, 13, 8, 10, 11};
  static const std::vector<int> identity{};
  switch (t) {
    case CellType::kTet10: return tet10;
    case CellType::kHex20: return hex20;
    case CellType::kWedge15: return wedge15;
    default: return identity;
  }
}

}  // namespace

std::vector<int> VtkOrderedConnectivity(const CellBlock& block) {
  const auto& map = GmshIndexOfVtk(block.type);
  if (map.empty()) return block.connectivity;
  const int k = block.nodes_per_cell();
  std::vector<int> out(block.connectivity.size());
  for (int c = 0; c < block.num_cells(); ++c)
    for (int v = 0; v < k; ++v) out[std::size_t(c) * k + v] = block.cell(c)[map[v]];
  return out;
}

std::string XdmfTopologyName(CellType type) {
  switch (type) {
    case CellType::kTet4: return "Tetrahedron";
    case CellType::kTet10: return "Tet_10";
    case CellType::kHex8: return "Hexahedron";
    case CellType::kHex20: return "Hex_20";
    case CellType::kWedge6: return "Wedge";
    case CellType::kWedge15: return "Wedge_15";
    case CellType::kTri3: return "Triangle";
    case CellType::kTri6: return "Tri_6";
    case CellType::kQuad4: return "Quadrilateral";
    case CellType::kQuad8: return "Quad_8";
  }
  EMB_THROW(InputError, "no XDMF topology for " << Name(type));
}

std::string MakeXdmfSteps(const std::string& h5, const Mesh& mesh, const std::string& field,
                          const std::string& field_name, const std::vector<double>& values,
                          const std::vector<std::string>& names) {
  EMB_CHECK(values.size() == names.size());
  const int n = mesh.num_nodes();
  const std::size_t steps = values.size();
  std::ostringstream x;
  x.precision(12);
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n"
    << "  <Grid Name=\"steps\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t s = 0; s < steps; ++s) {
    x << "   <Grid Name=\"" << names[s] << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "    <Time Value=\"" << values[s] << "\"/>\n";
    for (const auto& b : mesh.blocks) {
      const std::string type(Name(b.type));
      x << "    <Grid Name=\"" << type << "\" GridType=\"Uniform\">\n"
        << "     <Topology TopologyType=\"" << XdmfTopologyName(b.type) << "\" NumberOfElements=\""
        << b.num_cells() << "\">\n"
        << "      <DataItem Dimensions=\"" << b.num_cells() << " " << b.nodes_per_cell()
        << "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" << h5 << ":/viz/" << type
        << "</DataItem>\n     </Topology>\n"
        << "     <Geometry GeometryType=\"XYZ\">\n      <DataItem Dimensions=\"" << n
        << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5
        << ":/mesh/nodes</DataItem>\n     </Geometry>\n"
        << "     <Attribute Name=\"" << field_name
        << "\" AttributeType=\"Vector\" Center=\"Node\">\n"
        << "      <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << n << " 3\">\n"
        << "       <DataItem Dimensions=\"3 3\" Format=\"XML\">" << s << " 0 0 1 1 1 1 " << n
        << " 3</DataItem>\n"
        << "       <DataItem Dimensions=\"" << steps << " " << n
        << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":" << field
        << "</DataItem>\n      </DataItem>\n     </Attribute>\n    </Grid>\n";
    }
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  return x.str();
}

}  // namespace emb
