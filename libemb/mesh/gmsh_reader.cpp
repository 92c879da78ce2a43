#include "libemb/mesh/gmsh_reader.h"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <unordered_map>

#include "libemb/common/error.h"
#include "libemb/mesh/gmsh_session.h"

namespace emb {
namespace {

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string Extension(const std::string& path) {
  return Lower(std::filesystem::path(path).extension().string());
}

CellBlock MakeBlock(int gmsh_type, const std::vector<std::size_t>& tags,
                    const std::vector<std::size_t>& node_tags,
                    const std::vector<int>& index_of_tag, const std::string& path) {
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
    const int idx = t < index_of_tag.size() ? index_of_tag[t] : -1;
    EMB_THROW_IF(idx < 0, "mesh '" << path << "': element " << tags[k / NumNodes(b.type)]
                                   << " uses node " << t << " which is not a node of a solid cell");
    b.connectivity[k] = idx;
  }
  return b;
}

// gmsh picks the format from the extension, so the temporary name keeps it.
void SaveMesh(const std::string& target) {
  namespace fs = std::filesystem;
  const fs::path p(target);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  EMB_THROW_IF(!fs::is_directory(dir, ec),
               "output '" << target << "': directory '" << dir.string() << "' does not exist");
  const fs::path tmp = dir / ("." + p.stem().string() + ".tmp" + p.extension().string());
  GmshCall("write", target, [&] { gmsh::write(tmp.string()); });
  fs::rename(tmp, p, ec);
  if (ec) {
    fs::remove(tmp, ec);
    EMB_THROW(InputError, "output '" << target << "': could not move the written mesh into place");
  }
}

}  // namespace

bool IsGeometryFile(const std::string& path) {
  static const char* kGeometry[] = {".geo", ".brep", ".step", ".stp", ".iges", ".igs", ".xao"};
  const std::string ext = Extension(path);
  return std::any_of(std::begin(kGeometry), std::end(kGeometry),
                     [&](const char* g) { return ext == g; });
}

std::vector<std::pair<std::string, double>> GeoParameters(const std::string& path) {
  std::vector<std::pair<std::string, double>> out;
  if (Extension(path) != ".geo") return out;
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  // Inside DefineConstant[ ... ]: entries of the form `name = {value, ...}`.
  static const std::regex kBlock(R"(DefineConstant\s*\[([\s\S]*?)\]\s*;)");
  static const std::regex kEntry(R"(([A-Za-z_]\w*)\s*=\s*\{\s*([-+0-9.eE]+))");
  for (auto b = std::sregex_iterator(text.begin(), text.end(), kBlock); b != std::sregex_iterator();
       ++b) {
    const std::string body = (*b)[1];
    for (auto e = std::sregex_iterator(body.begin(), body.end(), kEntry);
         e != std::sregex_iterator(); ++e)
      out.emplace_back((*e)[1], std::stod((*e)[2]));
  }
  return out;
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
  EMB_THROW_IF(options.size < 0.0, "mesh size: expected > 0 (or 0 for the file's default), got "
                                       << options.size);

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

  GmshSession session(args);
  ReportProgress(progress, geometry ? "meshing" : "reading mesh", 0.0);
  GmshCall("open", path, [&] { gmsh::open(path); });
  if (geometry) {
    GmshCall("mesh", path, [&] {
      gmsh::option::setNumber("Mesh.ElementOrder", options.order);
      if (options.size > 0.0 && Extension(path) != ".geo")
        gmsh::option::setNumber("Mesh.MeshSizeMax", options.size);
      gmsh::model::mesh::generate(3);
    });
  }
  ReportProgress(progress, geometry ? "meshing" : "reading mesh", 0.5);
  if (!options.save_as.empty()) SaveMesh(options.save_as);

  Mesh mesh;
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
  std::vector<std::size_t> all_max{max_tag};
  for (auto t : node_tags) all_max[0] = std::max(all_max[0], t);
  std::vector<int> index_of_tag(all_max[0] + 1, -1);
  // Number the nodes of solid cells in the order gmsh lists them.
  std::vector<char> used(all_max[0] + 1, 0);
  for (const auto& nodes : elem_nodes)
    for (auto t : nodes) used[t] = 1;
  int n = 0;
  for (auto t : node_tags)
    if (used[t] && index_of_tag[t] < 0) index_of_tag[t] = n++;
  mesh.nodes.resize(3, n);
  mesh.node_tags.resize(n);
  for (size_t k = 0; k < node_tags.size(); ++k) {
    const int i = index_of_tag[node_tags[k]];
    if (i < 0) continue;
    mesh.nodes.col(i) << coords[3 * k], coords[3 * k + 1], coords[3 * k + 2];
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
      const int i = t < index_of_tag.size() ? index_of_tag[t] : -1;
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
  ReportProgress(progress, geometry ? "meshing" : "reading mesh", 1.0);
  return mesh;
}

}  // namespace emb
