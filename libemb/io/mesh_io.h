#pragma once
/// @file
/// Mesh and provenance sections shared by emb's HDF5 files (see modes_file.h for the layout).

#include "libemb/io/hdf5_file.h"
#include "libemb/io/provenance.h"
#include "libemb/mesh/mesh.h"

namespace emb {

/// Writes /mesh/{nodes, node_tags, cells/<Type>, cell_tags/<Type>, groups/<name>} and
/// /viz/<Type> (VTK node order) with @source and @hash on /mesh.
void WriteMesh(H5File& h5, const Mesh& mesh);
/// Reads back what WriteMesh wrote (groups without face cells).
Mesh ReadMeshSection(const H5File& h5);
/// Writes the /provenance attributes.
void WriteProvenance(H5File& h5, const Provenance& p);

}  // namespace emb
