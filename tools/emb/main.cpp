// emb — elasto-multibody dynamics of engines and drivelines with component mode synthesis.
//
// One command with subcommands:
//   emb mesh  PART            mesh a geometry (or read a mesh) and report what is in it
//   emb modes PART            free-free (or constrained) natural frequencies and mode shapes
//   emb reduce PART           Craig–Bampton reduction with a certificate -> body file (HDF5)
//   emb inspect FILE          what is inside a body file
//   emb dof SCENE             degrees of freedom and redundant constraints of a multibody scene
//   emb run SCENE             run a multibody scene (kinematic/static/dynamic), results to HDF5
//   emb spectrum RESULTS      engine-order spectrum of a results channel over whole cycles
// Sample run:
//   emb modes meshes/crankshaft_i4.geo --modes 20 -o crank_modes.h5
// Inputs: a gmsh geometry (.geo with parameters, .step, .brep) or a mesh (.msh, .unv, .bdf).
// Outputs: tables on stdout (or JSON with --json), progress on stderr, HDF5 result files
// written atomically with an XDMF companion for ParaView.
// Exit codes: 0 ok, 1 bad input, 2 usage, 3 numerical failure, 4 internal error.

#include <CLI/CLI.hpp>
#include <iostream>

#include "libemb/common/error.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/progress_display.h"

int main(int argc, char** argv) {
  using namespace emb::cli;
  SetCommandLine(argc, argv);
  CLI::App app{"emb: elasto-multibody dynamics of engines and drivelines with component mode "
               "synthesis"};
  app.set_version_flag("--version", std::string("emb ") + EMB_VERSION);
  app.require_subcommand(1);
  RegisterMeshCommand(app);
  RegisterModesCommand(app);
  RegisterReduceCommand(app);
  RegisterInspectCommand(app);
  RegisterDofCommand(app);
  RegisterRunCommand(app);
  RegisterSpectrumCommand(app);
  RegisterCompareCommand(app);
  // Name an unknown subcommand (CLI11 would only say that one is required).
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const CLI::App* sub : app.get_subcommands({})) {
      known |= sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "emb: unknown subcommand '" << argv[1] << "'; expected one of: " << names
                << " (see emb --help)\n";
      return kExitUsage;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitUsage;
  } catch (const emb::InputError& e) {
    FinishProgressLine();
    std::cerr << "emb: error: " << e.what() << "\n";
    return kExitInput;
  } catch (const emb::NumericalError& e) {
    FinishProgressLine();
    std::cerr << "emb: numerical failure: " << e.what() << "\n";
    return kExitNumerical;
  } catch (const std::exception& e) {
    FinishProgressLine();
    std::cerr << "emb: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return 0;
}
