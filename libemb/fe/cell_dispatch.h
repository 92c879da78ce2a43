#pragma once
/// @file
/// Runtime CellType → compile-time element kernel.

#include <cstddef>
#include <string>
#include <type_traits>

#include "libemb/common/error.h"
#include "libemb/mesh/cell_type.h"

namespace emb {

/// Calls f(std::integral_constant<CellType, T>{}) for the solid type t.
template <typename F>
decltype(auto) DispatchSolid(CellType t, F&& f) {
  switch (t) {
    case CellType::kTet4: return f(std::integral_constant<CellType, CellType::kTet4>{});
    case CellType::kTet10: return f(std::integral_constant<CellType, CellType::kTet10>{});
    case CellType::kHex8: return f(std::integral_constant<CellType, CellType::kHex8>{});
    case CellType::kHex20: return f(std::integral_constant<CellType, CellType::kHex20>{});
    case CellType::kWedge6: return f(std::integral_constant<CellType, CellType::kWedge6>{});
    case CellType::kWedge15: return f(std::integral_constant<CellType, CellType::kWedge15>{});
    default: break;
  }
  EMB_THROW(InputError, "expected a solid cell type, got " << Name(t));
}

/// Throws InputError naming the cell if its smallest Jacobian determinant `min_det` is not
/// positive (inverted) or negligible against its size³ (degenerate). `size` is the diagonal
/// of the cell's bounding box [m]. 1e-12·size³ is far below any usable cell: a sliver with
/// that ratio would make K ill-conditioned beyond double precision.
inline void CheckCellJacobian(const std::string& mesh_source, CellType type, std::size_t tag,
                              double min_det, double size) {
  if (min_det > 1e-12 * size * size * size) return;
  EMB_THROW(InputError, "mesh '" << mesh_source << "': element " << tag << " (" << Name(type)
                                 << ") is " << (min_det <= 0.0 ? "inverted" : "degenerate")
                                 << ": Jacobian determinant " << min_det
                                 << " at a quadrature point (cell size " << size
                                 << " m); expected > 0");
}

}  // namespace emb
