#pragma once
/// @file
/// The body file: a reduced flexible body in HDF5 ("emb.body", version 1).
///
/// Units SI (m, kg, s, N, rad); frequencies in Hz, eigenvalues in rad²/s². Matrices are stored
/// row-major with their natural shape (numpy sees K as (nr, nr)). nr = reduced coordinates
/// z = (q_1 … q_nb, η): six per interface (t_x t_y t_z θ_x θ_y θ_z of its reference node, in
/// interface order), then the kept fixed-interface modal coordinates. ne = elastic modes.
///
///   /                      @format "emb.body", @format_version 1, @emb_version, @units,
///                          @content_digest (FNV-1a of every numeric dataset below except
///                          /mesh and /modes/mesh_shapes, in a fixed order, /geometric_stiffness
///                          last if present, then — @content_digest_version 2 — the
///                          attributes and interface names the reader uses: provenance,
///                          material, /reduced counts, damping, stiffening support; a changed
///                          byte is detected on reading. Files without the version attribute
///                          (version 1) have only the datasets covered)
///   /provenance            @command @source @mesh_hash @options @element_types
///                          @interfaces ("name:coupling@x,y,z; ...") @selection @shift_hz
///   /material              @name @youngs_modulus [Pa] @poisson_ratio @density [kg/m³]
///   /interfaces/names, /interfaces/couplings, /interfaces/point_sources   (nb strings)
///   /interfaces/points     (nb, 3) reference points [m]
///   /interfaces/<name>/nodes, /interfaces/<name>/weights   surface nodes (0-based) and w_s
///   /reduced/K, /reduced/M, /reduced/D   (nr, nr)   @num_boundary @free_free
///   /reduced/rigid         (nr, 6) the rigid motions about the origin in z
///   /fixed_interface/frequencies_hz   (kept fixed-interface modes; free-free modes if
///                          @free_free)  @selection_note @eigen_log @static_iterations
///                          @static_residual
///   /modes/frequencies_hz, /modes/eigenvalues, /modes/damping_ratios   (ne)
///   /modes/X               (nr, ne) z = X ξ; XᵀM̂X = I, XᵀK̂X = diag(λ)
///   /modes/rigid           (nr, 6) M̂-orthonormal rigid-body modes
///   /modes/interface_shapes (6·nb, ne) = rows of X for the interface coordinates
///   /modes/rigid_frequencies_hz (6) of the unconstrained reduced problem (≈ 0)
///   /damping               @model "modal" (@ratio) or "rayleigh" (@alpha [1/s], @beta [s])
///   /invariants            @form "Shabana" @frame "mesh" @mass [kg]
///     first_moment (3), second_moment (3, 3), St (3, ne), Ibar (9, ne) [row 3k+l = Ī_kl],
///     Sbar (9, ne, ne) [3k+l = S̄_kl]  (see inertia_invariants.h for the definitions)
///   /certificate           @passed @mass_error @com_error @inertia_error
///                          @quadrature_mass_error @num_near_zero @orthonormality_error
///                          @k_diagonality_error @degenerate_coupling @rigid_stiffness @fmax_hz @reference_run
///                          @max_frequency_error @min_mac @reference_log @static_run
///                          @static_note @static_error @reduction_log
///     rigid_hz (6), pairs (k, 6): full_mode, full_hz, reduced_mode, reduced_hz,
///     relative_error, mac; failures (strings)
///   /geometric_stiffness   (optional: absent if reduced with --no-geometric-stiffness and in
///                          files written before it existed; see geometric_stiffening.h)
///                          @support "interfaces held" | "inertia relief"
///                          @centrifugal_products "wx^2, wy^2, wz^2, wx*wy, wy*wz, wz*wx"
///                          @translational_components "ax, ay, az"
///     centrifugal (6, ne, ne) K_G,p = Φᵀ K_σ(σ_p) Φ per unit product c_p(ω) [-]
///     translational (3, ne, ne) K_G,6+k per unit a_k [1/m] (a: frame-origin acceleration
///                          minus gravity, in B)
///     reference_point (3)  c̄, the undeformed centre of mass: the origin of B [m]
///   /stress                (optional: modal stresses at named surface groups, modal_stress.h;
///                          present → @content_digest_version 3, which digests them too)
///     names, <name>/nodes (m), <name>/modal (6 m, ne)  [Pa per unit elastic coordinate]
///     surface/…            (optional: the whole boundary surface, surface_stress.h; present →
///                          @content_digest_version 4) face_types, nodes (s), coordinates
///                          (s, 3), faces/<Type> (f, k), modal (6 s, ne)
///   /mesh …                the mesh (see mesh_io.h), and
///   /modes/mesh_shapes     (ne, n, 3) Φ = T X at every node  — both only if kept
///
/// Reading it back needs no emb: see the h5py snippet in README.md.

#include <string>

#include "libemb/cms/reduction.h"
#include "libemb/io/provenance.h"
#include "libemb/mesh/mesh.h"

namespace emb {

inline constexpr const char* kBodyFormat = "emb.body";
inline constexpr int kBodyFormatVersion = 1;
inline constexpr const char* kGeometricStiffnessGroup = "/geometric_stiffness";

/// What a body file records besides the body.
struct BodyFileInfo {
  Provenance provenance;
  IsotropicMaterial material;
  std::string element_types;  ///< e.g. "Tet10"
  std::string interfaces;     ///< the interface specs, "name:coupling@x,y,z; ..."
  std::string selection;      ///< ModeSelection::Describe()
  double shift_hz{0.0};
  std::string content_digest;
  int format_version{0};
};

/// Writes `body` to `path` atomically (temp + rename); with `mesh` non-null and
/// body.mesh_shapes kept, also the mesh and the mode shapes at all nodes, plus an XDMF file
/// `xdmf_path` (if not empty) for ParaView.
/// @throws InputError if the directory does not exist or HDF5 fails.
void WriteBodyFile(const std::string& path, const std::string& xdmf_path, const ReducedBody& body,
                   const BodyFileInfo& info, const Mesh* mesh);

/// Reads a body file (without the mesh and its mode shapes). The content digest is recomputed
/// and must match: a tampered or truncated file is refused.
/// @throws InputError naming the file for a missing file, another format or version, a
///   missing dataset, or a digest mismatch.
ReducedBody ReadBodyFile(const std::string& path, BodyFileInfo* info = nullptr);

/// Refuses a body whose provenance does not match what the caller uses: a different mesh hash
/// (always checked), or a different material (if given).
/// @throws InputError naming the file and both values ("stale basis: run emb reduce again").
void CheckBodyProvenance(const std::string& path, const BodyFileInfo& info,
                         const std::string& expected_mesh_hash,
                         const IsotropicMaterial* expected_material = nullptr);

}  // namespace emb
