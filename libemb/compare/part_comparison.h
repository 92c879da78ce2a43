#pragma once
/// @file
/// The beam-vs-CMS benchmark of one part (issue 6): natural frequencies of the same geometry
/// by every route emb has, against the full 3-D FE model.
///
/// Routes (each timed on its own, wall clock, including what it alone needs):
///  - "fe": the full 3-D FE model (reference): mesh + assembly + shift-invert Lanczos;
///  - "cms N": Craig–Bampton with N fixed-interface modes at the interfaces below,
///    orthonormalised (reduction.h): mesh + assembly + reduction + reduced eigen-solve;
///  - "beam lumped|consistent, <webs> webs": the beam model generated from the same geometry
///    (beam_geometry.h), dense eigen-solve (beam_modal.h): generation + assembly + solve;
///  - "tmm, <webs> webs": the transfer-matrix method on the same beam model (tmm_solver.h);
///    it is the lumped beam model, so it carries the lumped route's pairing.
/// Webs: rigid (the seed's dummy parts) and/or elastic (web arms, beam_geometry.h).
///
/// Support cases.
///  - free-free: nothing held; six rigid-body modes dropped everywhere. CMS interfaces: the
///    main journals (crankshaft) or end_a/end_b (tube), RBE3 (no stiffening), so the CB body
///    converges to the plain 3-D model.
///  - installed (parts with main journals): every journal centre held radially (u_y = u_z = 0),
///    journal 1 also axially (the thrust bearing); the spin about the axis stays free (one
///    rigid mode). 3-D: the RBE3 averages of the journal surfaces held (constrained pencil,
///    eigen_solver.h); CMS: the same RBE3 interfaces, their reduced coordinates held; beam:
///    the journal nodes held. Three models of one support, none stiffening the journals.
///
/// Pairing with the reference's elastic modes:
///  - beam routes by shape: sampled at stations (station_sampling.h), MAC pairing with
///    degenerate groups (mode_pairing.h); a reference mode no beam mode matches (MAC < 0.5)
///    is unpaired. Reference modes whose cross-sections deform (ratio ≥ shell_threshold: shell,
///    ovalling) are "not beam-like", listed separately and never paired with a beam mode
///    (their rigid fit is ~0, so a MAC would mean nothing): no beam can represent them.
///  - CMS by order: a Craig–Bampton model is a Rayleigh–Ritz approximation of the same 3-D
///    model, so by the min–max principle its k-th frequency bounds the k-th from above; the
///    order is the right pairing and every error is ≥ 0.
/// Errors are relative, (f_route − f_ref)/f_ref.

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "libemb/beam/beam_geometry.h"
#include "libemb/common/progress.h"
#include "libemb/fe/material.h"
#include "libemb/mesh/gmsh_reader.h"

namespace emb {

enum class SupportCase { kFreeFree, kInstalled };
/// "free-free" or "installed".
const char* Name(SupportCase support);

/// Modes below this are rigid-body modes [Hz] (the parts' first elastic modes are hundreds of
/// Hz; the rigid ones are ~1e-3 Hz in round-off).
inline constexpr double kRigidModeHz = 1.0;

struct ComparisonOptions {
  std::string geometry;       ///< .geo of the part: its 3-D mesh and (by default) its beams
  std::string beam_geometry;  ///< the beam model's .geo; empty = geometry
  MeshingOptions meshing;     ///< reference mesh (its parameters also shape the beam model)
  IsotropicMaterial material;
  SupportCase support{SupportCase::kFreeFree};
  int num_modes{10};                   ///< elastic reference modes compared, ≥ 1
  std::vector<int> cms_modes{5, 10, 20, 40};  ///< fixed-interface mode counts, each ≥ 0
  std::vector<WebModel> webs{WebModel::kRigid, WebModel::kElastic};  ///< parts with webs
  double web_width{0.0};               ///< elastic web arm width [m]; 0 = from the .geo
  double beam_element_length{0.02};    ///< [m]
  bool shear_deformable{true};         ///< Timoshenko beams
  /// TMM band [Hz]; max 0 = up to 1.25 × the highest reference frequency. A band given
  /// explicitly that holds no natural frequency is an InputError (it says so).
  double tmm_min_hz{0.0}, tmm_max_hz{0.0};
  int tmm_scan_intervals{400};
  int axis_stations{16};               ///< stations along a one-segment part (tube)
  double shell_threshold{0.5};         ///< section-deformation ratio of a non-beam-like mode
  /// Largest relative difference in mass or length between the beam and the 3-D model before
  /// they count as different parts.
  double same_part_tolerance{0.05};
};

struct ReferenceMode {
  double frequency_hz{0.0};
  double section_deformation{0.0};  ///< station_sampling.h
  bool beam_like{true};             ///< section_deformation < shell_threshold
};

struct RouteResult {
  std::string name;     ///< e.g. "cms 20", "beam lumped, rigid webs", "tmm, elastic webs"
  std::string method;   ///< "fe", "cms", "beam", "tmm"
  std::string variant;  ///< e.g. "20 modes", "lumped, rigid webs"
  int num_unknowns{0};
  double seconds{0.0};
  std::string pairing;  ///< "reference", "order (Ritz bounds)", "MAC", "as the lumped beam"
  /// Per reference mode: the paired frequency [Hz] and MAC (NaN where none).
  Eigen::VectorXd frequencies_hz, mac;
  std::string note;
  /// (f − f_ref)/f_ref of reference mode j (NaN if unpaired).
  double Error(const std::vector<ReferenceMode>& reference, int j) const;
};

struct PartComparison {
  std::string part;           ///< the geometry's stem, e.g. "crankshaft_i4"
  std::string geometry, beam_geometry;
  SupportCase support{SupportCase::kFreeFree};
  std::string support_description;
  std::string mesh_summary;
  int fe_dofs{0};
  double mesh_seconds{0.0}, assembly_seconds{0.0};
  double fe_mass_kg{0.0}, geometry_mass_kg{0.0};
  std::vector<std::string> stations;
  std::vector<std::string> interfaces;  ///< of the CMS routes (and the installed supports)
  std::vector<ReferenceMode> reference;
  std::vector<RouteResult> routes;      ///< routes[0] is the reference ("fe")
  double tmm_vs_lumped{0.0};            ///< max |f_TMM − f_lumped|/f_lumped over TMM roots
  std::vector<std::string> notes;
};

/// Runs every route (file comment). Cost: dominated by the 3-D eigen-solve and the CMS
/// reductions (each factorises the part once), seconds to a minute at benchmark meshes.
/// @throws InputError for bad options, beam segments of zero length or non-positive
///   sections (from the generator), a beam and a 3-D model of different parts (mass or
///   length differ by more than same_part_tolerance, or a station holds no 3-D node), an
///   installed case of a part without main journals, an explicit TMM band without roots.
/// @throws NumericalError if the reference eigen-solve fails.
PartComparison RunPartComparison(const ComparisonOptions& options, const ProgressFn& progress = {});

}  // namespace emb
