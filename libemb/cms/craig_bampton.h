#pragma once
/// @file
/// Craig–Bampton reduction of a solid part to its interfaces.
///
/// Unknowns: the full FE displacements u (3 per node). The boundary coordinates are the six
/// reference-node motions q_j = (t_j, θ_j) of every interface j (see interface.h). Interior
/// unknowns I are all FE unknowns except the RBE2 surface nodes (which are slaved,
/// u_S = T_S q). RBE3 interfaces add constraints C u_I = q_RBE3 (their weighted averages).
///
/// Basis (columns of T, in full FE unknowns):
///  - constraint modes Ψ: for each boundary coordinate k the static deformation with q = e_k,
///        K_II ψ + Cᵀ μ = −K_IS T_S e_k,   C ψ = e_k (RBE3 rows),
///    solved with the factorisation of A = K_II − σM_II by the refinement
///    ψ ← ψ + A_C⁻¹(b − K_II ψ; e_k − C ψ), residuals in extended precision, which contracts by
///    |σ|/(λ₁ − σ) per step (λ₁: lowest fixed-interface eigenvalue; ~1e-5 for a crankshaft).
///    A part held by RBE3 averages only (K_II singular, A nearly so) is pinned 3-2-1 instead
///    (PinnedConstrainedSolver). The rigid response, known exactly, is restored afterwards;
///  - fixed-interface normal modes Φ: K_II φ = λ M_II φ on C φ = 0 with the RBE2 surfaces
///    clamped, by shift-invert Lanczos on the same factorisation.
/// Both solves go through a ConstrainedPencilSolver (linalg/pencil_solver.h): the above is
/// LocalPencilSolver's (one process); the distributed one (ReductionOptions::pencil_solver,
/// distributed/slepc_pencil_solver.h) factorises [K_II Cᵀ; C 0] with MUMPS instead and runs
/// SLEPc on the constrained pencil, to the same solutions.
/// CB is statically exact: for loads at the interfaces, T reproduces the full solution.
///
/// Without interfaces the basis is the six rigid-body motions plus free-free elastic modes.

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "libemb/cms/interface.h"
#include "libemb/common/progress.h"
#include "libemb/common/timer.h"
#include "libemb/fe/assembly.h"
#include "libemb/linalg/eigen_solver.h"
#include "libemb/linalg/pencil_solver.h"

namespace emb {

/// Which fixed-interface (or free-free) modes to keep.
struct ModeSelection {
  enum class Kind {
    kCount,   ///< the `count` lowest
    kCutoff,  ///< all up to `fmax_hz`
    kBand,    ///< all up to band_factor × fmax_hz: fmax_hz is the highest frequency of interest
  };
  Kind kind{Kind::kCount};
  int count{100};
  double fmax_hz{0.0};
  /// Multiple of the band up to which fixed-interface modes are kept (the usual 1.5–2×). How
  /// accurate that makes the band is part-specific: the certificate of each run measures it
  /// (benchmarks/README.md has the crankshaft's error against mode count).
  double band_factor{2.0};

  /// The frequency up to which modes are kept [Hz] (infinite for kCount).
  double CutoffHz() const;
  /// E.g. "20 modes", "modes up to 3000 Hz", "band 1500 Hz x 2 = modes up to 3000 Hz".
  std::string Describe() const;
};

struct ReductionOptions {
  ModeSelection selection;
  double shift_hz{-1.0};       ///< Lanczos shift [Hz] (negative: lowest modes)
  EigenSolverOptions solver;   ///< tolerance, subspace, backend; num_modes/shift are set here
  /// Solver of the interior pencil (K_II, M_II, C) for the fixed-interface modes and the
  /// constraint modes; empty: LocalPencilSolver (one process, solver.backend). A distributed
  /// one (distributed/slepc_pencil_solver.h) makes BuildReductionBasis collective.
  PencilSolverFactory pencil_solver;
};

/// How the numerical steps of a reduction ended (ReductionBasis, ReducedBody). Inputs that
/// cannot be reduced (more modes than unknowns, interfaces that leave part of the mesh
/// unrestrained) are InputErrors instead; these are the solvers' outcomes on a valid input.
enum class ReductionStatus {
  kDone,
  kNotFactorised,        ///< K_II − σ M_II (or the part pinned 3-2-1) could not be factorised
  kEigenSolveFailed,     ///< the fixed-interface (free-free) eigen-solve failed its checks
  kStaticSolveFailed,    ///< the static load cases did not converge
  kReducedPencilFailed,  ///< the eigenproblem on (K̂, M̂) failed or lacks the rigid motions
};
const char* Name(ReductionStatus status);

/// A reduction basis in full FE unknowns, with what it took to make it.
struct ReductionBasis {
  ReductionStatus status{ReductionStatus::kDone};
  std::string message;  ///< what failed, with numbers, when status is not kDone
  bool ok() const { return status == ReductionStatus::kDone; }
  std::vector<Interface> interfaces;
  /// N × (6·interfaces + modes): constraint modes (6 per interface, order t_x t_y t_z θ_x θ_y
  /// θ_z), then the kept fixed-interface modes (M-orthonormal). Free-free: 6 rigid motions
  /// (translations, then rotations about the origin), then elastic modes.
  Eigen::MatrixXd T;
  int num_boundary{0};                 ///< 6 × interfaces (6 for the free-free basis)
  bool free_free{false};
  Eigen::VectorXd mode_frequencies_hz; ///< of the kept fixed-interface (free-free) modes
  EigenResult eig;                     ///< the eigen-solve's log (vectors moved into T)
  std::string selection_note;          ///< what was kept and why
  int static_iterations{0};            ///< refinement steps of the constraint modes
  /// max over ψ of ‖K_II ψ + K_IS u_S‖ outside range(Cᵀ) / (‖K_II ψ‖ + ‖K_IS u_S‖)
  double static_residual{0.0};
  double rigid_correction{0.0};        ///< ‖R_I − Ψ P‖/‖R_I‖ before the rigid correction
  /// Condition estimate of the interior stiffness the constraint modes solve with:
  /// (‖K_II‖₁/‖M_II‖₁) / λ₁, the stiffness scale over the lowest fixed-interface eigenvalue
  /// (1 when no mode was computed). A slender part's K_II is ill-conditioned, and the relative
  /// residual a correctly rounded solution leaves grows with it.
  double stiffness_condition{1.0};
  /// Reduced coordinates of the six rigid motions about the origin (translations x, y, z,
  /// rotations x, y, z): (nr × 6), exact by construction.
  Eigen::MatrixXd rigid;
  /// Static responses (N × k) to the `static_loads` given to BuildReductionBasis (empty if
  /// none): with every interface held (q = 0: RBE2 reference nodes fixed, RBE3 averages zero),
  /// solved like the constraint modes on the same factorisation; for the free-free basis by
  /// inertia relief (load less its rigid-body inertia forces F − M R (RᵀMR)⁻¹ Rᵀ F, part
  /// pinned 3-2-1, rigid motion then removed M-orthogonally: Rᵀ M u = 0).
  Eigen::MatrixXd static_responses;
  std::string static_support;          ///< "interfaces held" or "inertia relief"
  PhaseTimes times;                    ///< "constraint modes", "factorisation", "eigen-solve", ...
  /// False on an MPI rank other than 0 of a distributed reduction: it took part in the solves,
  /// rank 0 holds the basis (only interfaces, frequencies and times are filled in here).
  bool on_this_process{true};
};

/// The six rigid-body motions about the origin as full FE fields (N × 6): columns t_x, t_y,
/// t_z, θ_x, θ_y, θ_z.
Eigen::MatrixXd RigidBodyModes(const Mesh& mesh);

/// An eigen-solve of one pencil for the given options (num_modes set by the caller).
using EigenSolveFn = std::function<EigenResult(const EigenSolverOptions&, const ProgressFn&)>;

/// The lowest eigenpairs of a (constrained) pencil: `initial` of them, then more (reusing the
/// factorisation; NextModeCount predicts how many) until the highest one found is above
/// fmax_hz (infinite: no growth) or all `available` − 1 are asked for.
EigenResult SolveLowestModes(const EigenSolveFn& solve, EigenSolverOptions options, int initial,
                             double fmax_hz, int available, const ProgressFn& progress = {});
/// The same with a ShiftInvertSolver of the pencil.
EigenResult SolveLowestModes(ShiftInvertSolver& solver, EigenSolverOptions options, int initial,
                             double fmax_hz, int available, const ProgressFn& progress = {});

/// How many of the lowest modes to ask for next when the `eigenvalues` found (ascending,
/// [rad²/s²]) end below fmax_hz: the mode count is modelled as N(f) = N_top (f / f_top)^p, p
/// from the upper half of what was found (N/2 modes to f_{N/2}, N to f_top) and kept between
/// 1/2 (bending of a slender part: f ∝ n²) and 3 (Weyl's law for a solid), with a 20 %
/// margin. Why: asking for twice as many each time redid the whole solve up to three times
/// (20, 40, then 80 modes for the 48 the inline-4 crank keeps below 20 kHz). The answer is
/// at least N + 10 and at most max(3N, N + 20): a clustered start (the crank's first 20
/// fixed-interface modes are the eleven interfaces' local modes, 6.0–7.6 kHz: p = 5.8)
/// overstates the growth.
int NextModeCount(const Eigen::VectorXd& eigenvalues, double fmax_hz);

/// Builds the Craig–Bampton basis of `sys` (assembled from `mesh`) for `interfaces` (empty:
/// free-free basis).
/// @throws InputError for more modes than interior unknowns, interfaces that leave part of
///   the mesh unrestrained (naming the floating region), dependent interface constraints.
/// `static_loads` (N × k, may be empty): loads whose static responses are wanted too
/// (ReductionBasis::static_responses), phase "static load cases".
/// A factorisation, eigen-solve or static solve that fails is the basis's status (the rest
/// of it is then incomplete); on a distributed solver every rank returns it.
ReductionBasis BuildReductionBasis(const Mesh& mesh, const SystemMatrices& sys,
                                   const std::vector<Interface>& interfaces,
                                   const ReductionOptions& options, const ProgressFn& progress = {},
                                   const Eigen::MatrixXd& static_loads = Eigen::MatrixXd());

}  // namespace emb
