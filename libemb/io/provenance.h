#pragma once
/// @file
/// What a result was made from, stored with it so that a stale file can be recognised.

#include <string>

namespace emb {

struct Provenance {
  std::string command;      ///< the command line that produced the file
  std::string source;       ///< mesh or geometry file
  std::string mesh_hash;    ///< MeshHash of the mesh used
  std::string options;      ///< meshing/solver options, "key=value; ..." as given
};

}  // namespace emb
