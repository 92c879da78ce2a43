#include "libemb/mesh/cell_type.h"

#include <array>
#include <cctype>

namespace emb {
namespace {

struct CellInfo {
  CellType type;
  std::string_view name;
  int num_nodes;
  int dim;
  int gmsh_code;
};

constexpr std::array<CellInfo, 10> kCells{{
    {CellType::kTri3, "Tri3", 3, 2, 2},
    {CellType::kTri6, "Tri6", 6, 2, 9},
    {CellType::kQuad4, "Quad4", 4, 2, 3},
    {CellType::kQuad8, "Quad8", 8, 2, 16},
    {CellType::kTet4, "Tet4", 4, 3, 4},
    {CellType::kTet10, "Tet10", 10, 3, 11},
    {CellType::kHex8, "Hex8", 8, 3, 5},
    {CellType::kHex20, "Hex20", 20, 3, 17},
    {CellType::kWedge6, "Wedge6", 6, 3, 6},
    {CellType::kWedge15, "Wedge15", 15, 3, 18},
}};

const CellInfo& Info(CellType t) { return kCells[static_cast<int>(t)]; }

}  // namespace

int NumNodes(CellType t) { return Info(t).num_nodes; }
int Dimension(CellType t) { return Info(t).dim; }
std::string_view Name(CellType t) { return Info(t).name; }
int GmshCode(CellType t) { return Info(t).gmsh_code; }

std::optional<CellType> CellTypeFromGmsh(int gmsh_code) {
  for (const auto& c : kCells)
    if (c.gmsh_code == gmsh_code) return c.type;
  return std::nullopt;
}

std::optional<CellType> CellTypeFromName(std::string_view name) {
  for (const auto& c : kCells) {
    if (c.name.size() != name.size()) continue;
    bool same = true;
    for (size_t i = 0; i < name.size(); ++i)
      same &= std::tolower(static_cast<unsigned char>(name[i])) ==
              std::tolower(static_cast<unsigned char>(c.name[i]));
    if (same) return c.type;
  }
  return std::nullopt;
}

}  // namespace emb
