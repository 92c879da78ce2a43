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
//   emb campbell SCENE        Campbell diagram: installed frequencies vs speed, crossings
//   emb tvd-tune SCENE        Den Hartog tuning of a torsional damper ring
//   emb sweep SCENE --rpm ..  speed sweep: every speed to steady state, engine orders per point
//   emb runup RESULTS         order tracking of a speed-ramp run
// Sample run:
//   emb modes meshes/crankshaft_i4.geo --modes 20 -o crank_modes.h5
// Inputs: a gmsh geometry (.geo with parameters, .step, .brep) or a mesh (.msh, .unv, .bdf).
// Outputs: tables on stdout (or JSON with --json), progress on stderr, HDF5 result files
// written atomically with an XDMF companion for ParaView.
// Exit codes: 0 ok, 1 bad input, 2 usage, 3 numerical failure, 4 internal error; stopped by
// SIGINT/SIGTERM: the signal (the shell shows 130/143).

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <stdexcept>

#include "libemb/common/error.h"
#include "libemb/common/script_deadline.h"
#include "libemb/common/signal_cleanup.h"
#include "libemb/io/hdf5_file.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/interrupt.h"
#include "tools/emb/no_exec.h"
#include "tools/emb/progress_display.h"
#include "tools/emb/slepc_backend.h"

namespace {
// The limit on reading an untrusted geometry script: kGeoScriptSeconds, or EMB_GEO_SECONDS.
constexpr double kGeoScriptSeconds = 120.0;

bool InstallGeoScriptDeadline() {
  double seconds = kGeoScriptSeconds;
  if (const char* env = std::getenv("EMB_GEO_SECONDS")) {
    char* end = nullptr;
    seconds = std::strtod(env, &end);
    if (end == env || *end != '\0' || !std::isfinite(seconds) || !(seconds > 0.0)) {
      std::cerr << "emb: error: EMB_GEO_SECONDS: expected a positive number of seconds, got '"
                << env << "'\n";
      return false;
    }
  }
  emb::SetScriptDeadlineHandler(seconds, [](const std::string& what, double limit) {
    std::cerr << "emb: error: refusing '" << what << "': gmsh was still reading it after "
              << limit << " s (a loop or macro call that does not end?); if the file is yours "
              << "and only slow, run again with --trust-geo, or set EMB_GEO_SECONDS\n";
    std::cerr.flush();
    emb::RemoveCleanupFilesForever();
    std::_Exit(emb::cli::kExitInput);
  });
  return true;
}

// SIGINT and SIGTERM are blocked before any library constructor runs (the loader runs an
// executable's pre-initialisation functions first), so every thread a library starts
// inherits the mask and only emb's own signal thread takes them (interrupt.h). OpenBLAS
// starts its threads in its constructor, before main().
void BlockInterruptsBeforeLibraries(int, char**, char**) { emb::cli::BlockInterrupts(); }
__attribute__((section(".preinit_array"), used)) void (*const kBlockInterrupts)(
    int, char**, char**) = BlockInterruptsBeforeLibraries;

// A name for a standard exception that says what kind of failure it was.
const char* ExceptionKind(const std::exception& e) {
  if (dynamic_cast<const std::invalid_argument*>(&e)) return "invalid argument";
  if (dynamic_cast<const std::out_of_range*>(&e)) return "index out of range";
  if (dynamic_cast<const std::logic_error*>(&e)) return "logic error";
  if (dynamic_cast<const std::runtime_error*>(&e)) return "run-time error";
  return "exception";
}
}  // namespace

int main(int argc, char** argv) {
  using namespace emb::cli;
  emb::DisableHdf5ExitCleanup();
  try {
    InstallInterruptHandlers();
  } catch (const emb::InternalError& e) {
    std::cerr << "emb: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  // emb never starts programs; forbid it unless the user trusts a geometry script (whose
  // SystemCall would then run, as asked).
  bool trust_geo = false;
  for (int i = 1; i < argc; ++i) trust_geo |= std::strcmp(argv[i], "--trust-geo") == 0;
  if (!trust_geo) ForbidProgramExecution();
  // A geometry script from someone else may loop without end while gmsh reads it (gmsh
  // cannot be stopped): after the limit emb says which file and exits (issue 14).
  if (!trust_geo && !InstallGeoScriptDeadline()) return kExitInput;
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
  RegisterCampbellCommand(app);
  RegisterTvdTuneCommand(app);
  RegisterCompareCommand(app);
  RegisterSweepCommand(app);
  RegisterRunUpCommand(app);
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
  } catch (const ExitQuietly& e) {
    return e.code;  // an MPI rank whose failure rank 0 has reported
  } catch (const emb::InputError& e) {
    FinishProgressLine();
    std::cerr << "emb: error: " << e.what() << "\n";
    return kExitInput;
  } catch (const emb::NumericalError& e) {
    FinishProgressLine();
    std::cerr << "emb: numerical failure: " << e.what() << "\n";
    return kExitNumerical;
  } catch (const Interrupted& e) {
    FinishProgressLine();
    std::cerr << "emb: " << e.what() << "\n";
    EndBySignal(e.signal());
  } catch (const std::bad_alloc&) {
    FinishProgressLine();
    std::cerr << "emb: error: not enough memory for this problem; make it smaller (a coarser "
                 "mesh, fewer modes or output samples)\n";
    return kExitInput;
  } catch (const std::length_error&) {
    FinishProgressLine();
    std::cerr << "emb: error: the problem is too large to hold in memory; make it smaller (a "
                 "coarser mesh, fewer modes or output samples)\n";
    return kExitInput;
  } catch (const emb::InternalError& e) {
    FinishProgressLine();
    std::cerr << "emb: internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    // A standard-library failure the code did not expect (its text, e.g. "stod" or
    // "vector::_M_range_check", means nothing to a user): an emb bug.
    FinishProgressLine();
    std::cerr << "emb: internal error: an unexpected failure (" << ExceptionKind(e)
              << ") in emb " << EMB_VERSION << "; please report it with the command line\n";
    return kExitInternal;
  } catch (...) {
    FinishProgressLine();
    std::cerr << "emb: internal error: an unexpected failure in emb " << EMB_VERSION
              << "; please report it with the command line\n";
    return kExitInternal;
  }
  return 0;
}
