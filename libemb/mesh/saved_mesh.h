#pragma once
/// @file
/// `--save-mesh`: the mesh gmsh made, written through gmsh (format from the extension) to a
/// temporary beside the target and renamed over it only after it was read back and holds
/// what was written. gmsh does not report failed writes (a full disk leaves a truncated file
/// and no error), so the read-back is the check. Include only where gmsh.h is linked.

#include <cstddef>
#include <string>

#include "libemb/common/signal_cleanup.h"

namespace emb {

class SavedMeshFile {
 public:
  /// Writes the mesh of the current gmsh session's model (call inside a GmshSession).
  /// @throws InputError if the directory does not exist or gmsh reports an error.
  explicit SavedMeshFile(std::string target);
  /// Removes the temporary unless Commit() succeeded.
  ~SavedMeshFile();
  SavedMeshFile(const SavedMeshFile&) = delete;
  SavedMeshFile& operator=(const SavedMeshFile&) = delete;

  /// Reads the temporary back in a new gmsh session (call after the writing session ended)
  /// and renames it over the target if it reads without error and, for formats that store
  /// volume elements (.msh, .unv, .vtk, .bdf, .nas, .mesh), holds as many nodes and volume
  /// elements as the model had. @throws InputError otherwise (the target is left as it was).
  void Commit();

 private:
  std::string target_, temp_;
  std::size_t nodes_{0}, volume_elements_{0};
  CleanupOnSignal cleanup_;
  bool committed_{false};
};

}  // namespace emb
