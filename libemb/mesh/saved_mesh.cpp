#include "libemb/mesh/saved_mesh.h"

#include <gmsh.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "libemb/common/error.h"
#include "libemb/mesh/gmsh_session.h"

namespace emb {
namespace {

namespace fs = std::filesystem;

// Nodes and volume elements of the current model.
void Count(const std::string& path, std::size_t* nodes, std::size_t* volume_elements) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, node_tags;
  std::vector<std::size_t> all_nodes;
  std::vector<double> coords, param;
  GmshCall("count the mesh of", path, [&] {
    gmsh::model::mesh::getElements(types, tags, node_tags, 3, -1);
    gmsh::model::mesh::getNodes(all_nodes, coords, param, -1, -1, false, false);
  });
  *volume_elements = 0;
  for (const auto& t : tags) *volume_elements += t.size();
  std::sort(all_nodes.begin(), all_nodes.end());
  *nodes = std::unique(all_nodes.begin(), all_nodes.end()) - all_nodes.begin();
}

}  // namespace

SavedMeshFile::SavedMeshFile(std::string target) : target_(std::move(target)) {
  const fs::path p(target_);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  EMB_THROW_IF(!fs::is_directory(dir, ec),
               "output '" << target_ << "': directory '" << dir.string() << "' does not exist");
  // gmsh picks the format from the extension, so the temporary name keeps it.
  temp_ = (dir / ("." + p.stem().string() + ".tmp" + p.extension().string())).string();
  cleanup_ = CleanupOnSignal(temp_);
  Count(target_, &nodes_, &volume_elements_);
  cleanup_.Create([&] { GmshCall("write", target_, [&] { gmsh::write(temp_); }); });
}

SavedMeshFile::~SavedMeshFile() {
  if (!committed_) cleanup_.Release([&] { std::remove(temp_.c_str()); });
}

void SavedMeshFile::Commit() {
  std::error_code ec;
  EMB_THROW_IF(fs::file_size(temp_, ec) == 0 || ec,
               "output '" << target_ << "': gmsh wrote nothing (disk full?)");
  std::size_t nodes = 0, volume_elements = 0;
  try {
    GmshSession session({});
    GmshOpen(temp_, /*trusted=*/false);
    Count(temp_, &nodes, &volume_elements);
  } catch (const InputError& e) {
    EMB_THROW(InputError, "output '" << target_ << "': the written mesh does not read back "
                                     << "(disk full or I/O error?): " << e.what());
  }
  const std::string ext = fs::path(target_).extension().string();
  const bool volumes = ext == ".msh" || ext == ".unv" || ext == ".vtk" || ext == ".bdf" ||
                       ext == ".nas" || ext == ".mesh";
  EMB_THROW_IF(volumes && (nodes != nodes_ || volume_elements != volume_elements_),
               "output '" << target_ << "': the written mesh reads back with " << nodes
                          << " nodes and " << volume_elements << " volume elements instead of "
                          << nodes_ << " and " << volume_elements_
                          << " (disk full or I/O error?)");
  cleanup_.Release([&] {
    if (std::rename(temp_.c_str(), target_.c_str()) != 0)
      EMB_THROW(InputError,
                "output '" << target_ << "': could not move the written mesh into place");
  });
  committed_ = true;
}

}  // namespace emb
