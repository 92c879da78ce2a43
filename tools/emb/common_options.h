#pragma once
/// @file
/// Options shared by the subcommands that read a part: how to mesh it, its material, output.

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "libemb/fe/material.h"
#include "libemb/io/output_lock.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tools/emb/table.h"

namespace emb::cli {

/// CLI11 check of a path option: refuses an empty value (`-o ""`, an unset shell variable),
/// which would otherwise mean "no option" and write somewhere the user did not say.
const CLI::Validator& NonEmptyPath();

struct PartOptions {
  std::string file;
  int order{2};
  double size{0.0};
  std::vector<std::string> set;  ///< "name=value"
  std::string save_mesh;
  IsotropicMaterial material;
  bool trust_geo{false};  ///< --trust-geo: give the file to gmsh without the audit
  bool force{false};      ///< --force: mesh beyond the element-count estimate limit

  /// Adds FILE, --order, --size, --set, --save-mesh, --E, --nu, --rho to `cmd`.
  void Register(CLI::App& cmd);
  /// The meshing options, with --set parsed. @throws InputError for a malformed --set.
  MeshingOptions Meshing() const;
  /// "order=2; size=0.005; stroke=0.09; E=2.1e11; ..." for provenance records.
  std::string Describe() const;
};

/// The outputs of a command, checked before any work (the directory exists and is writable,
/// no output is an input or another output, none is being written by another emb) and
/// locked while the object lives. Empty paths are skipped.
class PreparedOutputs {
 public:
  /// `outputs`: {path, what names it in messages ("-o", "--save-mesh")}.
  /// @throws InputError for the first output that cannot be written.
  PreparedOutputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                  const std::vector<std::string>& inputs);

 private:
  std::vector<OutputLock> locks_;
};

/// Checks the eigen-solver options shared by modes and reduce (exit 1, not a numerical
/// failure, for a bad value): --tol in (0, 1), --ncv >= 0, --max-restarts >= 1, --shift-hz
/// finite.
void CheckSolverOptions(double tolerance, int subspace, int max_restarts, double shift_hz);

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
