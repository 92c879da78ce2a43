#include "libemb/mesh/gmsh_reader.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "libemb/common/error.h"
#include "libemb/mesh/geo_lexer.h"
#include "libemb/mesh/gmsh_input_audit.h"
#include "libemb/mesh/gmsh_session.h"
#include "libemb/mesh/saved_mesh.h"

namespace emb {
namespace {

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string Extension(const std::string& path) {
  return Lower(std::filesystem::path(path).extension().string());
}

// Node tag -> 0-based index of a node of a solid cell (negative: none). Dense while the tags
// are nearly contiguous; a hash map when the largest tag is far beyond the node count (a file
// may number its nodes up to 1e12), so memory follows the nodes, not the largest tag.
class TagIndex {
 public:
  static constexpr int kNone = -1, kUsed = -2;
  TagIndex(std::size_t max_tag, std::size_t count) : dense_(max_tag <= 4 * count + 1024) {
    if (dense_) v_.assign(max_tag + 1, kNone);
  }
  int operator[](std::size_t t) const {
    if (dense_) return t < v_.size() ? v_[t] : kNone;
    const auto it = m_.find(t);
    return it == m_.end() ? kNone : it->second;
  }
  void Set(std::size_t t, int i) {
    if (dense_)
      v_[t] = i;
    else
      m_[t] = i;
  }

 private:
  bool dense_;
  std::vector<int> v_;
  std::unordered_map<std::size_t, int> m_;
};

CellBlock MakeBlock(int gmsh_type, const std::vector<std::size_t>& tags,
                    const std::vector<std::size_t>& node_tags,
                    const TagIndex& index_of_tag, const std::string& path) {
  auto type = CellTypeFromGmsh(gmsh_type);
  if (!type) {
    std::string name;
    int dim = 0, order = 0, nn = 0, np = 0;
    std::vector<double> coords;
    gmsh::model::mesh::getElementProperties(gmsh_type, name, dim, order, nn, coords, np);
    EMB_THROW(InputError, "mesh '" << path << "': unsupported element type '" << name
                                   << "' (gmsh type " << gmsh_type
                                   << "); expected Tet4, Tet10, Hex8, Hex20, Wedge6, Wedge15 "
                                      "(solids) or Tri3, Tri6, Quad4, Quad8 (surfaces)");
  }
  CellBlock b;
  b.type = *type;
  b.tags = tags;
  b.connectivity.resize(node_tags.size());
  for (size_t k = 0; k < node_tags.size(); ++k) {
    const std::size_t t = node_tags[k];
    const int idx = index_of_tag[t];
    EMB_THROW_IF(idx < 0, "mesh '" << path << "': element " << tags[k / NumNodes(b.type)]
                                   << " uses node " << t << " which is not a node of a solid cell");
    b.connectivity[k] = idx;
  }
  return b;
}

// gmsh reads a mesh file with a node or element number given twice by keeping one of them and
// only logging it; emb refuses the file (which of the two is meant is not known).
// The MSH2 reader keeps the last of two elements numbered alike without a word; its log
// line "N elements" (the count the file declares) then exceeds the elements gmsh holds.
void RefuseDuplicates(const std::string& path) {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  long long declared = -1;
  for (const std::string& line : log) {
    for (const char* what : {"duplicate node", "duplicate element"}) {
      const auto at = line.find(std::string("Skipping ") + what);
      if (at == std::string::npos) continue;
      EMB_THROW(InputError, "mesh '" << path << "': " << (what + 10)
                                     << line.substr(at + 9 + std::string(what).size())
                                     << " is defined twice; expected unique numbers");
    }
    long long n = 0;
    char tail[16] = {};
    if (std::sscanf(line.c_str(), "Info: %lld element%15s", &n, tail) == 2 &&
        std::string(tail) == "s")
      declared = n;
  }
  if (declared < 0 || Extension(path) != ".msh") return;
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  GmshCall("read elements of", path,
           [&] { gmsh::model::mesh::getElements(types, tags, nodes, -1, -1); });
  long long held = 0;
  for (const auto& t : tags) held += static_cast<long long>(t.size());
  EMB_THROW_IF(held < declared, "mesh '" << path << "' declares " << declared
                                         << " elements but only " << held
                                         << " have distinct numbers: an element is defined "
                                            "twice; expected unique numbers");
}

// Refuses a mesh size that would make more than kMaxEstimatedElements elements, from the
// volume and surface area of the OpenCASCADE model (the bounding box for built-in-kernel
// geometry, which over-estimates).
void CheckElementEstimate(const std::string& path, double size) {
  double volume = 0.0, area = 0.0;
  gmsh::vectorpair volumes, surfaces;
  GmshCall("measure", path, [&] {
    gmsh::model::occ::getEntities(volumes, 3);
    gmsh::model::occ::getEntities(surfaces, 2);
    for (const auto& [dim, tag] : volumes) {
      double m = 0.0;
      gmsh::model::occ::getMass(dim, tag, m);
      volume += m;
    }
    for (const auto& [dim, tag] : surfaces) {
      double m = 0.0;
      gmsh::model::occ::getMass(dim, tag, m);
      area += m;
    }
    if (volumes.empty()) {
      double x0, y0, z0, x1, y1, z1;
      gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
      const double a = x1 - x0, b = y1 - y0, c = z1 - z0;
      volume = a * b * c;
      area = 2.0 * (a * b + b * c + c * a);
    }
  });
  const double estimate = EstimateTetrahedra(volume, area, size);
  EMB_THROW_IF(estimate > kMaxEstimatedElements,
               "meshing '" << path << "' at size " << size << " m would make about "
                           << static_cast<long long>(estimate) << " elements (estimated from "
                           << (volumes.empty() ? "the bounding box: " : "") << "volume "
                           << volume << " m^3 and surface " << area
                           << " m^2); the limit is " << static_cast<long long>(kMaxEstimatedElements)
                           << ": use a larger --size, or --force to mesh anyway");
}

}  // namespace

double EstimateTetrahedra(double volume, double area, double size) {
  return 4.0 * volume / (size * size * size) + 4.5 * area / (size * size);
}

bool IsGeometryFile(const std::string& path) {
  static const char* kGeometry[] = {".geo", ".brep", ".step", ".stp", ".iges", ".igs", ".xao"};
  const std::string ext = Extension(path);
  return std::any_of(std::begin(kGeometry), std::end(kGeometry),
                     [&](const char* g) { return ext == g; });
}

std::vector<std::pair<std::string, double>> GeoParameters(const std::string& path) {
  if (Extension(path) != ".geo") return {};
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return DefineConstantParameters(LexGeoScript(ss.str(), path));
}

Mesh ReadMesh(const std::string& path, const MeshingOptions& options, const ProgressFn& progress) {
  namespace fs = std::filesystem;
  std::error_code ec;
  EMB_THROW_IF(!fs::exists(path, ec), "mesh file '" << path << "' does not exist");
  EMB_THROW_IF(!fs::is_regular_file(path, ec), "mesh file '" << path << "' is not a regular file");
  {
    std::ifstream probe(path);
    EMB_THROW_IF(!probe.good(), "mesh file '" << path << "' cannot be read (permissions?)");
  }
  EMB_THROW_IF(options.order != 1 && options.order != 2,
               "meshing order: expected 1 or 2, got " << options.order);
  EMB_THROW_IF(!(std::isfinite(options.size) && options.size >= 0.0),
               "mesh size: expected > 0 m (or 0 for the file's default), got " << options.size
                                                                               << " m");
  // Before anything reads the file as a script: what gmsh would run while reading it.
  if (!options.trust_scripts) AuditGmshInput(path);

  const bool geometry = IsGeometryFile(path);
  std::vector<std::string> args;
  if (geometry && Extension(path) == ".geo") {
    const auto known = GeoParameters(path);
    auto overrides = options.parameters;
    if (options.size > 0.0) overrides.emplace_back("h", options.size);
    // `order` is passed only if the file declares it; the option is set after opening anyway.
    if (std::any_of(known.begin(), known.end(), [](const auto& k) { return k.first == "order"; }))
      overrides.emplace_back("order", options.order);
    // beam_parts = 1 (crankshaft_i4.geo, tube.geo) leaves the parts unfused: geometry for the
    // beam generator, not a solid to mesh.
    for (const auto& [name, value] : overrides)
      EMB_THROW_IF(name == "beam_parts" && value != 0.0,
                   "geometry '" << path << "': parameter beam_parts = " << value
                                << " is for the beam generator (libemb/beam); expected 0 when "
                                   "meshing the solid");
    args = GeoParameterArgs(path, overrides);
  } else {
    EMB_THROW_IF(!options.parameters.empty(),
                 "parameters can only be set for .geo geometry files, not '" << path << "'");
  }

  Mesh mesh;
  std::optional<SavedMeshFile> saved;
  {
  GmshSession session(args);
  ReportProgress(progress, geometry ? "meshing" : "reading mesh", 0.0);
  GmshOpen(path, /*trusted=*/true, /*time_limited=*/!options.trust_scripts);  // audited above
  if (geometry && options.size > 0.0 && !options.force) CheckElementEstimate(path, options.size);
  if (geometry) {
    GmshCall("mesh", path, [&] {
      gmsh::option::setNumber("Mesh.ElementOrder", options.order);
      if (options.size > 0.0 && Extension(path) != ".geo")
        gmsh::option::setNumber("Mesh.MeshSizeMax", options.size);
      gmsh::model::mesh::generate(3);
    });
  }
  ReportProgress(progress, geometry ? "meshing" : "reading mesh", 0.5);
  RefuseDuplicates(path);
  if (!options.save_as.empty()) saved.emplace(options.save_as);
  mesh.source = path;

  // Solid cells first: they decide which nodes exist.
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elem_tags, elem_nodes;
  GmshCall("read elements of", path,
           [&] { gmsh::model::mesh::getElements(types, elem_tags, elem_nodes, 3, -1); });
  std::size_t max_tag = 0;
  for (const auto& nodes : elem_nodes)
    for (auto t : nodes) max_tag = std::max(max_tag, t);
  EMB_THROW_IF(types.empty() || max_tag == 0,
               "mesh '" << path << "' has no volume elements; expected a 3-D solid mesh");

  std::vector<std::size_t> node_tags;
  std::vector<double> coords, param;
  GmshCall("read nodes of", path,
           [&] { gmsh::model::mesh::getNodes(node_tags, coords, param, -1, -1, true, false); });
  std::size_t all_max = max_tag;
  for (auto t : node_tags) all_max = std::max(all_max, t);
  TagIndex index_of_tag(all_max, node_tags.size());
  // Number the nodes of solid cells in the order gmsh lists them.
  for (const auto& nodes : elem_nodes)
    for (auto t : nodes) index_of_tag.Set(t, TagIndex::kUsed);
  int n = 0;
  for (auto t : node_tags)
    if (index_of_tag[t] == TagIndex::kUsed) index_of_tag.Set(t, n++);
  mesh.nodes.resize(3, n);
  mesh.node_tags.resize(n);
  std::vector<char> placed(n, 0);
  for (size_t k = 0; k < node_tags.size(); ++k) {
    const int i = index_of_tag[node_tags[k]];
    if (i < 0) continue;
    const Eigen::Vector3d x(coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]);
    // gmsh lists a node once per entity it bounds (same node, same place); one id at two
    // places is a broken file.
    EMB_THROW_IF(placed[i] && mesh.nodes.col(i) != x,
                 "mesh '" << path << "': node " << node_tags[k]
                          << " is defined twice at different places; expected unique node ids");
    EMB_THROW_IF(!x.allFinite(), "mesh '" << path << "': node " << node_tags[k]
                                          << " has a non-finite coordinate (" << x.transpose()
                                          << "); expected finite coordinates [m]");
    placed[i] = 1;
    mesh.nodes.col(i) = x;
    mesh.node_tags[i] = node_tags[k];
  }
  for (size_t b = 0; b < types.size(); ++b) {
    // Merge blocks of the same type coming from different volumes.
    CellBlock block = MakeBlock(types[b], elem_tags[b], elem_nodes[b], index_of_tag, path);
    auto it = std::find_if(mesh.blocks.begin(), mesh.blocks.end(),
                           [&](const CellBlock& x) { return x.type == block.type; });
    if (it == mesh.blocks.end()) {
      mesh.blocks.push_back(std::move(block));
    } else {
      it->tags.insert(it->tags.end(), block.tags.begin(), block.tags.end());
      it->connectivity.insert(it->connectivity.end(), block.connectivity.begin(),
                              block.connectivity.end());
    }
  }
  for (const auto& b : mesh.blocks)
    EMB_THROW_IF(Dimension(b.type) != 3, "mesh '" << path << "': expected solid cells in the "
                                                  << "volume, got " << Name(b.type));

  // Physical groups.
  gmsh::vectorpair groups;
  GmshCall("read physical groups of", path, [&] { gmsh::model::getPhysicalGroups(groups, -1); });
  for (const auto& [dim, tag] : groups) {
    PhysicalGroup g;
    g.dim = dim;
    gmsh::model::getPhysicalName(dim, tag, g.name);
    if (g.name.empty()) g.name = "group_" + std::to_string(dim) + "_" + std::to_string(tag);
    std::vector<std::size_t> gnodes;
    std::vector<double> gcoords;
    gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, gnodes, gcoords);
    for (auto t : gnodes) {
      const int i = index_of_tag[t];
      if (i >= 0) g.nodes.push_back(i);
    }
    std::sort(g.nodes.begin(), g.nodes.end());
    g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
    if (dim == 2) {
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
      for (int e : entities) {
        std::vector<int> ftypes;
        std::vector<std::vector<std::size_t>> ftags, fnodes;
        gmsh::model::mesh::getElements(ftypes, ftags, fnodes, 2, e);
        for (size_t b = 0; b < ftypes.size(); ++b)
          g.faces.push_back(MakeBlock(ftypes[b], ftags[b], fnodes[b], index_of_tag, path));
      }
    }
    mesh.groups.push_back(std::move(g));
  }
  }  // the gmsh session ends here: the saved mesh is read back in a new one
  if (saved) saved->Commit();
  ReportProgress(progress, geometry ? "meshing" : "reading mesh", 1.0);
  return mesh;
}

}  // namespace emb
