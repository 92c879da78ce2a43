#include "libemb/mesh/mesh.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>

#include "libemb/common/error.h"

namespace emb {

int Mesh::num_cells() const {
  int n = 0;
  for (const auto& b : blocks) n += b.num_cells();
  return n;
}

const PhysicalGroup& Mesh::group(const std::string& name) const {
  for (const auto& g : groups)
    if (g.name == name) return g;
  EMB_THROW(InputError, "mesh '" << source << "': unknown physical group '" << name
                                 << "'; expected one of: " << GroupNames());
}

std::string Mesh::GroupNames() const {
  if (groups.empty()) return "(none: the mesh has no physical groups)";
  std::string s;
  for (const auto& g : groups) {
    if (!s.empty()) s += ", ";
    s += g.name + (g.dim == 2 ? " (surface)" : g.dim == 3 ? " (volume)" : " (other)");
  }
  return s;
}

std::string Mesh::Summary() const {
  std::ostringstream oss;
  oss << num_nodes() << " nodes";
  std::map<std::string_view, int> counts;
  for (const auto& b : blocks) counts[Name(b.type)] += b.num_cells();
  for (const auto& [name, n] : counts) oss << ", " << n << " " << name;
  return oss.str();
}

std::string MeshHash(const Mesh& mesh) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      h ^= p[i];
      h *= 1099511628211ull;
    }
  };
  // Coordinates are hashed rounded to 1e-9 of the mesh size, so that a mesh written to a text
  // format (e.g. .msh, 16 digits) and read back has the same hash as the one in memory.
  const double size =
      mesh.num_nodes() ? (mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff()).norm() : 1.0;
  const double quantum = (size > 0 ? size : 1.0) * 1e-9;
  for (Eigen::Index k = 0; k < mesh.nodes.size(); ++k) {
    const long long q = std::llround(mesh.nodes.data()[k] / quantum);
    mix(&q, sizeof q);
  }
  for (const auto& b : mesh.blocks) {
    const int code = GmshCode(b.type);
    mix(&code, sizeof code);
    mix(b.connectivity.data(), sizeof(int) * b.connectivity.size());
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace emb
