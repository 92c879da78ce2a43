#pragma once
/// @file
/// Flexible (CMS) bodies from reduced bodies (cms/reduction.h, read from body files by
/// cms/body_file.h) in a multibody System: the floating-frame elastic model of
/// mbs/core/elastic_model.h (seed eqs. 1.27–1.30) and markers on the body's interfaces that
/// follow its deformation.
///
/// Frames. A reduced body lives in its mesh frame M: invariants about M's origin, interface
/// points in M. The multibody body frame B has M's axes and its origin at the undeformed
/// centre of mass c̄ = s̄/m (in M). A part placed with its mesh frame at (p_WM, R_WM) has
///   R_WB = R_WM,   p_WB = p_WM + R_WM c̄,
/// and a mesh point x̄_M is x̄_B = x̄_M − c̄ in B.
///
/// The elastic model in B (MakeElasticModel), with x̄_B = x̄_M − c̄ in the invariants of
/// cms/inertia_invariants.h:
///   J̄_B = J̄_M − m c̄ c̄ᵀ,   Ī_kl,B = Ī_kl,M − c̄_k S̄_t,l,   S̄_t and S̄_kl unchanged
/// (the first moment about c̄ vanishes), modal stiffness K = diag(ω_i²), damping projected on
/// the elastic modes D = sym(Xᵀ D̂ X) (X = /modes/X, D̂ the reduced damping).
/// A ModeSelection keeps a subset S of the elastic modes: every invariant, K, D, the
/// geometric-stiffness matrices (K_G,p)_SS and the interface shapes are restricted to S
/// (ElasticModel::Subset). The geometric-stiffness data are about c̄, the origin of B.
/// A part with `flexible = false` (or no mode kept) is a rigid body with the reduced body's
/// mass properties (m, c̄, the inertia about c̄ of the undeformed body).

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "libemb/cms/reduction.h"
#include "libemb/mbs/core/elastic_model.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

/// Which of a reduced body's elastic modes a multibody part keeps: the lowest `max_modes`,
/// and only those up to `fmax_hz`. (Not cms's ModeSelection, which chooses the
/// fixed-interface modes of the reduction itself.) A struct so that other bases can be added.
struct ModeSelection {
  int max_modes{-1};     ///< keep at most the lowest N (-1: no limit; 0: none, rigid part)
  double fmax_hz{-1.0};  ///< keep modes up to this frequency [Hz] (-1: no limit)
  /// Kept modes above this frequency [Hz] are quasi-static: massless, their stiffness and
  /// loads kept (ElasticModel::MakeQuasiStatic); -1: every kept mode is dynamic.
  double dynamic_band_hz{-1.0};
};

enum class GeometricStiffening {
  kIfAvailable,  ///< on when the reduced body has the data
  kOn,           ///< required: an InputError if the reduced body lacks it
  kOff,
};

struct FlexibleBodyOptions {
  bool flexible{true};  ///< false: rigid, with the reduced body's mass properties
  ModeSelection modes;
  GeometricStiffening geometric_stiffening{GeometricStiffening::kIfAvailable};
};

/// Where a part goes and how it moves at t0.
struct PartPlacement {
  Eigen::Vector3d p_WM{Eigen::Vector3d::Zero()};      ///< mesh frame origin [m]
  Eigen::Matrix3d R_WM{Eigen::Matrix3d::Identity()};  ///< mesh frame axes
  Eigen::Vector3d omega_W{Eigen::Vector3d::Zero()};   ///< angular velocity [rad/s]
  /// Velocity of the centre of mass [m/s]; by default the part spins about its mesh
  /// origin: v = ω × (p_WB − p_WM).
  std::optional<Eigen::Vector3d> v_WB;
};

/// A part made from a reduced body: what placing markers on it and reporting it need.
struct FlexiblePart {
  std::string name;    ///< the body's name
  std::string source;  ///< where the reduced body came from (e.g. its file), for messages
  int body{-1};        ///< index in the System (set by AddFlexibleBody)
  bool flexible{false};
  Eigen::Vector3d com_mesh{Eigen::Vector3d::Zero()};  ///< c̄ in M [m]
  std::vector<std::string> interface_names;
  std::vector<Eigen::Vector3d> interface_points;  ///< in M [m]
  /// 6 nb × ne (kept modes, B's axes): rows 6k..6k+2 the translation and 6k+3..6k+5 the
  /// rotation of interface k per unit modal coordinate. Empty for a rigid part.
  Eigen::MatrixXd interface_shapes;
  std::vector<int> kept_modes;  ///< indices into the reduced body's elastic modes
  int num_available_modes{0};   ///< elastic modes of the reduced body
  /// The full basis the kept modes come from (flexible parts only), for the truncation
  /// error indicator (mbs/analysis/basis_truncation.h): its eigenvalues [1/s^2] and
  /// interface shapes (as interface_shapes, every mode).
  Eigen::VectorXd available_eigenvalues;
  Eigen::MatrixXd available_interface_shapes;
  std::string note;             ///< what was kept, for the run report

  int num_modes() const { return static_cast<int>(kept_modes.size()); }
  /// Index of interface `name`. @throws InputError naming the part, the source and the
  /// available interfaces (with a did-you-mean).
  int FindInterface(const std::string& name) const;
  /// A point given in mesh coordinates, in B (from the CM).
  Eigen::Vector3d MeshToBody(const Eigen::Vector3d& p_M) const { return p_M - com_mesh; }
};

/// A body ready to be added to a System, and its part description.
struct FlexibleBodyModel {
  RigidBody body;  ///< mass properties, pose, velocities, elastic model (if flexible)
  FlexiblePart part;
};

/// The elastic model of all elastic modes of `reduced`, in B (file comment).
ElasticModel MakeElasticModel(const ReducedBody& reduced, const std::string& source);

/// Indices of the modes `selection` keeps of the ascending `frequencies_hz`.
/// @throws InputError naming `part` and `source`: more modes asked than there are, or an
/// empty band (fmax_hz below the lowest mode while modes are wanted).
std::vector<int> SelectModes(const Eigen::VectorXd& frequencies_hz, const ModeSelection& selection,
                             const std::string& part, const std::string& source);

/// Builds body `name` from `reduced` without adding it (the caller may set eta0, eta_dot0).
/// @throws InputError naming the part: SelectModes' errors, geometric stiffening asked (kOn)
/// of a reduced body without the data.
FlexibleBodyModel MakeFlexibleBody(const std::string& name, const ReducedBody& reduced,
                                   const std::string& source,
                                   const FlexibleBodyOptions& options = {},
                                   const PartPlacement& placement = {});

/// MakeFlexibleBody, with initial modal coordinates and rates (empty: zero; else one per
/// kept mode), added to `sys`. Returns the part with its body index.
/// @throws InputError as MakeFlexibleBody, for eta0/eta_dot0 of the wrong size, and as
/// System::AddBody.
FlexiblePart AddFlexibleBody(System* sys, const std::string& name, const ReducedBody& reduced,
                             const std::string& source, const FlexibleBodyOptions& options = {},
                             const PartPlacement& placement = {}, const Eigen::VectorXd& eta0 = {},
                             const Eigen::VectorXd& eta_dot0 = {});

/// Adds marker `marker` at interface `interface` of `part` with axes R_BM (in B, i.e. mesh
/// axes). On a flexible part it follows the interface node: translation and rotation shapes
/// from the kept modes' interface shapes (System::AddFlexibleMarker). Returns its index.
/// @throws InputError for an unknown interface (FlexiblePart::FindInterface).
int AddInterfaceMarker(System* sys, const FlexiblePart& part, const std::string& marker,
                       const std::string& interface,
                       const Eigen::Matrix3d& R_BM = Eigen::Matrix3d::Identity());

/// Reads the body file `path` for part `part` (ReadBodyFile), refusing a file reduced from
/// another mesh when `expect_mesh_hash` is given (CheckBodyProvenance).
/// @throws InputError "part '<part>': ..." with the file's error.
ReducedBody ReadPartBodyFile(const std::string& path, const std::string& part,
                             const std::string& expect_mesh_hash = "");

}  // namespace emb::mbs
