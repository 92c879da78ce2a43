#pragma once
/// @file
/// Reading meshes and meshing geometries through the gmsh SDK (gmsh.h).
///
/// Mesh files (.msh v2/v4, .unv, .bdf/.nas, .inp, .mesh, ...) are read as they are.
/// Geometry files (.geo, .brep, .step/.stp, .iges/.igs) are meshed in 3-D first, with the
/// order and size asked for. Physical groups (named surfaces and volumes) come along.

#include <string>
#include <utility>
#include <vector>

#include "libemb/common/progress.h"
#include "libemb/mesh/mesh.h"

namespace emb {

/// How to mesh a geometry file (ignored for mesh files, except where stated).
struct MeshingOptions {
  int order{2};        ///< element order, 1 (Tet4/Hex8) or 2 (Tet10/Hex20, curved to the geometry)
  double size{0.0};    ///< characteristic length [m]; 0 keeps the geometry's own default.
                       ///< For .geo files this sets the parameter `h`.
  /// Parameter overrides for .geo files, as `DefineConstant` names and values
  /// (e.g. {"stroke", 0.09}). A name the file does not define is an InputError.
  std::vector<std::pair<std::string, double>> parameters;
  /// If set, gmsh also writes the mesh it read or made to this file (format from the
  /// extension, e.g. .msh), atomically.
  std::string save_as;
  /// Give the file to gmsh without auditing it first (gmsh_input_audit.h): only for files
  /// the user trusts, since a .geo script can run commands and write or delete files.
  bool trust_scripts{false};
  /// Mesh even when the element estimate for `size` exceeds kMaxEstimatedElements.
  bool force{false};
};

/// Largest number of volume elements emb meshes for a `size` without MeshingOptions::force
/// (about 4.5 million unknowns with Tet10: more than the memory of the machines emb targets
/// holds for the assembly and factorisation).
inline constexpr double kMaxEstimatedElements = 1.5e6;

/// A rough count of the tetrahedra gmsh makes of a part of volume V [m³] and surface area
/// A [m²] at mesh size h [m]: 4 V/h³ (the bulk) + 4.5 A/h² (the layer under the surface
/// triangles, which dominates for thin walls). Fitted to emb's parts (Tet10, measured: the
/// crankshafts at h = 6…20 mm and the Tet tube at 15 mm come out at 0.6…1.3 × the estimate).
double EstimateTetrahedra(double volume, double area, double size);

/// True when `path` names a geometry gmsh meshes (by its extension), false for a mesh file.
bool IsGeometryFile(const std::string& path);

/// Reads (or meshes) `path` and returns its solid cells, nodes and physical groups.
/// Only nodes used by solid cells are kept, numbered 0..n-1.
/// @throws InputError if the file is missing or unreadable, the audit refuses it (unless
///         trusted), gmsh fails, the mesh has no volume cells, it has a solid cell type emb
///         does not support (named), a parameter override names no parameter of the file or
///         is not finite, or `size` would make more than kMaxEstimatedElements elements
///         (unless forced).
Mesh ReadMesh(const std::string& path, const MeshingOptions& options = {},
              const ProgressFn& progress = {});

/// The `DefineConstant` parameters a .geo file declares, with their default values (NaN for
/// an expression), in the order they appear (geo_lexer.h). Empty for other files.
/// @throws InputError for a file gmsh's lexer would misread (NUL byte, over-long string).
std::vector<std::pair<std::string, double>> GeoParameters(const std::string& path);

}  // namespace emb
