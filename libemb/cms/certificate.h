#pragma once
/// @file
/// The reduction certificate: how good a reduced body is, measured against the full FE model
/// by routes independent of the reduction itself.
///
///  1. Rigid-body mass properties of the reduced body (from R̂ᵀM̂R̂) vs the full FE model (from
///     RᵀMR with the exact rigid fields R), and vs an independent quadrature of the mesh.
///  2. Exactly six near-zero eigenvalues of the reduced pencil, and how close to 0 Hz.
///  3. M̂-orthonormality and K̂-diagonality of the orthonormalised basis.
///  4. Free-free frequencies of the reduced body vs the full FE model up to f_max, paired by
///     the mass-weighted MAC of the expanded reduced modes (summed over a degenerate group).
///  5. Static exactness: one interface held, unit forces and moments at every other interface;
///     interface displacements of the reduced model vs the full FE model with the same
///     couplings, solved by an independent route (a pinned factorisation of the unshifted
///     stiffness and the support condition by Lagrange multipliers).
///  6. The eigen-solver log of the reduction.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "libemb/cms/craig_bampton.h"
#include "libemb/cms/inertia_invariants.h"
#include "libemb/cms/orthonormal_modes.h"
#include "libemb/common/timer.h"
#include "libemb/fe/mass_properties.h"

namespace emb {

struct CertificateOptions {
  bool reference{true};     ///< run the full FE free-free comparison (one more eigen-solve)
  /// Compare free-free frequencies up to this [Hz]; 0 = half the highest fixed-interface mode
  /// kept (all modes of a free-free basis).
  double fmax_hz{0.0};
  bool static_check{true};  ///< run the static exactness check (one more factorisation)
  /// Stress operator of the stress groups (modal_stress.h; empty: none): the static check
  /// then also keeps S u_full and the reduced solutions of its load cases.
  SparseMatrix stress_operator;
  EigenSolverOptions solver;  ///< for the reference solve
};

/// Limits the certificate asserts. The orthonormality and constraint-mode limits are floors:
/// they grow with the conditioning of the problem (issue 14: a slender bar's correctly computed
/// basis is orthonormal to 7e-10 because its M̂ spans 1e6 in modal mass), as
///     limit = max(floor, kRoundOffMultiple · ε · condition),
/// with the condition of M̂ (OrthonormalModes::mass_condition) and of K_II
/// (ReductionBasis::stiffness_condition) respectively.
struct CertificateLimits {
  static constexpr double kMassProperties = 1e-10;  ///< relative error of m, c, I
  static constexpr double kStatic = 1e-8;           ///< relative error of interface displacements
  static constexpr double kOrthonormality = 1e-10;  ///< floor: ‖XᵀM̂X − I‖, ‖XᵀK̂X − Λ‖/max λ
  static constexpr double kConstraintModes = 1e-10; ///< floor: relative residual of the static solves
  /// Round-off of a backward-stable dense eigen-decomposition or solve is a modest multiple of
  /// ε·condition (the multiple grows with the size, nr ≲ a few hundred here); 100 leaves room
  /// for that and is still 10⁶ times below an O(1) lost direction at condition 1e8.
  static constexpr double kRoundOffMultiple = 100.0;
  static double Orthonormality(double mass_condition);
  static double ConstraintModes(double stiffness_condition);
};

struct ModePair {
  int full_mode{0};         ///< 1-based, elastic modes of the full model
  double full_hz{0.0};
  int reduced_mode{0};      ///< 1-based elastic mode of the reduced body, by best MAC
  double reduced_hz{0.0};
  double relative_error{0.0};  ///< (f_reduced − f_full) / f_full
  double mac{0.0};          ///< MAC summed over the reduced modes degenerate with the pair
  bool paired{false};       ///< mac ≥ 0.5: the reduced body represents this mode
};

struct ReductionCertificate {
  // 1.
  MassProperties full, reduced;  ///< from the rigid-body mass matrices (no volume)
  MassProperties quadrature;  ///< CalcMassProperties of the mesh (independent route)
  double mass_error{0.0}, com_error{0.0}, inertia_error{0.0};  ///< reduced vs full, relative
  double quadrature_mass_error{0.0};  ///< full (RᵀMR) vs quadrature, relative
  // 2.
  Eigen::VectorXd rigid_hz;
  int num_near_zero{0};
  // 3.
  double orthonormality_error{0.0}, k_diagonality_error{0.0}, rigid_stiffness{0.0};
  double degenerate_coupling{0.0};  ///< OrthonormalModes::degenerate_coupling (reported)
  double orthonormality_limit{CertificateLimits::kOrthonormality};  ///< as scaled
  // 4.
  bool reference_run{false};
  double fmax_hz{0.0};
  std::vector<ModePair> pairs;
  double max_frequency_error{0.0};  ///< max |relative_error| over paired modes
  double min_mac{1.0};              ///< over paired modes
  int num_unrepresented{0};         ///< full modes below fmax with MAC < 0.5 to every reduced one
  std::string reference_log;  ///< the full model's eigen-solve: shift, iterations, residual
  /// Cost of the certificate's own solves: "coupled model" (items 4 and 5's reference model),
  /// "reference modes" (4: factorisation and eigen-solve), "static check" (5).
  PhaseTimes times;
  // 5.
  bool static_run{false};
  std::string static_note;    ///< support and loads, or why it was not run
  int static_loads{0};
  double static_error{0.0};   ///< max over loads of ‖d_red − d_full‖/‖d_full‖ (rotations × L)
  /// With CertificateOptions::stress_operator: StaticExactness::full_stresses, reduced_z.
  Eigen::MatrixXd static_full_stresses, static_reduced_z;
  // 6.
  std::string reduction_log;
  int constraint_mode_iterations{0};
  double constraint_mode_residual{0.0};  ///< relative residual of the constraint modes
  double constraint_mode_limit{CertificateLimits::kConstraintModes};  ///< as scaled
  // Verdict.
  std::vector<std::string> failures;
  bool passed() const { return failures.empty(); }
};

/// Certifies the reduced body (K̂, M̂ from basis.T) against the full model;
/// `elastic_shapes` = basis.T · modes.elastic (the caller has them for the invariants).
ReductionCertificate CertifyReduction(const Mesh& mesh, const SystemMatrices& sys, double density,
                                      const ReductionBasis& basis, const Eigen::MatrixXd& Khat,
                                      const Eigen::MatrixXd& Mhat, const OrthonormalModes& modes,
                                      const Eigen::MatrixXd& elastic_shapes,
                                      const CertificateOptions& options,
                                      const ProgressFn& progress = {});

}  // namespace emb
