#include "libemb/cms/craig_bampton.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <string_view>

#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/cms/geometric_stiffening.h"
#include "libemb/cms/interface_partition.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/linalg/extended_product.h"
#include "libemb/linalg/pencil_solver.h"
#include "libemb/linalg/pinned_solver.h"
#include "libemb/linalg/shift_invert_solver.h"
#include "libemb/linalg/submatrix.h"

namespace emb {
namespace {

int FindRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Pieces of the mesh (cells joined through shared nodes) that touch none of the interfaces,
// described for an error message; empty if every piece touches one.
std::string DescribeFloatingPieces(const Mesh& mesh, const std::vector<Interface>& interfaces) {
  std::vector<int> parent(mesh.num_nodes());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& b : mesh.blocks)
    for (int c = 0; c < b.num_cells(); ++c) {
      const int* v = b.cell(c);
      for (int k = 1; k < b.nodes_per_cell(); ++k) parent[FindRoot(parent, v[k])] = FindRoot(parent, v[0]);
    }
  std::vector<char> held(mesh.num_nodes(), 0);
  for (const auto& itf : interfaces)
    for (int s : itf.nodes) held[FindRoot(parent, s)] = 1;
  std::vector<int> count(mesh.num_nodes(), 0);
  std::vector<Eigen::Vector3d> sum(mesh.num_nodes(), Eigen::Vector3d::Zero());
  for (const auto& b : mesh.blocks)
    for (int c = 0; c < b.num_cells(); ++c)
      for (int k = 0; k < b.nodes_per_cell(); ++k) {
        const int v = b.cell(c)[k];
        const int r = FindRoot(parent, v);
        ++count[r];
        sum[r] += mesh.nodes.col(v);
      }
  std::ostringstream o;
  int pieces = 0;
  for (int r = 0; r < mesh.num_nodes(); ++r) {
    if (count[r] == 0 || held[r] || FindRoot(parent, r) != r) continue;
    const Eigen::Vector3d c = sum[r] / count[r];
    o << (pieces++ ? "; " : "") << "a piece around (" << c.x() << ", " << c.y() << ", " << c.z()
      << ") m";
  }
  return o.str();
}

[[noreturn]] void ThrowUnrestrained(const Mesh& mesh, const std::vector<Interface>& interfaces,
                                    const std::string& evidence) {
  const std::string floating = DescribeFloatingPieces(mesh, interfaces);
  if (!floating.empty())
    EMB_THROW(InputError, "the interfaces do not restrain the part (" << evidence
                                                                      << "): floating region: "
                                                                      << floating
                                                                      << " touches no interface");
  EMB_THROW(InputError, "the interfaces do not restrain the part ("
                            << evidence
                            << "): they leave a mechanism; add or change interfaces, or reduce "
                               "free-free (no interfaces)");
}

// Solves the eigenproblem for the selection, growing the request until the cut-off is passed.
// A requested count that ends inside a degenerate group is extended to keep the group whole.
EigenResult SolveSelected(const EigenSolveFn& solve, double sigma, int available,
                          const ReductionOptions& o, std::string& note,
                          const ProgressFn& progress) {
  const ModeSelection& sel = o.selection;
  EigenSolverOptions so = o.solver;
  so.shift = sigma;
  const double cutoff = sel.CutoffHz();
  const int limit = available - 1;  // Lanczos needs fewer than the problem size
  EigenResult r = SolveLowestModes(
      solve, so, sel.kind == ModeSelection::Kind::kCount ? sel.count + 1 : 20, cutoff, available,
      progress);
  if (!r.ok()) return r;
  const int found = static_cast<int>(r.eigenvalues.size());
  int keep = 0;
  if (sel.kind == ModeSelection::Kind::kCount) {
    keep = std::min(sel.count, found);
    // Keep a degenerate partner (to 1e-6 relative, far above solver accuracy and far below
    // the splitting a mesh causes) with its mode: half a bending pair is a wrong model.
    if (keep < found && keep > 0 &&
        std::abs(r.eigenvalues[keep] - r.eigenvalues[keep - 1]) <=
            1e-6 * std::abs(r.eigenvalues[keep - 1])) {
      ++keep;
      note += "; mode " + std::to_string(keep) + " kept too (degenerate partner of mode " +
              std::to_string(keep - 1) + ")";
    }
  } else {
    while (keep < found && FrequencyHz(r.eigenvalues[keep]) <= cutoff) ++keep;
    if (keep == found && found == limit) note += "; every available mode is below the cut-off";
  }
  r.eigenvalues.conservativeResize(keep);
  // (Vectors may be absent: on the ranks of a distributed solve other than 0.)
  if (r.vectors.cols() > 0) r.vectors.conservativeResize(Eigen::NoChange, keep);
  r.backward_errors.conservativeResize(keep);
  r.num_converged = std::min(r.num_converged, keep);
  return r;
}

// Marks `b` as failed at a numerical step. @returns it, for `return Failed(...)`.
ReductionBasis Failed(ReductionBasis b, ReductionStatus status, std::string message) {
  b.status = status;
  b.message = std::move(message);
  return b;
}

std::string EigenFailure(const EigenResult& r, const char* what) {
  return std::string(what) + " eigen-solve " + Name(r.status) + ": " + r.message;
}

// Inertia relief: the load less its rigid-body inertia forces, F − M R (RᵀMR)⁻¹ Rᵀ F, is
// self-equilibrated; the part pinned 3-2-1 (by multipliers on six unknowns, which then carry no
// reaction) deforms under it, and its rigid motion is removed M-orthogonally (Rᵀ M u = 0).
// @returns false (with the message) if the pinned part cannot be factorised.
bool SolveInertiaRelief(const Mesh& mesh, const SystemMatrices& sys, const Eigen::MatrixXd& F,
                        Eigen::MatrixXd* U, std::string* message) {
  const int N = sys.num_dofs();
  const Eigen::MatrixXd R = RigidBodyModes(mesh);
  const Eigen::MatrixXd MR = sys.M * R;
  const Eigen::LDLT<Eigen::MatrixXd> rigid_mass((R.transpose() * MR).eval());
  const Eigen::MatrixXd balanced = F - MR * rigid_mass.solve(R.transpose() * F);
  const std::vector<int> pins = PinUnknowns(mesh, PartitionByInterfaces(mesh, {}));
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < 6; ++k) t.emplace_back(k, pins[k], 1.0);
  SparseMatrix G(6, N);
  G.setFromTriplets(t.begin(), t.end());
  const PinnedConstrainedSolver pinned(sys.K, R, pins, G);
  if (!pinned.ok()) {
    *message = "inertia relief: the part pinned 3-2-1 could not be solved: " + pinned.message();
    return false;
  }
  *U = pinned.Solve(balanced, Eigen::MatrixXd::Zero(6, F.cols()));
  *U -= R * rigid_mass.solve(MR.transpose() * *U);
  return true;
}

// The constraint modes K_II Ψ + Cᵀ Λ = rhs, C Ψ = Q in groups of at most
// kConstraintModesPerSolve columns (of equal size: no small group at the end): the refinement's
// residuals and corrections and the solver's workspace scale with the columns solved at once
// (the 66 constraint modes of a 293k-DOF crankshaft in one group held ~0.5 GB more at the
// reduction's peak), and a group is still a blocked solve (the factor is streamed once per
// group). There, three groups of 22 took 6.8 s against 8.7 s for five of 13–14 (one group of
// 66: 7.2 s, a quieter run), at the same peak (set by the fixed-interface eigen-solve).
// `iterations`: the most refinement steps a group took, −1 if one did not converge. Every rank
// of a distributed solver makes the same calls; Ψ is empty where it does not hold results.
Eigen::MatrixXd SolveConstraintModes(ConstrainedPencilSolver& solver, const Eigen::MatrixXd& rhs,
                                     const Eigen::MatrixXd& Q, int& iterations,
                                     const ProgressFn& progress) {
  constexpr int kConstraintModesPerSolve = 22;
  const int nq = static_cast<int>(rhs.cols());
  const int groups = (nq + kConstraintModesPerSolve - 1) / kConstraintModesPerSolve;
  Eigen::MatrixXd Psi;
  if (solver.holds_results()) Psi.resize(rhs.rows(), nq);
  iterations = 0;
  for (int g = 0; g < groups; ++g) {
    const int first = g * nq / groups, k = (g + 1) * nq / groups - first;
    ProgressFn group_progress;
    if (progress)
      group_progress = [&progress, first, k, nq](std::string_view phase, double fraction) {
        progress(phase, (first + fraction * k) / nq);
      };
    int steps = 0;
    const Eigen::MatrixXd X = solver.StaticSolve(rhs.middleCols(first, k),
                                                 Q.middleCols(first, k), steps, group_progress);
    if (steps < 0) {
      iterations = -1;
      return Psi;
    }
    iterations = std::max(iterations, steps);
    if (solver.holds_results()) Psi.middleCols(first, k) = X;
  }
  return Psi;
}

ReductionBasis BuildFreeFree(const Mesh& mesh, const SystemMatrices& sys,
                             const ReductionOptions& o, const ProgressFn& progress,
                             const Eigen::MatrixXd& static_loads) {
  ReductionBasis b;
  b.free_free = true;
  b.num_boundary = 6;
  SparseMatrix none(0, sys.num_dofs());
  ShiftInvertSolver solver(sys.K, sys.M, none, o.solver.backend);
  ReductionOptions shifted = o;
  // The six rigid modes come first; the selection counts elastic modes.
  if (shifted.selection.kind == ModeSelection::Kind::kCount) shifted.selection.count += 6;
  b.selection_note = "free-free (no interfaces): rigid-body motions + elastic modes, " +
                     o.selection.Describe();
  Stopwatch sw;
  b.eig = SolveSelected(
      [&](const EigenSolverOptions& so, const ProgressFn& p) {
        return SolveGeneralizedEigen(solver, so, p);
      },
      LambdaFromHz(o.shift_hz), sys.num_dofs(), shifted, b.selection_note, progress);
  if (!b.eig.ok()) {
    std::string message = EigenFailure(b.eig, "free-free");
    return Failed(std::move(b), ReductionStatus::kEigenSolveFailed, std::move(message));
  }
  const double threshold = 1e-10 * NormOne(sys.K) / NormOne(sys.M);
  const int rigid = static_cast<int>((b.eig.eigenvalues.array().abs() < threshold).count());
  if (rigid != 6)
    ThrowUnrestrained(mesh, {}, std::to_string(rigid) + " modes at 0 Hz instead of 6");
  const int ne = static_cast<int>(b.eig.eigenvalues.size()) - 6;
  b.T.resize(sys.num_dofs(), 6 + ne);
  b.T.leftCols(6) = RigidBodyModes(mesh);
  b.T.rightCols(ne) = b.eig.vectors.rightCols(ne);
  b.mode_frequencies_hz.resize(ne);
  for (int i = 0; i < ne; ++i) b.mode_frequencies_hz[i] = FrequencyHz(b.eig.eigenvalues[6 + i]);
  b.eig.vectors.resize(0, 0);
  b.rigid = Eigen::MatrixXd::Zero(6 + ne, 6);
  b.rigid.topRows(6).setIdentity();
  for (const auto& [name, s] : b.eig.times.phases) b.times.Add(name, s);
  if (static_loads.cols() > 0) {
    sw.Restart();
    std::string message;
    if (!SolveInertiaRelief(mesh, sys, static_loads, &b.static_responses, &message))
      return Failed(std::move(b), ReductionStatus::kNotFactorised, std::move(message));
    b.static_support = kSupportInertiaRelief;
    b.times.Add("static load cases", sw.seconds());
  }
  return b;
}

}  // namespace

EigenResult SolveLowestModes(ShiftInvertSolver& solver, EigenSolverOptions options, int initial,
                             double fmax_hz, int available, const ProgressFn& progress) {
  return SolveLowestModes(
      [&solver](const EigenSolverOptions& so, const ProgressFn& p) {
        return SolveGeneralizedEigen(solver, so, p);
      },
      options, initial, fmax_hz, available, progress);
}

EigenResult SolveLowestModes(const EigenSolveFn& solve, EigenSolverOptions options, int initial,
                             double fmax_hz, int available, const ProgressFn& progress) {
  const int limit = available - 1;  // Lanczos needs fewer than the problem size
  int nev = initial;
  // What earlier, too small attempts cost: reported with the last one.
  PhaseTimes spent, spent_block;
  int solves = 0, block_steps = 0;
  for (;;) {
    options.num_modes = std::min(nev, limit);
    EigenResult r = solve(options, progress);
    r.times.Merge(spent);
    r.block_times.Merge(spent_block);
    r.num_solves += solves;
    r.block_steps += block_steps;
    if (!r.ok() || !std::isfinite(fmax_hz) ||
        FrequencyHz(r.eigenvalues[r.eigenvalues.size() - 1]) > fmax_hz || options.num_modes == limit)
      return r;
    nev = NextModeCount(r.eigenvalues, fmax_hz);
    spent = r.times;
    spent_block = r.block_times;
    solves = r.num_solves;
    block_steps = r.block_steps;
    // The pairs found are locked in the next, larger solve (EigenSolverOptions::known_vectors).
    options.known_vectors = std::move(r.vectors);
    options.known_eigenvalues = std::move(r.eigenvalues);
  }
}

int NextModeCount(const Eigen::VectorXd& eigenvalues, double fmax_hz) {
  constexpr double kMinExponent = 0.5, kMaxExponent = 3.0, kMargin = 1.2;
  const int n = static_cast<int>(eigenvalues.size());
  const int lowest = n + 10, highest = std::max(3 * n, n + 20);
  if (n < 4) return lowest;
  const double f_top = FrequencyHz(eigenvalues[n - 1]);
  const double f_half = FrequencyHz(eigenvalues[n / 2 - 1]);
  double p = kMaxExponent;  // no usable spread (e.g. only rigid modes): assume the steepest
  if (f_half > 0.0 && f_top > f_half)
    p = std::clamp(std::log(n / static_cast<double>(n / 2)) / std::log(f_top / f_half),
                   kMinExponent, kMaxExponent);
  if (!(f_top > 0.0) || !(fmax_hz > f_top)) return lowest;
  const double predicted = kMargin * n * std::pow(fmax_hz / f_top, p);
  if (!(predicted < highest)) return highest;
  return std::max(lowest, static_cast<int>(std::ceil(predicted)));
}

double ModeSelection::CutoffHz() const {
  switch (kind) {
    case Kind::kCount: return std::numeric_limits<double>::infinity();
    case Kind::kCutoff: return fmax_hz;
    case Kind::kBand: return band_factor * fmax_hz;
  }
  return 0.0;
}

std::string ModeSelection::Describe() const {
  std::ostringstream o;
  switch (kind) {
    case Kind::kCount: o << count << " modes"; break;
    case Kind::kCutoff: o << "modes up to " << fmax_hz << " Hz"; break;
    case Kind::kBand:
      o << "band " << fmax_hz << " Hz x " << band_factor << " = modes up to " << CutoffHz() << " Hz";
      break;
  }
  return o.str();
}

const char* Name(ReductionStatus status) {
  switch (status) {
    case ReductionStatus::kDone:
      return "done";
    case ReductionStatus::kNotFactorised:
      return "not-factorised";
    case ReductionStatus::kEigenSolveFailed:
      return "eigen-solve-failed";
    case ReductionStatus::kStaticSolveFailed:
      return "static-solve-failed";
    case ReductionStatus::kReducedPencilFailed:
      return "reduced-pencil-failed";
  }
  return "unknown";
}

Eigen::MatrixXd RigidBodyModes(const Mesh& mesh) {
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * mesh.num_nodes(), 6);
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Eigen::Vector3d x = mesh.nodes.col(i);
    R.block<3, 6>(3 * i, 0) = ReferenceRigidMotions(x).topRows<3>();  // t0 + θ0 × x
  }
  return R;
}

ReductionBasis BuildReductionBasis(const Mesh& mesh, const SystemMatrices& sys,
                                   const std::vector<Interface>& interfaces,
                                   const ReductionOptions& o, const ProgressFn& progress,
                                   const Eigen::MatrixXd& static_loads) {
  const ModeSelection& sel = o.selection;
  EMB_THROW_IF(sel.kind == ModeSelection::Kind::kCount && sel.count < 0,
               "number of modes: expected 0 or more, got " << sel.count);
  EMB_THROW_IF(sel.kind != ModeSelection::Kind::kCount && !(sel.fmax_hz > 0),
               "frequency limit: expected a positive frequency, got " << sel.fmax_hz << " Hz");
  EMB_THROW_IF(!(sel.band_factor >= 1.0),
               "band factor: expected at least 1, got " << sel.band_factor);
  EMB_THROW_IF(sys.num_dofs() != 3 * mesh.num_nodes(),
               "reduction: the matrices (" << sys.num_dofs() << " unknowns) do not belong to the "
                                           << "mesh (" << mesh.num_nodes() << " nodes)");
  EMB_THROW_IF(static_loads.cols() > 0 && static_loads.rows() != sys.num_dofs(),
               "reduction: static loads of " << static_loads.rows() << " rows; expected "
                                             << sys.num_dofs());
  if (interfaces.empty()) {
    EMB_THROW_IF(o.pencil_solver, "a free-free reduction (no interfaces) runs on one process "
                                  "only; give interfaces, or leave out the distributed backend");
    return BuildFreeFree(mesh, sys, o, progress, static_loads);
  }

  ReductionBasis b;
  b.interfaces = interfaces;
  const int N = sys.num_dofs();
  const int nb = static_cast<int>(interfaces.size());
  const int nq = 6 * nb;
  b.num_boundary = nq;

  Stopwatch sw;
  const InterfacePartition part = PartitionByInterfaces(mesh, interfaces);
  const std::vector<int>& slaved = part.slaved;
  const std::vector<int>& interior = part.interior;
  const int ni = static_cast<int>(interior.size());
  const Eigen::MatrixXd& TS = part.TS;
  const Eigen::MatrixXd& Q = part.Q;
  const SparseMatrix& C = part.C;

  const SparseMatrix KII = ExtractSubmatrix(sys.K, interior, interior);
  const SparseMatrix MII = ExtractSubmatrix(sys.M, interior, interior);
  const SparseMatrix KIS = ExtractSubmatrix(sys.K, interior, slaved);
  b.times.Add("partition", sw.seconds());

  const int available = ni - C.rows();
  EMB_THROW_IF(sel.kind == ModeSelection::Kind::kCount && sel.count >= available,
               "number of modes: " << sel.count << " requested but the interior has only "
                                   << available << " degrees of freedom");
  std::unique_ptr<ConstrainedPencilSolver> solver =
      o.pencil_solver ? o.pencil_solver(KII, MII, C)
                      : std::make_unique<LocalPencilSolver>(KII, MII, C, o.solver.backend);
  const Eigen::MatrixXd R = RigidBodyModes(mesh);
  // Only RBE3 averages hold the part: K_II is singular and K_II − σM nearly so in the rigid
  // directions (its constrained solves would cancel rigid parts 1/|σ| large, and the Schur
  // complement of the averages is ill-conditioned: a slender bar's three RBE3 sections were
  // refused as "dependent", issue 19). The constrained inverse of K_II itself is applied
  // instead (shift 0), e.g. through a factorisation pinned 3-2-1: for the fixed-interface
  // modes and the constraint modes alike. With no slaved unknowns the interior rigid motions
  // are the full ones.
  if (slaved.empty()) solver->HoldRigidMotions(R, PinUnknowns(mesh, part));
  const double sigma = slaved.empty() ? 0.0 : LambdaFromHz(o.shift_hz);
  if (!solver->Prepare(sigma)) {
    if (slaved.empty()) ThrowUnrestrained(mesh, interfaces, solver->message());
    std::ostringstream o;
    o << "fixed-interface matrix K_II - sigma M_II (sigma = " << sigma
      << ") could not be factorised: " << solver->message();
    return Failed(std::move(b), ReductionStatus::kNotFactorised, o.str());
  }
  b.times.Add("factorisation", solver->factor_seconds());
  ReturnFreedMemory();  // the factorisation's temporaries (K_II − σM_II, CHOLMOD's workspace)
  const double threshold = 1e-10 * NormOne(KII) / NormOne(MII);

  // Fixed-interface modes.
  b.selection_note = "fixed-interface modes: " + sel.Describe();
  const bool want_modes = !(sel.kind == ModeSelection::Kind::kCount && sel.count == 0);
  if (want_modes) {
    b.eig = SolveSelected(
        [&solver](const EigenSolverOptions& so, const ProgressFn& p) {
          return solver->Eigenpairs(so, p);
        },
        sigma, available, o, b.selection_note, progress);
    if (!b.eig.ok()) {
      std::string message = EigenFailure(b.eig, "fixed-interface");
      return Failed(std::move(b), ReductionStatus::kEigenSolveFailed, std::move(message));
    }
    for (const auto& [name, s] : b.eig.times.phases)
      if (name != "factorisation") b.times.Add(name, s);
    const int rigid = static_cast<int>((b.eig.eigenvalues.array().abs() < threshold).count());
    if (rigid > 0)
      ThrowUnrestrained(mesh, interfaces,
                        std::to_string(rigid) + " fixed-interface modes at 0 Hz");
  }
  const int nm = static_cast<int>(b.eig.eigenvalues.size());
  if (nm > 0 && b.eig.eigenvalues[0] > 0.0)
    b.stiffness_condition = std::max(1.0, NormOne(KII) / NormOne(MII) / b.eig.eigenvalues[0]);
  b.mode_frequencies_hz.resize(nm);
  for (int i = 0; i < nm; ++i) b.mode_frequencies_hz[i] = FrequencyHz(b.eig.eigenvalues[i]);

  // Constraint modes: K_II ψ + Cᵀμ = −K_IS T_S, C ψ = Q.
  sw.Restart();
  if (progress) progress("constraint modes", 0.0);
  const Eigen::MatrixXd rhs = -MultiplyExtended(KIS, TS);
  Eigen::MatrixXd Psi = SolveConstraintModes(*solver, rhs, Q, b.static_iterations, progress);
  if (b.static_iterations < 0)
    ThrowUnrestrained(mesh, interfaces,
                      "the constraint modes did not converge: the interior stiffness is "
                      "(nearly) singular");
  const double constraint_solve_seconds = sw.seconds();

  // Static load cases with the interfaces held: the constraint-mode equations with q = 0.
  Eigen::MatrixXd UI;
  if (static_loads.cols() > 0) {
    sw.Restart();
    const int nl = static_cast<int>(static_loads.cols());
    Eigen::MatrixXd FI(ni, nl);
    for (int k = 0; k < ni; ++k) FI.row(k) = static_loads.row(interior[k]);
    int iterations = 0;
    UI = solver->StaticSolve(FI, Eigen::MatrixXd::Zero(C.rows(), nl), iterations, {});
    if (iterations < 0)
      return Failed(std::move(b), ReductionStatus::kStaticSolveFailed,
                    "the static load cases with the interfaces held did not converge: the "
                    "interior stiffness is (nearly) singular");
    b.times.Add("static load cases", sw.seconds());
  }
  // The factorisation is not needed from here on: released before the residuals and T are
  // formed. A process that only took part in distributed solves stops here (rank 0 holds the
  // results).
  const bool holds_results = solver->holds_results();
  solver.reset();
  if (!holds_results) {
    b.times.Add("constraint modes", constraint_solve_seconds);
    b.on_this_process = false;
    return b;
  }

  sw.Restart();
  Eigen::MatrixXd RI(ni, 6);
  for (int k = 0; k < ni; ++k) RI.row(k) = R.row(interior[k]);
  // A rigid motion of the interfaces moves the part rigidly (K R = 0): that response is known
  // exactly, so the solves' forward error (~cond(K)·ε, 1e-9 on a slender tube) is removed from
  // it by a rank-6 correction Ψ ← Ψ + (R_I − Ψ P)(PᵀP)⁻¹Pᵀ, P = the rigid q-coordinates. The
  // rigid-body mass properties of the reduced body are then exact to round-off.
  {
    Eigen::MatrixXd P(nq, 6);
    for (int j = 0; j < nb; ++j) P.middleRows(6 * j, 6) = ReferenceRigidMotions(interfaces[j].point);
    const Eigen::MatrixXd E = RI - Psi * P;
    b.rigid_correction = E.norm() / RI.norm();
    Psi += E * (P.transpose() * P).ldlt().solve(P.transpose());
  }
  // Residual outside the constraint forces range(Cᵀ), relative to the scale of the terms
  // summed in forming it, ‖ |K| |Ψ_k| ‖ + ‖rhs_k‖ (the size its round-off has). Against
  // ‖K Ψ_k‖ alone a constraint mode that is a rigid motion (one interface: K Ψ_k = 0 up to
  // round-off) would show a relative residual of 1 however exact it is.
  {
    Eigen::MatrixXd res = KII * Psi;  // K Ψ, then the residual K Ψ − rhs in place
    Eigen::VectorXd scale(nq);
    Eigen::VectorXd terms(ni);
    for (int k = 0; k < nq; ++k) {
      terms.setZero();
      for (int j = 0; j < KII.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(KII, j); it; ++it)
          terms[it.row()] += std::abs(it.value()) * std::abs(Psi(j, k));
      scale[k] = std::max(terms.norm(), res.col(k).norm()) + rhs.col(k).norm();
    }
    res -= rhs;
    if (C.rows() > 0) {
      Eigen::LLT<Eigen::MatrixXd> cct(Eigen::MatrixXd(C * C.transpose()));
      res -= C.transpose() * cct.solve(C * res);
    }
    double worst = 0.0;
    for (int k = 0; k < nq; ++k)
      worst = std::max(worst, res.col(k).norm() / std::max(scale[k], 1e-300));
    b.static_residual = worst;
  }
  b.times.Add("constraint modes", constraint_solve_seconds + sw.seconds());
  if (static_loads.cols() > 0) {
    b.static_responses = Eigen::MatrixXd::Zero(N, static_loads.cols());  // u_S = T_S·0 = 0
    for (int k = 0; k < ni; ++k) b.static_responses.row(interior[k]) = UI.row(k);
    b.static_support = kSupportInterfacesHeld;
  }

  // T in full unknowns.
  sw.Restart();
  b.T = Eigen::MatrixXd::Zero(N, nq + nm);
  for (int k = 0; k < ni; ++k) {
    b.T.row(interior[k]).head(nq) = Psi.row(k);
    if (nm > 0) b.T.row(interior[k]).tail(nm) = b.eig.vectors.row(k);
  }
  for (size_t k = 0; k < slaved.size(); ++k) b.T.row(slaved[k]).head(nq) = TS.row(k);
  b.eig.vectors.resize(0, 0);

  // Rigid motion (t0, θ0) about the origin: q_j = (t0 + θ0 × p_j, θ0), η = 0.
  b.rigid = Eigen::MatrixXd::Zero(nq + nm, 6);
  for (int j = 0; j < nb; ++j) b.rigid.block<6, 6>(6 * j, 0) = ReferenceRigidMotions(interfaces[j].point);
  b.times.Add("basis", sw.seconds());
  return b;
}

}  // namespace emb
