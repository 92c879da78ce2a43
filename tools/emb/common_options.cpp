#include "tools/emb/common_options.h"

#include <iostream>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/io/output_path.h"

namespace emb::cli {

const CLI::Validator& NonEmptyPath() {
  static const CLI::Validator check(
      [](std::string& value) {
        return value.empty() ? std::string("expected a file name, got an empty string")
                             : std::string();
      },
      "PATH");
  return check;
}

namespace {
std::string g_command_line;
}

void PartOptions::Register(CLI::App& cmd) {
  cmd.add_option("file", file,
                 "Part: a mesh (.msh, .unv, .bdf, ...) or a geometry gmsh meshes (.geo, .step, "
                 ".brep), e.g. meshes/crankshaft_i4.geo")
      ->required();
  cmd.add_option("--order", order, "Element order when meshing a geometry: 1 (Tet4/Hex8) or 2 "
                                   "(Tet10/Hex20, curved)")
      ->capture_default_str()
      ->check(CLI::IsMember({1, 2}));
  cmd.add_option("--size", size,
                 "Mesh size h [m] when meshing a geometry (sets the .geo parameter h); 0 keeps "
                 "the file's default")
      ->capture_default_str();
  cmd.add_option("--set", set,
                 "Override a .geo DefineConstant parameter, NAME=VALUE (SI units), repeatable; "
                 "e.g. --set stroke=0.09");
  cmd.add_option("--save-mesh", save_mesh,
                 "Also save the mesh gmsh made (format by extension, e.g. part.msh)")
      ->check(NonEmptyPath());
  cmd.add_flag("--trust-geo", trust_geo,
               "Give the part to gmsh without checking it first: only for files you trust. "
               "By default emb refuses a .geo script (or anything gmsh reads as one) that would "
               "run a command, write or delete files or stop the process (README: Files from "
               "others)");
  cmd.add_flag("--force", force,
               "Mesh even when the estimated element count for --size exceeds the limit "
               "(1.5 million)");
  cmd.add_option("--E", material.youngs_modulus, "Young's modulus [Pa]")->capture_default_str();
  cmd.add_option("--nu", material.poisson_ratio, "Poisson's ratio [-]")->capture_default_str();
  cmd.add_option("--rho", material.density, "Density [kg/m^3]")->capture_default_str();
}

MeshingOptions PartOptions::Meshing() const {
  MeshingOptions m;
  m.order = order;
  m.size = CheckNumber("--size", size, NumberRange::NonNegative("m"));
  m.save_as = save_mesh;
  m.trust_scripts = trust_geo;
  m.force = force;
  for (const auto& kv : set) {
    const auto eq = kv.find('=');
    EMB_THROW_IF(eq == std::string::npos || eq == 0,
                 "--set '" << kv << "': expected NAME=VALUE, e.g. --set stroke=0.09");
    const std::string name = kv.substr(0, eq);
    const std::string value = kv.substr(eq + 1);
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(value, &used);
    } catch (...) {
      used = 0;
    }
    EMB_THROW_IF(used == 0 || used != value.size(),
                 "--set '" << kv << "': expected a number after '=', got '" << value << "'");
    CheckNumber("--set " + name, v, NumberRange::Finite());
    m.parameters.emplace_back(name, v);
  }
  return m;
}

std::string PartOptions::Describe() const {
  std::ostringstream o;
  o.precision(12);
  o << "order=" << order << "; size=" << size;
  for (const auto& s : set) o << "; " << s;
  o << "; E=" << material.youngs_modulus << "; nu=" << material.poisson_ratio
    << "; rho=" << material.density;
  return o.str();
}

PreparedOutputs::PreparedOutputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                                 const std::vector<std::string>& inputs) {
  std::vector<std::string> paths;
  for (const auto& [path, what] : outputs) {
    CheckWritableOutput(path, what);
    paths.push_back(path);
  }
  CheckDistinctFiles(paths, inputs);
  for (const auto& path : paths)
    if (!path.empty()) locks_.emplace_back(path);
}

void CheckSolverOptions(double tolerance, int subspace, int max_restarts, double shift_hz) {
  CheckNumber("--tol", tolerance, NumberRange::Open(0.0, 1.0));
  CheckInteger("--ncv", subspace, 0, 1000000);
  CheckInteger("--max-restarts", max_restarts, 1, 1000000000);
  CheckNumber("--shift-hz", shift_hz, NumberRange::Finite("Hz"));
}

void OutputOptions::Register(CLI::App& cmd) {
  cmd.add_flag("--json", json, "Print the tables as one JSON document on stdout");
  cmd.add_flag("-q,--quiet", quiet,
               "No progress display on stderr, and no report tables on stdout where a file is "
               "the result (errors, warnings and --json's document still print)");
}

void PrintJson(const nlohmann::json& j) { std::cout << j.dump(2) << std::endl; }

std::string CommandLine() { return g_command_line; }

void SetCommandLine(int argc, char** argv) {
  g_command_line.clear();
  for (int i = 0; i < argc; ++i) g_command_line += (i ? " " : "") + std::string(argv[i]);
}

}  // namespace emb::cli
