#pragma once
/// @file
/// Natural frequencies and mode shapes by the transfer-matrix method: the roots of the
/// boundary determinant of a TmmChain in a frequency band, none missed.
///
/// Algorithm. The band [f_lo, f_hi] is scanned on a uniform grid in f; at each grid point
/// the scaled determinant det B(λ) (tmm_chain.h) and the count N(λ) of eigenvalues below λ
/// are evaluated. An interval whose count rises by one and whose determinant changes sign is
/// refined by Brent's method on the determinant, with the row/column scaling frozen at the
/// interval's midpoint (so it is a polynomial in λ). An interval whose count rises by k ≥ 2
/// (close or degenerate roots, e.g. the two bending planes of a round shaft, where det B has
/// a double root and no sign change) is bisected on the count until its pieces hold one
/// root each, or until it is narrower than `cluster_tolerance`·λ: then it is one root of
/// multiplicity k, located to round-off as the minimum of the k-th smallest singular value
/// of the scaled B(λ) (which vanishes linearly there, where det B only touches zero).
/// A root's mode shapes are the right singular vectors of the scaled B(λ) for its k smallest
/// singular values, propagated along the chain and made M-orthonormal with the lumped mass.
/// The count makes the search exhaustive: the number of roots returned is N(λ_hi) − N(λ_lo)
/// by construction, and a sign change of the determinant without a count change is reported.
///
/// Frequencies below `zero_frequency_hz` (the rigid-body modes of a free model) are counted,
/// not searched: det B has a root of multiplicity up to 6 at λ = 0.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "libemb/beam/tmm_chain.h"

namespace emb {

struct TmmOptions {
  TmmMotion motion{TmmMotion::kFull};
  double min_hz{0.0};              ///< band start [Hz], ≥ 0
  double max_hz{0.0};              ///< band end [Hz], > min_hz
  int scan_intervals{200};         ///< grid intervals over the band (uniform in f), ≥ 1
  double zero_frequency_hz{1e-2};  ///< modes below are rigid-body modes, counted only [Hz]
  /// Roots closer than this (relative, in λ) are one root of higher multiplicity. The count
  /// is exact well below it (its pivots are ~1e-9 of their scale there, far above round-off).
  double cluster_tolerance{1e-9};
};

enum class TmmStatus {
  kSuccess,
  kNoRoots,        ///< the band holds no natural frequency (message says which band)
  kInconsistent,   ///< determinant and count disagree somewhere (message says where)
};

/// "success", "no roots", "inconsistent".
const char* Name(TmmStatus status);

/// One natural frequency (a root of multiplicity k is k entries with the same frequency).
struct TmmMode {
  int index{0};            ///< 1-based position in the spectrum of the motion set (count)
  double lambda{0.0};      ///< ω² [rad²/s²]
  double frequency_hz{0.0};
  int multiplicity{1};     ///< of the root this mode belongs to
  std::string refinement;  ///< "brent" or "singular-value minimum"
  Eigen::MatrixXd motion;  ///< node motions 6 × num_nodes (W), M-orthonormal (lumped M)
  double boundary_residual{0.0};  ///< σ_min/σ_max of the scaled B at the root
};

struct TmmResult {
  TmmStatus status{TmmStatus::kSuccess};
  std::string message;
  TmmMotion motion{TmmMotion::kFull};
  BeamMassType mass_type{BeamMassType::kLumped};  ///< TMM is always the lumped model
  double min_hz{0.0}, max_hz{0.0};
  std::vector<TmmMode> modes;             ///< ascending
  int num_zero_frequency_modes{0};        ///< below zero_frequency_hz (if min_hz is below it)
  int num_below_band{0};                  ///< N(λ_lo): modes below the band (incl. zero ones)
  int num_determinant_evaluations{0};
  int num_count_evaluations{0};
  std::vector<int> node_order;            ///< the chain
  bool ok() const { return status == TmmStatus::kSuccess; }
  /// The modes' frequencies [Hz].
  Eigen::VectorXd frequencies_hz() const;
};

/// The natural frequencies of `model` (as a chain of transfer matrices) in the band.
/// @throws InputError for a bad band or grid, or a model TmmChain rejects (named).
/// Numerical outcomes (no root in the band, an inconsistency) are in TmmResult::status.
/// Cost: (scan_intervals + refinement steps) · O(chain); refinement ~10–60 evaluations per
/// root.
TmmResult CalcTmmModes(const BeamModel& model, const TmmOptions& options);

/// The same on an already built chain.
TmmResult CalcTmmModes(const TmmChain& chain, const TmmOptions& options);

}  // namespace emb
