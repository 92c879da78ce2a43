#pragma once
/// @file
/// The error indicator of a truncated free-free basis (issue 12): a part that keeps
/// `modes: N` or the modes up to `fmax_hz` of its body file loses the static completeness
/// the full basis has at its interfaces (the Craig-Bampton constraint modes are spread over
/// all free-free modes), and nothing else says so: 8 of the 14 elastic modes of a
/// root-clamped beam gave its clamped first frequency 18 % high and its tip response 29 %
/// off. The indicator is the static compliance of the kept modes at the markers that carry
/// loads or constraints (MarkerLoadsOf) against that of the full basis in the body file,
/// StaticComplianceError (static_compliance.h) with
///   K = diag(lambda) of the full basis (1/s^2, mass-normalised modes),
///   F = [shape_t^T for each force, shape_r^T for each moment a loaded marker can carry]
///       in the full basis (the interface shapes of the body file),
///   T = the kept columns of the identity,
/// so that it is 0 for the full basis and grows with what the truncation stiffens. The run
/// warns above AnalysisSettings::truncation_warning_threshold.

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "libemb/mbs/core/system.h"

namespace emb::mbs {

/// A flexible body whose elastic coordinates are a subset of a full basis.
struct TruncatedBasis {
  std::string body;                  ///< a flexible body of the system
  std::string source;                ///< where the full basis is (e.g. the body file)
  Eigen::VectorXd full_eigenvalues;  ///< lambda of the full basis, K = diag(lambda) [1/s^2]
  std::vector<int> kept;             ///< the body's coordinates: these full-basis modes
  /// The body's markers (by name) with their shapes in the full basis: rows 0-2 the
  /// translation, 3-5 the rotation per unit modal coordinate (6 x ne_full, B's axes).
  std::vector<std::pair<std::string, Eigen::MatrixXd>> markers;
};

/// What the truncation loses, per body.
struct TruncationReport {
  std::string body;
  int num_kept{0}, num_available{0};
  std::vector<std::string> loaded_markers;  ///< markers of the body that carry loads
  double static_compliance_error{0.0};      ///< see the file comment
  std::string note;  ///< one line for the run report
};

/// The reports of `bases` in `system` (markers matched by name; a loaded marker of the body
/// missing from TruncatedBasis::markers is an InternalError). A body without loaded markers
/// has error 0.
std::vector<TruncationReport> CalcTruncationReports(const System& system,
                                                    const std::vector<TruncatedBasis>& bases);

/// The warning for a report above `threshold` (empty if none): names the part and the fix.
std::string TruncationWarning(const TruncationReport& report, double threshold);

}  // namespace emb::mbs
