// emb reduce PART: Craig–Bampton reduction of a solid part to its interfaces, orthonormalised,
// with inertia invariants and a reduction certificate; the body file (HDF5) for multibody runs.
// With --backend slepc the constraint modes and fixed-interface modes are solved on MPI ranks
// (MUMPS, SLEPc); every rank meshes and assembles, rank 0 alone does the rest and writes:
//   mpirun -n 4 emb reduce crank.msh --backend slepc -n 60

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "libemb/cms/body_file.h"
#include "libemb/cms/reduction.h"
#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/common/timer.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/progress_display.h"
#include "tools/emb/slepc_backend.h"

namespace emb::cli {
namespace {

struct ReduceCommand {
  PartOptions part;
  OutputOptions out;
  std::vector<std::string> interfaces;
  bool free_free{false};
  std::optional<int> num_modes;
  std::optional<double> fmax_hz, band_hz, check_fmax_hz;
  double band_factor{2.0};
  double shift_hz{-1.0};
  double tolerance{1e-10};
  int subspace{0};
  int max_restarts{1000};
  double damping_ratio{0.01};
  std::vector<double> rayleigh;
  bool no_reference{false};
  bool no_static_check{false};
  bool no_mesh_shapes{false};
  bool no_geometric_stiffness{false};
  std::vector<std::string> stiffening_supports;
  std::vector<std::string> stress_groups;
  bool no_stress{false};
  bool stress_surface{false};
  bool no_xdmf{false};
  bool allow_failed_certificate{false};
  std::string output;
  std::string backend{"cholmod"};

  std::string OutputPath() const {
    if (!output.empty()) return output;
    return std::filesystem::path(part.file).stem().string() + "_body.h5";
  }

  ReductionJob Job(const Mesh& mesh) const {
    ReductionJob job;
    const int selections = num_modes.has_value() + fmax_hz.has_value() + band_hz.has_value();
    EMB_THROW_IF(selections > 1, "give one of --modes, --fmax, --band, got " << selections);
    ModeSelection& sel = job.reduction.selection;
    if (fmax_hz) {
      sel.kind = ModeSelection::Kind::kCutoff;
      sel.fmax_hz = *fmax_hz;
    } else if (band_hz) {
      sel.kind = ModeSelection::Kind::kBand;
      sel.fmax_hz = *band_hz;
      sel.band_factor = band_factor;
    } else {
      sel.kind = ModeSelection::Kind::kCount;
      sel.count = num_modes ? *num_modes : ModeSelection().count;
    }
    job.reduction.shift_hz = shift_hz;
    job.reduction.solver.tolerance = tolerance;
    job.reduction.solver.subspace = subspace;
    job.reduction.solver.max_restarts = max_restarts;
    job.certificate.solver.tolerance = tolerance;
    job.certificate.reference = !no_reference;
    job.certificate.static_check = !no_static_check;
    if (sel.kind != ModeSelection::Kind::kCount) job.certificate.fmax_hz = sel.fmax_hz;
    if (check_fmax_hz) job.certificate.fmax_hz = *check_fmax_hz;
    if (!rayleigh.empty()) {
      EMB_THROW_IF(rayleigh.size() != 2, "--rayleigh: expected ALPHA,BETA, got "
                                             << rayleigh.size() << " values");
      job.damping.kind = DampingModel::Kind::kRayleigh;
      job.damping.alpha = CheckNumber("--rayleigh ALPHA", rayleigh[0], NumberRange::NonNegative("1/s"));
      job.damping.beta = CheckNumber("--rayleigh BETA", rayleigh[1], NumberRange::NonNegative("s"));
    } else {
      job.damping.ratio = CheckNumber("--damping-ratio (the modal damping ratio)", damping_ratio, NumberRange::Closed(0.0, 1.0));
    }
    job.keep_mesh_shapes = !no_mesh_shapes;
    job.geometric_stiffness = !no_geometric_stiffness;
    job.stiffening_supports = stiffening_supports;
    EMB_THROW_IF(no_stress && !stress_groups.empty(),
                 "--no-stress and --stress-groups exclude each other");
    EMB_THROW_IF(no_stress && stress_surface, "--no-stress and --stress-surface exclude each other");
    if (!no_stress)
      job.stress_groups = stress_groups.empty() ? DefaultStressGroups(mesh) : stress_groups;
    job.stress_surface = stress_surface;
    if (free_free) {
      EMB_THROW_IF(!interfaces.empty(), "--free-free and --interface exclude each other");
    } else if (!interfaces.empty()) {
      for (const auto& s : interfaces) job.interfaces.push_back(InterfaceSpec::Parse(s));
    } else {
      job.interfaces = DefaultInterfaces(mesh);
    }
    return job;
  }

  void Run() const {
    if (backend != "slepc") return Reduce(nullptr);
    // Every rank of `mpirun -n N emb reduce ... --backend slepc` runs this; rank 0 alone prints
    // and writes, and the ranks agree on the exit code (one message).
    std::unique_ptr<SlepcBackend> distributed = SlepcBackend::Start();
    if (!distributed->is_root() && !std::freopen("/dev/null", "w", stdout))
      EMB_THROW(InputError, "--backend slepc: cannot send the output of rank > 0 to /dev/null");
    distributed->Agree([&] { Reduce(distributed.get()); });
    distributed->Finish();
  }

  // The reduction; with `distributed`, the constraint modes and fixed-interface modes are
  // solved on every MPI rank and the rest by rank 0.
  void Reduce(SlepcBackend* distributed) const {
    const Stopwatch elapsed;  // the whole command, the steps between the phases too
    const bool root = !distributed || distributed->is_root();
    EMB_THROW_IF(distributed && free_free,
                 "--free-free: not available with --backend slepc (it distributes the "
                 "interior solves of a Craig-Bampton reduction; give interfaces)");
    part.material.Validate();
    if (num_modes) CheckInteger("--modes", *num_modes, 0, 1000000);
    if (fmax_hz) CheckNumber("--fmax", *fmax_hz, NumberRange::Positive("Hz"));
    if (band_hz) CheckNumber("--band", *band_hz, NumberRange::Positive("Hz"));
    if (check_fmax_hz) CheckNumber("--check-fmax", *check_fmax_hz, NumberRange::Positive("Hz"));
    CheckNumber("--band-factor", band_factor, NumberRange::Closed(1.0, 100.0));
    CheckSolverOptions(tolerance, subspace, max_restarts, shift_hz);
    // Every output checked and locked before any work (by rank 0, which writes them).
    const std::string h5_path = root ? OutputPath() : "";
    const std::string xdmf_path =
        no_xdmf || no_mesh_shapes || !root
            ? ""
            : std::filesystem::path(h5_path).replace_extension(".xdmf").string();
    MeshingOptions meshing = part.Meshing();
    if (!root) meshing.save_as.clear();
    const PreparedOutputs outputs(
        {{h5_path, "-o"}, {xdmf_path, "the .xdmf beside -o"}, {meshing.save_as, "--save-mesh"}},
        {part.file});
    const ProgressFn progress = MakeProgressDisplay(out.quiet || !root);
    PhaseTimes times;
    Stopwatch sw;
    const Mesh mesh = ReadMesh(part.file, meshing, progress);
    times.Add("mesh", sw.seconds());
    ReductionJob job = Job(mesh);
    if (distributed) job.reduction.pencil_solver = distributed->PencilSolver();
    // Resolve the interfaces before the expensive part: a wrong name fails at once.
    ResolveInterfaces(mesh, job.interfaces);

    sw.Restart();
    const SystemMatrices sys = AssembleSystem(mesh, part.material, progress);
    times.Add("assembly", sw.seconds());
    if (distributed) distributed->Checkpoint();  // every rank ready for the collective solves
    const ReducedBody body = ReduceBody(mesh, sys, part.material, job, progress);
    if (!body.ok())  // every rank of a distributed reduction has the status
      EMB_THROW(NumericalError, "the reduction failed (" << Name(body.status) << "): "
                                                         << body.message);
    if (!body.on_this_process) return;  // an MPI rank done with its part of the solves
    for (const auto& p : body.times.phases) times.Add(p.first, p.second);
    FinishProgressLine();

    const ReductionCertificate& ct = body.certificate;
    Table itf_table("Interfaces", {"name", "coupling", "x", "y", "z", "point", "nodes"},
                    {"interface", "coupling", "x [m]", "y [m]", "z [m]", "reference point", "nodes"});
    for (const auto& itf : body.interfaces)
      itf_table.AddRow({itf.name, std::string(Name(itf.coupling)), itf.point.x(), itf.point.y(),
                        itf.point.z(), itf.point_source, static_cast<long long>(itf.nodes.size())});
    Table freq("Free-free frequencies: reduced vs full FE (MAC-paired)",
               {"mode", "full_hz", "reduced_mode", "reduced_hz", "error_percent", "mac"},
               {"mode", "full FE [Hz]", "reduced mode", "reduced [Hz]", "error [%]", "MAC"});
    for (const auto& p : ct.pairs) {
      if (p.paired)
        freq.AddRow({static_cast<long long>(p.full_mode), p.full_hz,
                     static_cast<long long>(p.reduced_mode), p.reduced_hz,
                     100.0 * p.relative_error, p.mac});
      else
        freq.AddRow({static_cast<long long>(p.full_mode), p.full_hz, std::string("-"),
                     std::string("not represented"), std::string("-"), p.mac});
    }
    Table modes("Elastic modes of the reduced body", {"mode", "frequency_hz"},
                {"mode", "frequency [Hz]"});
    for (int i = 0; i < body.modes.frequencies_hz.size(); ++i)
      modes.AddRow({static_cast<long long>(i + 1), body.modes.frequencies_hz[i]});

    // Modal stresses and their check against the full FE model (modal_stress.h).
    const ModalStressCheck& sc = body.stress_check;
    Table stress("Modal stresses at the stress groups (static check: full FE vs modal)",
                 {"group", "nodes", "check_error", "peak_stress_per_unit_load"},
                 {"group", "nodes", "max rel. error", "peak |sigma| per unit load [Pa/N, Pa/(N m)]"});
    for (std::size_t g = 0; g < body.stress_groups.size(); ++g) {
      const bool checked = sc.run && g < sc.errors.size();
      stress.AddRow({body.stress_groups[g].name,
                     static_cast<long long>(body.stress_groups[g].num_nodes()),
                     checked ? Table::Cell(sc.errors[g]) : Table::Cell(std::string("-")),
                     checked ? Table::Cell(sc.peak_stress[g]) : Table::Cell(std::string("-"))});
    }

    Summary cert("Reduction certificate");
    cert.Add("passed", "passed", ct.passed());
    for (size_t i = 0; i < ct.failures.size(); ++i)
      cert.Add("failure_" + std::to_string(i + 1), "FAILED", ct.failures[i]);
    cert.Add("mass_kg", "mass full / reduced [kg]",
             std::to_string(ct.full.mass) + " / " + std::to_string(ct.reduced.mass));
    cert.Add("mass_error", "mass rel. error (limit 1e-10)", ct.mass_error);
    cert.Add("com_error", "centre of mass rel. error (limit 1e-10)", ct.com_error);
    cert.Add("inertia_error", "inertia tensor rel. error (limit 1e-10)", ct.inertia_error);
    cert.Add("quadrature_mass_error", "mass vs mesh quadrature rel. error", ct.quadrature_mass_error);
    cert.Add("num_near_zero", "rigid-body modes (expected 6)", static_cast<long long>(ct.num_near_zero));
    cert.Add("max_rigid_hz", "largest rigid-body frequency [Hz]",
             ct.rigid_hz.size() ? ct.rigid_hz.cwiseAbs().maxCoeff() : 0.0);
    cert.Add("orthonormality_error", "M-orthonormality error", ct.orthonormality_error);
    cert.Add("orthonormality_limit", "orthonormality limit (scaled by cond M^)",
             ct.orthonormality_limit);
    cert.Add("k_diagonality_error", "K-diagonality error", ct.k_diagonality_error);
    cert.Add("degenerate_coupling", "stiffness coupling of near-equal modes (<= 5e-9)",
             ct.degenerate_coupling);
    cert.Add("rigid_stiffness", "rigid-motion strain residual", ct.rigid_stiffness);
    if (ct.reference_run) {
      cert.Add("fmax_hz", "compared up to [Hz]", ct.fmax_hz);
      cert.Add("max_frequency_error", "max frequency error [%]", 100.0 * ct.max_frequency_error);
      // The design target: frequencies below the band within 0.1 % of the full model.
      if (ct.max_frequency_error > 1e-3)
        cert.Add("warning", "warning",
                 "frequencies up to " + FormatNumber(ct.fmax_hz) + " Hz are off by up to " +
                     FormatNumber(100.0 * ct.max_frequency_error) +
                     " %: keep more modes (--modes, --fmax or a larger --band-factor)");
      cert.Add("min_mac", "min MAC (paired)", ct.min_mac);
      cert.Add("unrepresented", "full modes not represented", static_cast<long long>(ct.num_unrepresented));
      cert.Add("reference_log", "full FE eigen-solve", ct.reference_log);
    } else {
      cert.Add("reference", "full FE comparison", std::string("not run"));
    }
    cert.Add("static_note", "static check", ct.static_note);
    if (ct.static_run) cert.Add("static_error", "static rel. error (limit 1e-8)", ct.static_error);
    cert.Add("reduction_log", "fixed-interface eigen-solve", ct.reduction_log);
    for (const auto& [name, secs] : ct.times.phases)
      cert.Add("seconds_" + name, "time " + name + " [s]", secs);
    if (!body.free_free) {
      cert.Add("constraint_mode_residual", "constraint-mode residual", ct.constraint_mode_residual);
      cert.Add("constraint_mode_limit", "constraint-mode limit (scaled by cond K_II)",
               ct.constraint_mode_limit);
      cert.Add("constraint_mode_iterations", "constraint-mode refinement steps",
               static_cast<long long>(ct.constraint_mode_iterations));
    }

    Summary s("Craig-Bampton reduction of " + mesh.source);
    s.Add("mesh", "mesh", mesh.Summary());
    s.Add("dofs", "FE degrees of freedom", sys.num_dofs());
    s.Add("backend", "interior solves", distributed ? std::string("slepc (MUMPS + SLEPc, MPI)")
                                                    : std::string("cholmod"));
    if (distributed) distributed->AddReductionSummary(s);
    s.Add("basis", "basis", body.free_free ? std::string("free-free (no interfaces)")
                                           : std::string("Craig-Bampton"));
    s.Add("selection", "selection", body.selection_note);
    s.Add("boundary_coordinates", "interface coordinates", static_cast<long long>(body.num_boundary));
    s.Add("fixed_interface_modes", "fixed-interface modes kept",
          static_cast<long long>(body.fixed_interface_hz.size()));
    s.Add("elastic_modes", "elastic modes", static_cast<long long>(body.modes.frequencies_hz.size()));
    s.Add("dropped", "dependent vectors dropped", static_cast<long long>(body.modes.num_dropped));
    s.Add("damping", "damping", body.damping.Describe());
    s.Add("geometric_stiffness", "geometric stiffening", body.geometric_stiffness.Describe());
    std::string stress_note = "none (no --stress-groups and no fillet groups in the mesh)";
    if (no_stress) stress_note = "none (--no-stress)";
    if (!body.stress_groups.empty())
      stress_note = std::to_string(body.stress_groups.size()) + " group(s); check: " +
                    (sc.run ? sc.note + ", max rel. error " + FormatNumber(sc.max_error)
                            : sc.note.empty() ? std::string("not run") : sc.note);
    s.Add("stress_groups", "modal stresses", stress_note);
    const ModalStressSurface& surf = body.stress_surface;
    s.Add("stress_surface", "modal stresses on the whole surface",
          surf.empty() ? std::string("none (no --stress-surface)")
                       : std::to_string(surf.num_nodes()) + " nodes, " +
                             std::to_string(surf.num_faces()) + " faces");
    if (!surf.empty())
      s.Add("stress_surface_nodes", "surface nodes with modal stresses",
            static_cast<long long>(surf.num_nodes()));
    if (sc.run) s.Add("stress_check_error", "modal stress check: max rel. error", sc.max_error);
    for (const auto& [name, secs] : times.phases) s.Add("seconds_" + name, "time " + name + " [s]", secs);
    s.Add("seconds_total", "time total [s]", times.Total());
    s.Add("peak_memory_mb", "peak memory [MB]", PeakResidentBytes() / 1e6);

    const bool write = ct.passed() || allow_failed_certificate;
    if (write) {
      const std::string& xdmf = xdmf_path;
      BodyFileInfo info;
      info.provenance = {CommandLine(), part.file, sys.mesh_hash, part.Describe()};
      info.material = part.material;
      for (const auto& spec : job.interfaces)
        info.interfaces += (info.interfaces.empty() ? "" : "; ") + spec.ToString();
      info.selection = job.reduction.selection.Describe();
      info.shift_hz = shift_hz;
      Stopwatch ws;
      WriteBodyFile(h5_path, xdmf, body, info, &mesh);
      s.Add("seconds_write", "time write [s]", ws.seconds());
      s.Add("output", "written", h5_path + (xdmf.empty() ? "" : " and " + xdmf));
    }
    s.Add("seconds_elapsed", "time elapsed, whole command [s]", elapsed.seconds());
    if (out.json) {
      PrintJson({{"summary", s.ToJson()},
                 {"interfaces", itf_table.ToJson()},
                 {"modes", modes.ToJson()},
                 {"comparison", freq.ToJson()},
                 {"certificate", cert.ToJson()},
                 {"stress", stress.ToJson()}});
    } else if (!out.quiet) {  // -q: the file is the result, no report
      itf_table.Print(std::cout);
      std::cout << "\n";
      modes.Print(std::cout);
      std::cout << "\n";
      if (ct.reference_run) {
        freq.Print(std::cout);
        std::cout << "\n";
      }
      cert.Print(std::cout);
      std::cout << "\n";
      if (!body.stress_groups.empty()) {
        stress.Print(std::cout);
        std::cout << "\n";
      }
      s.Print(std::cout);
    }
    if (!ct.passed())
      EMB_THROW(NumericalError, "the reduction certificate failed: "
                                    << ct.failures.front()
                                    << (write ? "" : " (no body file written; "
                                                     "--allow-failed-certificate writes it anyway)"));
  }
};

}  // namespace

void RegisterReduceCommand(CLI::App& app) {
  auto st = std::make_shared<ReduceCommand>();
  CLI::App* cmd = app.add_subcommand(
      "reduce",
      "Craig-Bampton reduction of a part to its interfaces (RBE2/RBE3 reference nodes), "
      "orthonormalised, with inertia invariants and a reduction certificate; writes the body "
      "file (HDF5) that multibody runs use");
  st->part.Register(*cmd);
  cmd->add_option("-i,--interface", st->interfaces,
                  "Interface NAME[:rbe2|rbe3][@x,y,z] (repeatable): a surface physical group "
                  "condensed to one 6-DOF node; rbe3 (weighted average, default) or rbe2 (rigid "
                  "spider); the point defaults to the cylinder axis at mid-width or the plane "
                  "centroid. Default: main_journal_*, crankpin_* rbe3; flange, nose rbe2; "
                  "tube end_a, end_b rbe2");
  cmd->add_flag("--free-free", st->free_free,
                "No interfaces: a basis of the six rigid motions and free-free elastic modes");
  cmd->add_option("-n,--modes", st->num_modes,
                  "Keep this many fixed-interface modes (default 100 unless --fmax/--band)");
  cmd->add_option("--fmax", st->fmax_hz, "Keep all fixed-interface modes up to this frequency [Hz]");
  cmd->add_option("--band", st->band_hz,
                  "Highest frequency of interest [Hz]: keep fixed-interface modes up to "
                  "band-factor x this, and compare free-free frequencies up to it");
  cmd->add_option("--band-factor", st->band_factor, "Multiple of --band kept")->capture_default_str();
  cmd->add_option("--check-fmax", st->check_fmax_hz,
                  "Certificate: compare free-free frequencies with the full model up to this [Hz] "
                  "(default: --band/--fmax, or half the highest fixed-interface mode kept)");
  cmd->add_option("--shift-hz", st->shift_hz, "Lanczos shift [Hz] (negative: lowest modes)")
      ->capture_default_str();
  cmd->add_option("--tol", st->tolerance, "Relative tolerance on the Ritz residuals (block Krylov-Schur and Lanczos); the pairs are then checked against their backward errors")->capture_default_str();
  cmd->add_option("--ncv", st->subspace, "Lanczos subspace size (0 = automatic)")->capture_default_str();
  cmd->add_option("--max-restarts", st->max_restarts, "Spectra's Lanczos restart limit")
      ->capture_default_str();
  cmd->add_option("--backend", st->backend,
                  "Interior solves: cholmod (one process) or slepc (distributed: constraint "
                  "modes by MUMPS on MPI ranks, fixed-interface modes by SLEPc; run as mpirun "
                  "-n N emb reduce ... --backend slepc; rank 0 does the rest and writes)")
      ->capture_default_str()
      ->check(CLI::IsMember({"cholmod", "slepc"}));
  cmd->add_option("--damping-ratio", st->damping_ratio, "Modal damping ratio of every elastic mode")
      ->capture_default_str();
  cmd->add_option("--rayleigh", st->rayleigh, "Rayleigh damping ALPHA,BETA [1/s, s] instead of modal")
      ->delimiter(',');
  cmd->add_flag("--no-reference", st->no_reference,
                "Skip the full FE free-free comparison in the certificate (saves one eigen-solve)");
  cmd->add_flag("--no-static-check", st->no_static_check,
                "Skip the static exactness check in the certificate (saves one factorisation)");
  cmd->add_flag("--no-mesh-shapes", st->no_mesh_shapes,
                "Do not store the mesh and the mode shapes at all nodes (smaller file, no animation)");
  cmd->add_flag("--no-geometric-stiffness", st->no_geometric_stiffness,
                "Do not compute the stress-stiffening matrices of the nine inertial load cases "
                "(centrifugal about the centre of mass, uniform acceleration; saves nine static "
                "solves, stress recoveries and geometric-stiffness assemblies)");
  cmd->add_option("--stiffening-supports", st->stiffening_supports,
                  "Interfaces NAME,... held in the geometric-stiffness load cases (those clamped "
                  "in service, e.g. a blade root); the others are free and take the static "
                  "response. Default: every interface held")
      ->delimiter(',');
  cmd->add_option("--stress-groups", st->stress_groups,
                  "Surface groups NAME,... whose modal stresses the body file stores (6 "
                  "nodal-averaged components at the group's nodes per elastic mode), for "
                  "stress recovery in emb run; checked against the full FE model under the "
                  "certificate's static interface loads. Default: the mesh's "
                  "crankpin_fillet_<i> and journal_fillet_<k> groups, if any")
      ->delimiter(',');
  cmd->add_flag("--no-stress", st->no_stress, "Store no modal stresses (not even the default fillet groups)");
  cmd->add_flag("--stress-surface", st->stress_surface,
                "Also store the modal stresses on the whole boundary surface (the faces of one "
                "cell; quadratic faces kept) with its nodes and faces, for the whole-surface "
                "stress field of emb run (stress_outputs: surface_field_times) in ParaView; "
                "grows the body file by 24 bytes per surface node and elastic mode (float32)");
  cmd->add_flag("--no-xdmf", st->no_xdmf, "Do not write the .xdmf file next to the .h5");
  cmd->add_flag("--allow-failed-certificate", st->allow_failed_certificate,
                "Write the body file even if the certificate fails (the exit code is still 3)");
  cmd->add_option("-o,--output", st->output,
                  "Body file (default: <part name>_body.h5 in the current directory)")
      ->check(NonEmptyPath());
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
