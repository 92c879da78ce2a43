#pragma once
/// @file
/// Stress recovery on a flexible part during a multibody run (issue 17): hot-spot stresses
/// of the surface groups whose modal stresses the body file holds (cms/modal_stress.h).
///
/// With eta the part's elastic coordinates (the kept modes S of the body file, possibly in
/// a changed basis eta = T xi: installed_basis.h), the stress at node i of group g is
///     sigma_i = Sigma_g,i eta      (6 components, Voigt xx yy zz xy yz zx, mesh axes) [Pa],
/// Sigma_g,i the node's six rows of the file's modal stresses restricted to S (and times T
/// after a basis change, WithElasticBasis): the map back to the body file's coordinates is in
/// the rows, so the stresses are those of the file's basis whatever the run integrates.
/// Only the elastic deformation is stressed: rigid motion and the inertia of the frame act
/// through eta (their quasi-static share included when the basis has it).
///
/// Channels per group g (in that order):
///   g.von_mises            max over the group's nodes of the von Mises stress [Pa]
///   g.von_mises_node       the mesh node (0-based) where it is
///   g.max_principal        max over the nodes of the largest principal stress sigma_1 [Pa]
///   g.max_principal_node   its node
/// then per chosen node N: nN.xx, nN.yy, nN.zz, nN.xy, nN.yz, nN.zx [Pa] (N the 0-based
/// mesh index), and per node chosen by its mesh file's tag T: tagT.xx ... tagT.zx.
/// Cost per evaluation O(6 m n) for m nodes and n elastic coordinates, plus closed-form
/// principal stresses per node (fe/stress_measures.h). The last evaluation is kept
/// (Evaluate): the stress recorder's per-node histories at a sample reuse the channels' work.

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "libemb/cms/modal_stress.h"
#include "libemb/mbs/core/probe.h"
#include "libemb/mbs/parts/flexible_body.h"

namespace emb::mbs {

/// What a stress output asks for.
struct StressProbeSpec {
  std::string name;                 ///< probe name (channel prefix)
  std::vector<std::string> groups;  ///< stress groups of the body file; empty: all of them
  std::vector<int> nodes;           ///< mesh nodes (0-based) with full component histories
  std::vector<long long> node_tags;  ///< the same by the mesh file's (gmsh's) node tags
  bool surface{false};              ///< also keep the whole-surface rows (field output only)
};

/// One group's node stresses in the part's current elastic coordinates.
struct StressRows {
  std::string name;
  std::vector<int> nodes;  ///< mesh nodes
  Eigen::MatrixXd rows;    ///< 6 m x n: sigma = rows * eta
};

/// Every group's node stresses and their measures at one state.
struct StressSnapshot {
  std::vector<Eigen::MatrixXd> sigma;          ///< per group, 6 x m [Pa]
  std::vector<Eigen::VectorXd> von_mises;      ///< per group, m [Pa]
  std::vector<Eigen::VectorXd> max_principal;  ///< sigma_1 per node [Pa]
  std::vector<Eigen::VectorXd> min_principal;  ///< sigma_3 per node [Pa]
};

class StressProbe final : public Probe {
 public:
  /// @throws InputError naming the probe if a component node is in none of the groups.
  /// `surface`: the whole-surface rows (name "surface"; no channels: the stress recorder
  /// writes its field at chosen times), empty rows for none.
  /// `labels`: the channel prefix of each component node ("n<node>" where empty).
  StressProbe(std::string name, int body, std::vector<StressRows> groups, std::vector<int> nodes,
              StressRows surface = {}, std::vector<std::string> labels = {});
  std::vector<int> bodies() const override { return {body_}; }
  std::shared_ptr<const Probe> WithElasticBasis(int body, const Eigen::MatrixXd& T) const override;
  int body() const { return body_; }
  const std::vector<StressRows>& groups() const { return groups_; }
  /// Stresses (6 x m, column i = node i of the group) of group `g` at elastic coordinates
  /// `eta` of the part. @pre eta.size() == number of the part's elastic coordinates.
  Eigen::MatrixXd GroupStresses(int g, const Eigen::VectorXd& eta) const;
  /// Whether the probe holds the whole-surface rows (StressProbeSpec::surface).
  bool has_surface() const { return surface_.rows.size() > 0; }
  /// The whole-surface rows (mesh nodes of the body file's surface, sigma = rows * eta).
  const StressRows& surface() const { return surface_; }
  /// Stresses (6 x s, column i = surface node i) on the whole surface at `eta`. Cost
  /// O(6 s n). @pre has_surface().
  Eigen::MatrixXd SurfaceStresses(const Eigen::VectorXd& eta) const;
  /// All groups' stresses and measures at elastic coordinates `eta`, into the caller's
  /// snapshot (its vectors reused). The probe keeps nothing: it lives in the immutable
  /// System, so a caller that reads one sample several times (the stress recorder) keeps the
  /// snapshot itself.
  void Evaluate(const Eigen::VectorXd& eta, StressSnapshot* out) const;

 protected:
  void DoEval(const System& system, const std::vector<BodyKinematics>& bodies,
              const Eigen::VectorXd& vdot, Eigen::Ref<Eigen::VectorXd> values) const override;

 private:
  int body_;
  std::vector<StressRows> groups_;
  std::vector<int> nodes_;                         // component nodes
  std::vector<std::string> labels_;                // their channel prefixes
  std::vector<std::pair<int, int>> node_slots_;    // (group, index in the group) per node
  StressRows surface_;                             // whole surface (rows empty: none)
};

/// The probe of `spec` on `part` from the body file's modal stress groups `file_groups`
/// (ReducedBody::stress_groups of the part's file) and, if spec.surface, its whole-surface
/// modal stresses `file_surface` (ReducedBody::stress_surface). A file with a surface but no
/// groups gives a probe without groups (and channels) when spec names no group or node.
/// @throws InputError naming the probe, the part and its file: a rigid part, a body file
///   without modal stresses ("reduce it with --stress-groups"), an unknown group (with the
///   groups the file has and a did-you-mean), a node in none of the groups, a surface asked
///   from a file without one ("reduce it with --stress-surface") or together with a group
///   named "surface" (both fields would be called so).
std::shared_ptr<StressProbe> MakeStressProbe(const FlexiblePart& part,
                                             const std::vector<ModalStressGroup>& file_groups,
                                             const StressProbeSpec& spec,
                                             const ModalStressSurface* file_surface = nullptr);

}  // namespace emb::mbs
