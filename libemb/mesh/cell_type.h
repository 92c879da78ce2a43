#pragma once
/// @file
/// Cell (element) types emb understands, with their gmsh element-type codes.
/// Node ordering is gmsh's for every type (checked against gmsh's own reference
/// coordinates in tests/fe/reference_element_test.cpp).

#include <optional>
#include <string_view>

namespace emb {

enum class CellType {
  kTri3, kTri6, kQuad4, kQuad8,                          // surfaces (interface groups)
  kTet4, kTet10, kHex8, kHex20, kWedge6, kWedge15,       // solids
};

/// Number of nodes of a cell of type `t`.
int NumNodes(CellType t);
/// Topological dimension (2 for surfaces, 3 for solids).
int Dimension(CellType t);
/// Human-readable name, e.g. "Tet10".
std::string_view Name(CellType t);
/// gmsh's element-type code (e.g. 11 for Tet10).
int GmshCode(CellType t);
/// The CellType of a gmsh element-type code, or nullopt if emb does not support it.
std::optional<CellType> CellTypeFromGmsh(int gmsh_code);
/// The CellType called `name` (case-insensitive, e.g. "tet10"), or nullopt.
std::optional<CellType> CellTypeFromName(std::string_view name);

}  // namespace emb
