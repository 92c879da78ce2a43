#pragma once
/// @file
/// The offline mode-reduction job: mesh + material + interfaces → a certified reduced body.
///
///     K, M (FE)  →  Craig–Bampton basis T  →  K̂ = TᵀKT, M̂ = TᵀMT  →  orthonormal modes X
///     →  inertia invariants of Φ = T X  →  damping D̂  →  certificate
///     →  geometric stiffening K_G,p = Φᵀ K_σ(σ_p) Φ of nine inertial load cases (optional)
///
/// The reduced coordinates are z = (q_1, …, q_nb, η) (six per interface, then the kept
/// fixed-interface modal coordinates); the elastic coordinates of the floating frame are
/// ξ = Xᵀ M̂ z, i.e. z = X ξ for an elastic motion. Interface j moves by rows 6j..6j+5 of X.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "libemb/cms/certificate.h"
#include "libemb/cms/craig_bampton.h"
#include "libemb/cms/geometric_stiffening.h"
#include "libemb/cms/inertia_invariants.h"
#include "libemb/cms/interface.h"
#include "libemb/cms/modal_stress.h"
#include "libemb/cms/orthonormal_modes.h"
#include "libemb/fe/material.h"

namespace emb {

/// Damping of the elastic modes: a ratio per mode, or Rayleigh D = α M + β K.
struct DampingModel {
  enum class Kind { kModal, kRayleigh };
  Kind kind{Kind::kModal};
  double ratio{0.01};  ///< ζ of every elastic mode (kModal); 1 %, the seed's default
  double alpha{0.0};   ///< [1/s] (kRayleigh)
  double beta{0.0};    ///< [s]   (kRayleigh)
  std::string Describe() const;
};

struct ReductionJob {
  std::vector<InterfaceSpec> interfaces;  ///< empty: free-free basis
  ReductionOptions reduction;
  DampingModel damping;
  CertificateOptions certificate;
  bool keep_mesh_shapes{true};            ///< keep Φ = T X at all nodes (for animation)
  /// Compute the stress-stiffening matrices of the nine inertial load cases
  /// (geometric_stiffening.h); costs nine static solves on the existing factorisation plus
  /// nine stress recoveries and geometric-stiffness assemblies.
  bool geometric_stiffness{true};
  /// Names of the interfaces held in those load cases, i.e. clamped in service (e.g. the
  /// root of a blade); the others are free (their boundary coordinates take the static
  /// response, K̂_FF q_F = Ψ_Fᵀ F). Empty: every interface held. An interface that only
  /// carries a sensor or a light attachment must be left out, or its stress (e.g. a free
  /// blade tip held axially: compression instead of centrifugal tension) is wrong.
  std::vector<std::string> stiffening_supports;
  /// Surface groups whose modal stresses are stored (modal_stress.h); checked against the
  /// full FE model in the certificate's static load cases when that check runs.
  std::vector<std::string> stress_groups;
  /// Also store the modal stresses on the whole boundary surface (surface_stress.h), for the
  /// whole-surface stress field of a run (ParaView).
  bool stress_surface{false};
};

/// A reduced flexible body: everything a multibody run (and Python) needs.
struct ReducedBody {
  /// kDone, or the numerical step that failed (message); the rest is then incomplete.
  ReductionStatus status{ReductionStatus::kDone};
  std::string message;
  bool ok() const { return status == ReductionStatus::kDone; }
  std::vector<Interface> interfaces;
  bool free_free{false};
  int num_boundary{0};                 ///< 6 · interfaces (6 rigid coordinates if free-free)
  Eigen::MatrixXd K, M, D;             ///< reduced (nr × nr) in coordinates z
  Eigen::VectorXd fixed_interface_hz;  ///< kept fixed-interface (or free-free) modes [Hz]
  std::string selection_note;
  OrthonormalModes modes;
  Eigen::VectorXd damping_ratios;      ///< ζ_i of the elastic modes (both models)
  DampingModel damping;
  Eigen::MatrixXd interface_shapes;    ///< 6·nb × ne: (t, θ) of every interface per mode
  InertiaInvariants invariants;        ///< of the elastic modes Φ = T X
  ReductionCertificate certificate;
  GeometricStiffness geometric_stiffness;  ///< present unless the job switched it off
  std::vector<ModalStressGroup> stress_groups;  ///< modal stresses (modal_stress.h)
  ModalStressSurface stress_surface;   ///< on the whole surface (surface_stress.h), optional
  ModalStressCheck stress_check;       ///< against the full model (not stored in the file)
  Eigen::MatrixXd mesh_shapes;         ///< 3n × ne, empty unless kept
  int num_fe_dofs{0};
  PhaseTimes times;
  /// False on an MPI rank other than 0 of a distributed reduction (ReductionOptions::
  /// pencil_solver): it took part in the solves and holds nothing else; rank 0 has the body.
  bool on_this_process{true};
};

/// Runs the job on an assembled part. With a distributed pencil solver in job.reduction every
/// rank calls it (collective until the basis is built), and only rank 0's body is complete.
/// @throws InputError as the steps do (see craig_bampton.h, interface.h); a numerical step
/// that fails (factorisation, eigen-solves, static solves, the reduced eigenproblem) is the
/// body's status, on every rank of a distributed reduction.
ReducedBody ReduceBody(const Mesh& mesh, const SystemMatrices& sys,
                       const IsotropicMaterial& material, const ReductionJob& job,
                       const ProgressFn& progress = {});

}  // namespace emb
