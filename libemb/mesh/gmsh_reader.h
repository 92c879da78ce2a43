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
};

/// True when `path` names a geometry gmsh meshes (by its extension), false for a mesh file.
bool IsGeometryFile(const std::string& path);

/// Reads (or meshes) `path` and returns its solid cells, nodes and physical groups.
/// Only nodes used by solid cells are kept, numbered 0..n-1.
/// @throws InputError if the file is missing or unreadable, gmsh fails, the mesh has no
///         volume cells, it has a solid cell type emb does not support (named), or a
///         parameter override names no parameter of the file.
Mesh ReadMesh(const std::string& path, const MeshingOptions& options = {},
              const ProgressFn& progress = {});

/// The `DefineConstant` parameters a .geo file declares, with their default values,
/// in the order they appear. Empty for other files.
std::vector<std::pair<std::string, double>> GeoParameters(const std::string& path);

}  // namespace emb
