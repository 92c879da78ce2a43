// emb modes PART: natural frequencies and mode shapes of a solid part, free-free by default
// or with supports (held components of groups, symmetry planes, RBE2/RBE3 reference nodes with
// held components, equations between nodes); results to an HDF5 file (+ XDMF for ParaView).
//   emb modes beam.msh --rbe3 end_a:x,y,z,rx --rbe3 end_b:y,z --modes 8 --json
// With --backend slepc the eigen-solve runs on MPI ranks (PETSc/SLEPc + MUMPS); every rank
// meshes and assembles, rank 0 alone prints and writes:
//   mpirun -n 4 emb modes crank.msh --backend slepc --modes 20

#include <filesystem>
#include <future>
#include <iostream>
#include <memory>

#include "libemb/cms/supports.h"
#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/common/timer.h"
#include "libemb/fe/assembly.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/fe/rigid_body_modes.h"
#include "libemb/io/modes_file.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/progress_display.h"
#include "tools/emb/slepc_backend.h"
#include "tools/emb/support_options.h"

namespace emb::cli {
namespace {

struct ModesCommand {
  PartOptions part;
  OutputOptions out;
  int num_modes{20};
  double shift_hz{-1.0};
  SupportOptions supports;
  int subspace{0};
  int block_size{0};
  double tolerance{1e-9};  // EigenSolverOptions::tolerance: why modes, unlike reduce, use 1e-9
  int max_restarts{1000};
  bool sturm_check{false};
  std::string backend{"cholmod"};
  std::string method{"auto"};
  std::string output;
  bool no_output{false};
  bool no_xdmf{false};

  std::string OutputPath() const {
    if (!output.empty()) return output;
    return std::filesystem::path(part.file).stem().string() + "_modes.h5";
  }

  void Run() const {
    const Stopwatch elapsed;  // the whole command, the steps between the phases too
    part.material.Validate();
    EMB_THROW_IF(num_modes < 1, "--modes: expected at least 1, got " << num_modes);
    CheckSolverOptions(tolerance, subspace, max_restarts, shift_hz);
    std::unique_ptr<SlepcBackend> distributed;
    if (backend == "slepc") {
      EMB_THROW_IF(sturm_check, "--sturm-check: not available with --backend slepc (its "
                                "negative_pivots entry counts the eigenvalues below the shift)");
      EMB_THROW_IF(method != "auto", "--method " << method << ": expected auto with --backend "
                                                    "slepc (SLEPc's Krylov-Schur is used)");
      EMB_THROW_IF(block_size != 0, "--block-size: not used by --backend slepc, expected 0");
      distributed = SlepcBackend::Start();
      // Rank 0 alone prints and writes; the other ranks' stdout goes nowhere.
      if (!distributed->is_root() && !std::freopen("/dev/null", "w", stdout))
        EMB_THROW(InputError, "--backend slepc: cannot send the output of rank > 0 to /dev/null");
    }
    const bool root = !distributed || distributed->is_root();
    // Supports parsed (and the equation file read) before any work.
    const SupportSpecs specs = supports.Specs();
    // Every output checked and locked before any work.
    const std::string h5_path = no_output || !root ? "" : OutputPath();
    MeshingOptions meshing = part.Meshing();
    if (!root) meshing.save_as.clear();  // --save-mesh: rank 0 writes it
    const std::string xdmf_path =
        h5_path.empty() || no_xdmf
            ? ""
            : std::filesystem::path(h5_path).replace_extension(".xdmf").string();
    const PreparedOutputs outputs(
        {{h5_path, "-o"}, {xdmf_path, "the .xdmf beside -o"}, {meshing.save_as, "--save-mesh"}},
        {part.file});
    const ProgressFn progress = MakeProgressDisplay(out.quiet || !root);
    PhaseTimes times;
    Stopwatch sw;
    const Mesh mesh = ReadMesh(part.file, meshing, progress);
    times.Add("mesh", sw.seconds());

    ModalOptions mo;
    mo.num_modes = num_modes;
    mo.shift_hz = shift_hz;
    mo.solver.subspace = subspace;
    mo.solver.spare_blocks = 6;  // fewer solves and restarts; memory does not bind here
    mo.solver.tolerance = tolerance;
    mo.solver.max_restarts = max_restarts;
    mo.solver.sturm_check = sturm_check;
    if (backend == "eigen") mo.solver.backend = CholeskyBackend::kEigenLDLT;
    mo.solver.block_size = block_size;
    if (distributed) mo.eigen_solver = distributed->Solver();
    if (method == "block") mo.solver.method = EigenMethod::kBlock;
    if (method == "lanczos") mo.solver.method = EigenMethod::kLanczos;
    if (method == "dense") mo.solver.method = EigenMethod::kDense;
    sw.Restart();
    const Supports held = BuildSupports(mesh, specs);
    mo = held.Apply(mo);
    // The part's null space, locked in the eigen-solve instead of searched for: only if it
    // fits the modes asked for (six per connected piece).
    mo.rigid_motions = PieceRigidBodyModes(mesh, std::max(1, num_modes / 6));
    times.Add("supports", sw.seconds());

    sw.Restart();
    // The factorisation's ordering needs only the mesh: METIS runs on its own thread beside
    // the assembly, not after it. Its own time is part of one factorisation's cost; only what
    // is left of it when the assembly ends is a phase.
    std::future<std::vector<int>> ordering;
    double ordering_seconds = 0.0;
    if (!distributed)
      ordering = std::async(std::launch::async, [&mesh, &ordering_seconds] {
        const Stopwatch own;
        std::vector<int> perm = FillReducingOrdering(mesh);
        ordering_seconds = own.seconds();
        return perm;
      });
    const SystemMatrices sys = AssembleSystem(mesh, part.material, progress);
    times.Add("assembly", sw.seconds());
    if (ordering.valid()) {
      sw.Restart();
      mo.ordering = ordering.get();
      times.Add("ordering wait", sw.seconds());
    }
    ModalResult modes = ComputeModes(sys, mo, progress);
    for (const auto& p : modes.eig.times.phases) times.Add(p.first, p.second);
    FinishProgressLine();
    if (distributed) {
      distributed->Finish();  // every rank agrees on the outcome; rank 0 goes on alone
      if (!root) {
        if (!modes.eig.ok())  // the exit code of rank 0, which says why
          EMB_THROW(NumericalError, "modal analysis " << Name(modes.eig.status) << " (rank "
                                                      << "0 reports the details)");
        return;
      }
    }
    const double constraint_residual =
        specs.empty() || !modes.eig.ok() ? 0.0 : ConstraintResidual(held, modes);
    if (modes.eig.ok() && !(constraint_residual <= kConstraintResidualLimit)) {
      modes.eig.status = EigenStatus::kInaccurate;
      modes.eig.message = "a mode violates the supports by " +
                          std::to_string(constraint_residual) + " (limit " +
                          std::to_string(kConstraintResidualLimit) + ")";
    }

    Table table("Natural frequencies (" +
                    (specs.empty() ? std::string("free-free") : held.description) + ")",
                {"mode", "frequency_hz", "kind", "backward_error"},
                {"mode", "frequency [Hz]", "kind", "backward error"});
    const int m = static_cast<int>(modes.frequencies_hz.size());
    for (int k = 0; k < m; ++k) {
      const bool rigid = k < modes.num_rigid_modes;
      table.AddRow({static_cast<long long>(k + 1), modes.frequencies_hz[k],
                    std::string(rigid ? "rigid" : "elastic"), modes.eig.backward_errors[k]});
    }
    Summary s("Modal analysis of " + mesh.source);
    s.Add("mesh", "mesh", mesh.Summary());
    s.Add("dofs", "degrees of freedom", sys.num_dofs());
    s.Add("supports", "supports", specs.empty() ? std::string("none (free-free)") : held.description);
    s.Add("fixed_dofs", "unknowns removed by supports", static_cast<long long>(modes.num_fixed_dofs));
    if (!specs.empty()) {
      s.Add("held_components", "held node components",
            static_cast<long long>(held.num_held_components));
      s.Add("constraints", "constraint rows", static_cast<long long>(held.rows.size()));
      s.Add("redundant_constraints", "redundant symmetry rows (implied, unused)",
            static_cast<long long>(held.num_redundant_rows));
      s.Add("constraint_residual", "max constraint residual of the modes", constraint_residual);
    }
    s.Add("mass_kg", "mass [kg]", sys.mass);
    s.Add("status", "status", std::string(Name(modes.eig.status)));
    if (!modes.eig.message.empty()) s.Add("message", "message", modes.eig.message);
    s.Add("converged", "converged pairs", static_cast<long long>(modes.eig.num_converged));
    s.Add("rigid_modes", "rigid-body modes", static_cast<long long>(modes.num_rigid_modes));
    s.Add("expected_rigid_modes", "rigid-body modes the supports leave",
          static_cast<long long>(modes.expected_rigid_modes));
    if (modes.eig.ok() && modes.num_rigid_modes != modes.expected_rigid_modes &&
        modes.num_rigid_modes < num_modes)
      s.Add("rigid_warning", "warning",
            std::to_string(modes.num_rigid_modes) + " zero-frequency modes found, but the "
            "supports leave " + std::to_string(modes.expected_rigid_modes) +
            " rigid motions: a mechanism or a disconnected piece?");
    if (modes.splits_degenerate_group)
      s.Add("warning", "warning",
            "mode " + std::to_string(num_modes) + " has a degenerate partner (mode " +
                std::to_string(num_modes + 1) + ") that was not asked for: use --modes " +
                std::to_string(num_modes + 1));
    s.Add("method", "eigen-solver", modes.eig.method);
    s.Add("shift", "shift sigma [rad^2/s^2]", modes.eig.shift);
    s.Add("iterations", "Krylov restarts", static_cast<long long>(modes.eig.iterations));
    s.Add("solves", "solves with K - sigma M (vectors)", static_cast<long long>(modes.eig.num_solves));
    s.Add("block_size", "right-hand sides per solve", static_cast<long long>(modes.eig.block_size));
    s.Add("block_steps", "block solves", static_cast<long long>(modes.eig.block_steps));
    s.Add("nnz_factor", "nonzeros in factor", static_cast<long long>(modes.eig.factor.nnz_factor));
    if (distributed) distributed->AddSummary(s);
    s.Add("max_backward_error", "max backward error", modes.eig.max_backward_error);
    s.Add("orthonormality_error", "M-orthonormality error", modes.eig.orthonormality_error);
    if (modes.eig.sturm_count >= 0)
      s.Add("sturm_count", "Sturm count below top mode",
            static_cast<long long>(modes.eig.sturm_count));
    for (const auto& [name, secs] : times.phases) s.Add("seconds_" + name, "time " + name + " [s]", secs);
    s.Add("seconds_total", "time total [s]", times.Total());
    for (const auto& [name, secs] : modes.eig.block_times.phases)
      s.Add("seconds_eigen-solve_" + name, "  eigen-solve: " + name + " [s]", secs);
    s.Add("peak_memory_mb", "peak memory [MB]", PeakResidentBytes() / 1e6);

    if (!h5_path.empty() && modes.eig.ok()) {
      Provenance prov{CommandLine(), part.file, sys.mesh_hash, part.Describe()};
      WriteModesFile(h5_path, xdmf_path, mesh, part.material, modes, prov);
      s.Add("output", "written", h5_path + (xdmf_path.empty() ? "" : " and " + xdmf_path));
    }
    if (!distributed)
      s.Add("ordering_seconds", "time ordering (METIS, beside the assembly) [s]", ordering_seconds);
    s.Add("seconds_elapsed", "time elapsed, whole command [s]", elapsed.seconds());
    if (out.json) {
      PrintJson({{"summary", s.ToJson()}, {"modes", table.ToJson()}});
    } else if (!out.quiet || no_output) {  // -q: the file is the result, no report
      table.Print(std::cout);
      std::cout << "\n";
      s.Print(std::cout);
    }
    if (!modes.eig.ok())
      EMB_THROW(NumericalError, "modal analysis " << Name(modes.eig.status) << ": "
                                                  << modes.eig.message
                                                  << " (no output file written)");
  }
};

}  // namespace

void RegisterModesCommand(CLI::App& app) {
  auto st = std::make_shared<ModesCommand>();
  CLI::App* cmd = app.add_subcommand(
      "modes",
      "Natural frequencies and mass-normalised mode shapes of a solid part (free-free unless "
      "--fixed), checked by residuals; saved to HDF5 with an XDMF file for ParaView");
  st->part.Register(*cmd);
  cmd->add_option("-n,--modes", st->num_modes, "Number of modes (rigid-body modes included)")
      ->capture_default_str();
  cmd->add_option("--shift-hz", st->shift_hz,
                  "Find the modes nearest this frequency [Hz]; the default (negative) gives the "
                  "lowest modes, also for free-free parts")
      ->capture_default_str();
  st->supports.Register(*cmd);
  cmd->add_option("--method", st->method,
                  "Eigen-solver: auto (dense up to 300 unknowns, else block), block (block "
                  "shift-invert Krylov-Schur on multi-RHS solves), lanczos (Spectra's "
                  "single-vector shift-invert Lanczos), dense")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "block", "lanczos", "dense"}));
  cmd->add_option("--ncv", st->subspace,
                  "Krylov basis size (0 = automatic: block method max(2 modes, modes + 6 blocks))")
      ->capture_default_str();
  cmd->add_option("--block-size", st->block_size,
                  "Right-hand sides per solve of the block method (0 = automatic: 8 for up to "
                  "12 modes, else 16)")
      ->capture_default_str();
  cmd->add_option("--tol", st->tolerance, "Relative tolerance on the Ritz residuals (block Krylov-Schur and Lanczos); the pairs are then checked against their backward errors")->capture_default_str();
  cmd->add_option("--max-restarts", st->max_restarts, "Spectra's Lanczos restart limit")
      ->capture_default_str();
  cmd->add_flag("--sturm-check", st->sturm_check,
                "Prove no mode was missed below the highest one found (extra LDL^T "
                "factorisation, slow on big models)");
  cmd->add_option("--backend", st->backend,
                  "Sparse factorisation: cholmod (supernodal, fast), eigen (simplicial "
                  "LDL^T, slow fallback) or slepc (distributed: SLEPc Krylov-Schur with MUMPS "
                  "shift-invert on MPI ranks; run as mpirun -n N emb modes ... --backend slepc)")
      ->capture_default_str()
      ->check(CLI::IsMember({"cholmod", "eigen", "slepc"}));
  cmd->add_option("-o,--output", st->output,
                  "HDF5 output file (default: <part name>_modes.h5 in the current directory)")
      ->check(NonEmptyPath());
  cmd->add_flag("--no-output", st->no_output, "Write no file, only print");
  cmd->add_flag("--no-xdmf", st->no_xdmf, "Do not write the .xdmf file next to the .h5");
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
