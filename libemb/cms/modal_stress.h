#pragma once
/// @file
/// Modal stresses of a reduced body at named surface groups (issue 17: the crankpin and
/// journal fillets, where cranks fail), so that a multibody run recovers stresses from its
/// elastic coordinates without the FE model.
///
/// For group g with mesh nodes n_1 … n_m and the body's elastic mode shapes Φ = T X (T the
/// Craig–Bampton basis: constraint and fixed-interface modes; X the orthonormalised elastic
/// modes the body file stores, reduction.h), the modal stresses are
///     Σ_g = S_g Φ   (6 m × ne)   [Pa per unit ξ, i.e. Pa / (kg^½ m)],
/// S_g the nodal-averaged stress operator of fe/nodal_stress.h (Voigt order xx, yy, zz, xy,
/// yz, zx; mesh axes; row 6 i + c = component c at node n_i). The stress of an elastic state
/// ξ (the body file's elastic coordinates, eta of a multibody body that keeps every mode) is
/// σ = Σ_g ξ; the six rigid-body modes carry no stress.
///
/// Exactness: the static response to loads at the interfaces lies in the Craig–Bampton span
/// (its constraint modes), so σ of that response from Σ_g equals the full FE model's up to
/// round-off whatever the number of fixed-interface modes (CheckModalStresses). Dynamic
/// stresses converge with the fixed-interface modes kept.
///
/// Body file (format version 1, optional group, digest version 3 when present):
///   /stress                @components "xx, yy, zz, xy, yz, zx" @recovery (text)
///                          @units "Pa per unit elastic coordinate"
///     names                (g strings)
///     <name>/nodes         (m) 0-based mesh nodes
///     <name>/modal         (6 m, ne) Σ_g, row 6 i + c
///     surface/…            the whole boundary surface (surface_stress.h; digest version 4)

#include <string>
#include <vector>

#include <Eigen/Core>

#include "libemb/cms/surface_stress.h"
#include "libemb/fe/material.h"
#include "libemb/linalg/sparse_types.h"
#include "libemb/mesh/mesh.h"

namespace emb {

namespace body_codec {
class Codec;
}

inline constexpr const char* kStressGroup = "/stress";
inline constexpr const char* kStressComponentNames = "xx, yy, zz, xy, yz, zx";

/// The modal stresses of one surface group.
struct ModalStressGroup {
  std::string name;
  std::vector<int> nodes;    ///< mesh nodes, ascending
  Eigen::MatrixXd stresses;  ///< 6 m × ne, Σ_g of the file comment [Pa per unit ξ]
  /// The mesh file's (gmsh's) tags of `nodes`, as scenes name nodes elsewhere; empty in body
  /// files written before emb stored them.
  std::vector<int> node_tags;
  int num_nodes() const { return static_cast<int>(nodes.size()); }
};

/// The surface groups of `mesh` named crankpin_fillet_<i> or journal_fillet_<k> (the crank
/// meshes' fillets), in mesh order; empty for other meshes.
std::vector<std::string> DefaultStressGroups(const Mesh& mesh);

/// The nodal stress operators of `groups` stacked (Σ_g rows in group order): S (6 Σm × 3n).
/// @throws InputError naming a group that does not exist (listing those that do) or is not
///   a surface group, or a repeated group.
SparseMatrix BuildGroupStressOperator(const Mesh& mesh, const IsotropicMaterial& material,
                                      const std::vector<std::string>& groups);

/// Σ_g = S_g Φ for every group (Φ: 3n × ne mode shapes at all nodes). Throws as above.
/// Cost: one sparse-dense product per group, O(nnz(S_g) · ne).
std::vector<ModalStressGroup> CalcModalStresses(const Mesh& mesh, const IsotropicMaterial& material,
                                                const Eigen::MatrixXd& Phi,
                                                const std::vector<std::string>& groups);

/// Modal stresses against the full FE model under the same interface loads: the static
/// load cases of the certificate (one interface held, unit forces and moments at the
/// others, six columns per loaded interface: forces then moments; static_exactness.h). Per
/// group and kind of load (unit forces, unit moments: one unit each),
///     max_k ‖σ_red,k − σ_full,k‖_∞ / max_k ‖σ_full,k‖_∞   over the loads k of that kind
/// and the group's components, the larger of the two kinds; σ_full = S_g u_full and
/// σ_red = Σ_g ξ with ξ = Xᵀ M̂ z the elastic part of the reduced static solution z (the route
/// a multibody run takes). Relative to the group's largest stress per unit load, not per
/// load case: a load that does not reach the group leaves it round-off only.
struct ModalStressCheck {
  bool run{false};
  std::string note;                  ///< what was loaded, or why it was not run
  int num_loads{0};
  std::vector<std::string> groups;
  std::vector<double> errors;        ///< per group
  std::vector<double> peak_stress;   ///< per group: max ‖σ_full‖_∞ over the loads [Pa per N or N m]
  double max_error{0.0};
};

/// @param full_stresses  S u_full (6 Σm × loads), the groups stacked as in `groups`
/// @param reduced_z      the reduced static solutions z (nr × loads)
/// @param X, Mhat        the body's elastic modes (nr × ne) and reduced mass (nr × nr)
ModalStressCheck CheckModalStresses(const std::vector<ModalStressGroup>& groups,
                                    const Eigen::MatrixXd& full_stresses,
                                    const Eigen::MatrixXd& reduced_z, const Eigen::MatrixXd& X,
                                    const Eigen::MatrixXd& Mhat, const std::string& note);

/// Writes or reads the optional /stress group of a body file through `codec` (internal to
/// body_file.cpp): the groups, then the whole surface (surface_stress.h) if present; reading,
/// absent in the file → `groups` / `surface` empty. Stress matrices must have `ne` columns.
/// @throws InputError naming the file and dataset for a wrong shape.
void TransferModalStresses(body_codec::Codec& codec, std::vector<ModalStressGroup>& groups,
                           ModalStressSurface& surface, Eigen::Index ne);

}  // namespace emb
