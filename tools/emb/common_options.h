#pragma once
/// @file
/// Options shared by the subcommands that read a part: how to mesh it, its material, output.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "libemb/fe/material.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tools/emb/table.h"

namespace emb::cli {

struct PartOptions {
  std::string file;
  int order{2};
  double size{0.0};
  std::vector<std::string> set;  ///< "name=value"
  std::string save_mesh;
  IsotropicMaterial material;

  /// Adds FILE, --order, --size, --set, --save-mesh, --E, --nu, --rho to `cmd`.
  void Register(CLI::App& cmd);
  /// The meshing options, with --set parsed. @throws InputError for a malformed --set.
  MeshingOptions Meshing() const;
  /// "order=2; size=0.005; stroke=0.09; E=2.1e11; ..." for provenance records.
  std::string Describe() const;
};

/// Output options every subcommand has.
struct OutputOptions {
  bool json{false};
  bool quiet{false};
  void Register(CLI::App& cmd);
};

/// Prints a JSON document (pretty) to stdout.
void PrintJson(const nlohmann::json& j);

/// The command line as one string (for provenance).
std::string CommandLine();
void SetCommandLine(int argc, char** argv);

}  // namespace emb::cli
