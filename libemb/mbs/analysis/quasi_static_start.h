#pragma once
/// @file
/// A smooth start for flexible bodies: the elastic coordinates and their rates of the
/// quasi-static deformation under the initial loads and motion, so that a run does not
/// begin with the free vibration an undeformed start excites (issue 19).
///
/// For the assembled rigid state (q_r, v_r) at t0, the elastic coordinates eta solve
///   g(eta) = eta''(q_r, eta, v_r, eta', t0) = 0,
/// the modal accelerations of the equations of motion (1.24) with the constraints at
/// acceleration level (SolveAccelerations): the elastic rows M_er v_r' + M_ee eta'' + K eta +
/// D eta' = Q_e - C_e^T lambda balanced with eta'' = 0, the rigid accelerations and the
/// reactions following. Quasi-static modes (ElasticModel::quasi_static) are included: their
/// unit start mass makes g their force balance. The rates are those of the quasi-static
/// solution along the motion: differentiating g(eta_qs(t), t) = 0,
///   eta' = -J^{-1} dg/dt|_eta,   J = dg/deta,
/// with dg/dt the change of g along the rigid motion (q_r' from v_r, v_r' from the
/// accelerations) at fixed eta and eta'. eta' changes g through damping and Coriolis terms,
/// so eta and eta' are iterated (a few outer rounds). J is a forward-difference Jacobian
/// (one acceleration solve per elastic coordinate), reused by the chord iterations.
/// Afterwards the positions are re-assembled (the deformed interfaces move the joints) and
/// the velocities projected.

#include <Eigen/Dense>
#include <string>

#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

struct QuasiStaticStartOptions {
  /// Converged when every |eta_j''| / w_j^2 (the static displacement the imbalance would
  /// cause, w_j the mode's circular frequency) is below tolerance * max(|eta|, eta_floor).
  double tolerance{1e-8};
  int max_iterations{30};  ///< chord iterations per round
  int rounds{3};           ///< eta, then eta' from it, repeated
  AssemblyOptions assembly;
};

struct QuasiStaticStartReport {
  bool converged{false};
  int iterations{0};             ///< chord iterations, all rounds
  int jacobians{0};              ///< forward-difference Jacobians (ne acceleration solves each)
  double residual{0.0};          ///< max_j |eta_j''| / w_j^2 at the end, after re-assembly [eta]
  double max_eta{0.0};           ///< max |eta| of the start [eta units]
  double max_eta_rate{0.0};      ///< max |eta'| of the start
  std::string message;           ///< what happened, for the run report
};

/// Sets the elastic coordinates of q and their rates in v to the quasi-static start at t
/// (see the file comment); q must be assembled and v consistent. A system without elastic
/// coordinates is left unchanged (converged, zero iterations). Failures are a status.
QuasiStaticStartReport SetQuasiStaticStart(const System& system, double t, Eigen::VectorXd* q,
                                           Eigen::VectorXd* v, ConstraintWorkspace* workspace,
                                           const QuasiStaticStartOptions& options = {});

}  // namespace emb::mbs
