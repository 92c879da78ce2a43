#pragma once
/// @file
/// XDMF (version 2) text describing a mesh and per-node vector fields stored in an HDF5 file,
/// so that ParaView shows emb results directly.

#include <string>
#include <vector>

#include "libemb/mesh/mesh.h"

namespace emb {

/// Cells of `block` re-ordered from gmsh's to VTK/XDMF's node order (row-major).
std::vector<int> VtkOrderedConnectivity(const CellBlock& block);
/// XDMF topology type name of a cell type (e.g. "Tet_10"). @throws InputError if none.
std::string XdmfTopologyName(CellType type);

/// An XDMF document with one grid per step: geometry at `h5_file`:/mesh/nodes, topology at
/// `h5_file`:/viz/<Type>, and the vector field `field_dataset` ([steps][n][3]) sliced per step
/// as the node attribute `field_name`. `step_values` are the XDMF times (e.g. mode numbers)
/// and `step_names` the grid names.
std::string MakeXdmfSteps(const std::string& h5_file, const Mesh& mesh,
                          const std::string& field_dataset, const std::string& field_name,
                          const std::vector<double>& step_values,
                          const std::vector<std::string>& step_names);

}  // namespace emb
