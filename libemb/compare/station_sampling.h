#pragma once
/// @file
/// Stations: points on a part's axis where the mode shapes of its beam model and of its 3-D
/// FE model are compared (MAC), and the sampling of both kinds of shape there.
///
/// A station s sits at a beam node N (position p_s) and owns the 3-D mesh nodes inside the
/// part's prism around it: |x − x_s| ≤ w_s and distance from the segment's axis ≤ R_o (1 + 1e-3).
/// The 3-D motion of the station is the least-squares rigid fit of those nodes' motions,
///   q_s = argmin Σ_n ‖u_n − (t + θ × r_n)‖²,   r_n = x_n − p_s,
/// i.e. q_s = (Σ B_nᵀB_n)⁻¹ Σ B_nᵀ u_n with B_n = [I₃ −[r_n×]] — the motion a beam can
/// describe. What is left, e_n = u_n − B_n q_s, is the deformation of the cross-section; the
/// section-deformation ratio of a mode, ρ = √(Σ‖e_n‖² / Σ‖u_n‖²) over all station nodes,
/// is ~0 for beam-like modes (bending, torsion, axial) and ~1 for shell modes (ovalling,
/// circumferential waves), which no beam can represent.
/// A sampled shape stacks per station (t, θ·R_s), R_s the station's section radius, so that
/// translations and rotations weigh alike in a MAC (torsion moves a journal centre by θ only).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "libemb/beam/beam_geometry.h"
#include "libemb/mesh/mesh.h"

namespace emb {

struct Station {
  std::string name;      ///< the beam node's name (e.g. "main_journal_3", "tube:12")
  int beam_node{-1};
  Eigen::Vector3d p_W{Eigen::Vector3d::Zero()};  ///< [m]
  double radius{0.0};    ///< R_s, outer radius of the segment [m]
  double half_width{0.0};///< w_s [m]
  std::vector<int> mesh_nodes;  ///< 3-D nodes sampled, ascending
};

/// At least this many 3-D nodes per station (so the six-unknown fit is well posed).
inline constexpr int kMinStationNodes = 12;

/// The stations of a generated beam model on `mesh`: the mid-length node of every segment
/// except journal necks ("neck_*", a few mm long) — journals, crankpins, nose, flange — or,
/// for a part made of one segment (a tube), `axis_stations` nodes evenly along it (ends
/// included). w_s: half the segment for a mid-length station, else half an element, widened
/// (×1.5 steps up to half the segment) until the station holds kMinStationNodes nodes.
/// @throws InputError naming the station if it holds too few mesh nodes (the models are not
///         of the same part, or the mesh is far too coarse), or axis_stations < 2.
std::vector<Station> MakeStations(const GeneratedBeamModel& beam, const Mesh& mesh,
                                  int axis_stations);

struct SampledShapes {
  Eigen::MatrixXd values;                ///< 6·stations × modes, per station (t, θ·R_s)
  Eigen::VectorXd section_deformation;   ///< ρ per mode (file comment); empty for beams
};

/// Samples 3-D shapes (3·mesh nodes × modes, node-major) at the stations. Cost O(station
/// nodes · modes).
SampledShapes SampleMeshShapes(const Mesh& mesh, const std::vector<Station>& stations,
                               const Eigen::MatrixXd& shapes);

/// Samples beam shapes of `model` (6·nodes × modes, BeamDof order) at the stations, found in
/// the model by their names (so stations made on one variant of a part's beam model serve
/// another, e.g. with elastic webs). @throws InputError if a station has no node in `model`.
SampledShapes SampleBeamShapes(const BeamModel& model, const std::vector<Station>& stations,
                               const Eigen::MatrixXd& shapes);

}  // namespace emb
