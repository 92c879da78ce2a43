#pragma once
/// @file
/// The modes file (HDF5) written by `emb modes`, with an XDMF companion for ParaView.
/// Schema (format "emb.modes", version 1; SI units):
///   /                      @format, @format_version, @emb_version, @units
///   /provenance            @command, @source, @mesh_hash, @options
///   /material              @name, @youngs_modulus [Pa], @poisson_ratio, @density [kg/m^3]
///   /mesh/nodes            [n][3] float64, node coordinates [m]
///   /mesh/node_tags        [n] uint64, the mesh file's node tags
///   /mesh/cells/<Type>     [c][k] int32, 0-based node indices in gmsh order (Type: Tet10, ...)
///   /mesh/cell_tags/<Type> [c] uint64, the mesh file's element tags
///   /mesh/groups/<name>    [g] int32, node indices of a physical group (@dim)
///   /modes/frequencies_hz  [m] float64 [Hz], ascending (rigid modes ~0, signed)
///   /modes/eigenvalues     [m] float64, λ = ω² [rad²/s²]
///   /modes/shapes          [m][n][3] float64, mass-normalised: Φᵀ M Φ = I [1/√kg]
///   /modes/backward_errors [m] float64, η_i (see linalg/eigen_solver.h)
///   /modes                 @status, @message, @num_rigid_modes, @rigid_threshold, @shift,
///                          @method, @iterations, @num_solves, @orthonormality_error,
///                          @factorisation, @nnz_factor
///   /viz/<Type>            [c][k] int32, the cells in VTK node order (read by the .xdmf)

#include <string>

#include "libemb/fe/material.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/io/provenance.h"
#include "libemb/mesh/mesh.h"

namespace emb {

inline constexpr const char* kModesFormat = "emb.modes";
inline constexpr int kModesFormatVersion = 1;

/// Writes the modes file `path` and, unless `xdmf_path` is empty, the XDMF file that shows
/// each mode as a time step in ParaView (it refers to `path` by its file name). Both are
/// written atomically. @throws InputError if a file cannot be written.
void WriteModesFile(const std::string& path, const std::string& xdmf_path, const Mesh& mesh,
                    const IsotropicMaterial& material, const ModalResult& modes,
                    const Provenance& provenance);

}  // namespace emb
