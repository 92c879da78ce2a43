#pragma once
/// @file
/// The elastic basis a flexible body needs in the model it is installed in (issue 12): a
/// band of *installed* dynamics plus static completeness at the places it is loaded.
///
/// A body file's free-free modes are the wrong currency for "a band": inside an engine the
/// crank sits on stiff bearings, carries the flywheel at its flange and the rods at its pins,
/// and its installed modes below, say, 3 kHz are made of free-free modes far above it. So
/// the basis is built from the whole model linearised at the start (linearization.h,
/// undamped: M, K with the multipliers' and centrifugal terms, on null(C)):
///
///  1. Dynamic coordinates V_d: the body's part (its modal rows eta) of every installed mode
///     at or below `dynamic_band_hz`, M-orthonormalised (M = sum_i Sbar_ii, the body's
///     modal mass) and rotated to the Ritz vectors of the body's own K, M in that span (so
///     each has a frequency, the modal velocity tolerance and the reports use it).
///  2. Quasi-static coordinates V_s: the static responses K^-1 F of the body to every load
///     it can feel: the shapes of its loaded markers, F = Phi_m^T for the forces and
///     Psi_m^T for the moments a marker can carry (the constraint kernels' structure: a
///     point-on-axis joint puts only a force on its point's marker; the force elements'
///     ForceElement::MarkerLoads), and its inertia loads (the rows of Ibar: centrifugal and frame-acceleration loads of a
///     spinning body), M-orthogonalised against V_d, orthonormalised, Ritz-rotated. They
///     are massless (ElasticModel::MakeQuasiStatic): at every instant they take the static
///     response to the loads, so the static compliance of the full basis at every loaded
///     marker is kept exactly (the "residual flexibility" or mode-acceleration correction).
///
/// With eta = [V_d V_s] xi the body has n_d + n_s coordinates instead of ne (System::
/// WithElasticBases). What the basis misses is the inertia of the static shapes and the
/// installed dynamics above the band; the report quotes the first installed frequency
/// left out. Cost: one dense eigen-solve of the linearised model, O(nv^3).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "libemb/mbs/core/system.h"

namespace emb::mbs {

class ConstraintWorkspace;

/// Which body gets an installed basis, and its band.
struct InstalledBasisRequest {
  std::string body;              ///< a flexible body of the system
  double dynamic_band_hz{-1.0};  ///< installed modes up to this frequency are dynamic [Hz]
  /// The quasi-static coordinates relax to their static response with the time constant
  /// tau = relaxation / (2 pi dynamic_band_hz) (ElasticModel::AddRelaxationDamping): what
  /// rides on the massless static flexibility (rods on a crankpin, a flywheel on a flange)
  /// gets damped above the band instead of ringing with the ~1 % damping of the high modes
  /// its static shapes are made of, which the integrator would otherwise resolve. Measured
  /// on the inline-4 at a 2 kHz band (benchmarks/results/inline4_basis.json, rows relax*):
  /// 0.01 takes about 2.5x the steps of 0.1, 1 moves a bearing force by over 1 %; 0 adds
  /// nothing.
  double relaxation{0.1};
};

/// What CalcInstalledBases made of one body.
struct InstalledBasisReport {
  std::string body;
  int num_available{0};      ///< elastic coordinates before
  int num_dynamic{0};        ///< n_d
  int num_quasi_static{0};   ///< n_s
  int num_loaded_markers{0};
  double dynamic_band_hz{0.0};
  double highest_kept_hz{0.0};      ///< highest installed mode of the model in the band
  double first_left_out_hz{0.0};    ///< lowest installed mode above the band (0: none)
  /// Largest relative difference between the static compliance of the new basis and of
  /// the full one at the loaded markers' directions, max |C_new - C_full| / max |C_full|
  /// (round-off: the static shapes are in the basis).
  double static_compliance_error{0.0};
  std::string note;  ///< one line for the run report
};

struct InstalledBases {
  std::vector<ElasticBasisChange> changes;
  std::vector<InstalledBasisReport> reports;
};

/// The installed bases of the requested bodies at the state (q, v, t) with multipliers
/// `lambda` (SolveAccelerations), see the file comment. @throws InputError naming the body
/// for an unknown or rigid body or a band <= 0; NumericalError if the linearisation fails.
InstalledBases CalcInstalledBases(const System& system, const Eigen::VectorXd& q,
                                  const Eigen::VectorXd& v, double t,
                                  const Eigen::VectorXd& lambda, ConstraintWorkspace* workspace,
                                  const std::vector<InstalledBasisRequest>& requests);

/// Coordinates x of `from` (q-like if `positions`, else v-like) in `to` =
/// from.WithElasticBases(changes): the rigid-body part copied, each changed body's eta
/// mapped to the least-squares xi of T xi = eta, the others' eta copied.
Eigen::VectorXd MapElasticCoordinates(const System& from, const System& to,
                                      const std::vector<ElasticBasisChange>& changes,
                                      const Eigen::VectorXd& x, bool positions);

}  // namespace emb::mbs
