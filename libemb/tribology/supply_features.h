#pragma once
/// @file
/// Oil supply features of a bearing shell: circular oil holes and circumferential grooves
/// (full or partial; a narrow angular extent over most of the length is an axial groove).
/// Each holds its nodes at its supply pressure (gauge, >= 0) and fully flooded (theta = 1).
/// Oil holes in the journal, which turn with it, feed the film through a conductance
/// instead (JournalOilHole below).
///
/// A node (phi_i, z_j) belongs to
///   a hole   if R^2 wrap(phi_i - phi_h)^2 + (z_j - z_h)^2 <= (d/2)^2
///            (wrap to (-pi, pi]; the hole measured on the unwrapped surface),
///   a groove if |z_j - z_g| <= w/2 and wrap_{[0, 2pi)}(phi_i - phi_start) <= extent.
/// Only interior nodes count (the edge rows are ambient). A feature that holds no interior
/// node is refused: the grid is too coarse for it.

#include <string>
#include <vector>

#include "libemb/tribology/bearing_grid.h"

namespace emb::tribology {

struct OilHole {
  double angle{0.0};            ///< phi_h, centre angle in the shell frame [rad]
  double axial_position{0.0};   ///< z_h, centre from the mid-plane [m]
  double diameter{0.0};         ///< d [m]
  double supply_pressure{0.0};  ///< gauge [Pa], >= 0
};

struct Groove {
  double axial_position{0.0};   ///< z_g, groove centre line from the mid-plane [m]
  double width{0.0};            ///< w, axial width [m]
  double start_angle{0.0};      ///< phi_start [rad]
  double angular_extent{0.0};   ///< (0, 2 pi]; 2 pi is a full circumferential groove [rad]
  double supply_pressure{0.0};  ///< gauge [Pa], >= 0
};

/// An oil hole in the journal's surface (a crankpin's drilling fed from the main bearings):
/// it turns with the journal, centred at phi_h = angle + psi in the shell frame, psi the
/// journal's rotation relative to the shell (JournalKinematics::journal_angle). It feeds the
/// film through a conductance instead of holding nodes at its pressure (held nodes that
/// change as the hole passes would switch the DAE's equations):
///   q_k = G_k (Psi_s - Psi_k)                  flow into unknown k [m^3/s]
///   G_k = kappa g_ref w_k / sum_j w_j,          g_ref = pi c^3 / (6 mu_0),
///   w_k = 1 for d_k <= d/2,  (1 - t^2)^2 with t = (d_k - d/2) / b for d/2 < d_k < d/2 + b,
///   else 0,   b = 1.2 max(R dphi, dz),
/// d_k the distance on the unwrapped surface from the hole's centre to node k, the sum over
/// all interior unknowns (some w_k > 0 at every angle: the nearest node is within 1.12
/// max(R dphi, dz), at a bearing edge). The weights are C^1 in psi and their normalised
/// sum is one, so the hole's total conductance kappa g_ref does not change as it passes the
/// nodes. g_ref is the conductance of a film of the clearance's thickness between radii a
/// and e a around a source; kappa (ReynoldsBearingParameters::journal_feed_ratio) makes the
/// drilling that much more conductive than the film, so the hole's nodes sit near Psi_s.
/// The taper b makes the hole act a little larger than it is: against a shell hole held at
/// the same pressure the load differs by a few per cent on a 48 x 8 grid, halving with each
/// refinement (JournalFeed tests). A hole over a node that a shell feature holds feeds
/// nothing there (the held row wins).
struct JournalOilHole {
  double angle{0.0};            ///< centre angle in the journal's frame, from x_I [rad]
  double axial_position{0.0};   ///< z_h, centre from the mid-plane [m]
  double diameter{0.0};         ///< d [m]
  double supply_pressure{0.0};  ///< gauge [Pa], >= 0
};

/// The journal holes' feed at one journal angle: entries (unknown k, G_k, dG_k/dpsi, Psi_s);
/// an unknown under two holes has two entries. Capacity is kept between evaluations.
struct JournalFeed {
  std::vector<int> unknown;
  std::vector<double> conductance;        ///< G_k [m^3/(Pa s)]
  std::vector<double> conductance_slope;  ///< dG_k/dpsi [m^3/(Pa s rad)]
  std::vector<double> supply_psi;         ///< Psi_s of the feeding hole [Pa]
  int size() const { return static_cast<int>(unknown.size()); }
  void clear();
};

/// Checks the journal holes against the bearing.
/// @throws InputError naming the bearing and the key ("journal_oil_holes[0].diameter ...")
///   for a non-finite value, a diameter <= 0, a negative supply pressure, or a hole
///   reaching outside the bearing (|z| + d/2 > L/2).
void CheckJournalOilHoles(const BearingGrid& grid, const std::vector<JournalOilHole>& holes,
                          const std::string& who);

/// The feed of `holes` at journal angle `psi` [rad]: `hole_conductance` = kappa g_ref
/// [m^3/(Pa s)], `supply_psi` the holes' reduced supply pressures [Pa].
void CalcJournalFeed(const BearingGrid& grid, const std::vector<JournalOilHole>& holes,
                     double hole_conductance, const std::vector<double>& supply_psi, double psi,
                     JournalFeed* feed);

/// Which unknowns are held by a supply feature, and at what pressure.
struct SupplyMap {
  std::vector<int> feature;      ///< per unknown: feature index (holes first), -1 if free
  std::vector<double> pressure;  ///< per feature: supply pressure [Pa]
  std::vector<int> nodes;        ///< the held unknowns, ascending
  bool empty() const { return nodes.empty(); }
};

/// Checks the features against the bearing and marks their nodes.
/// @param who names the bearing in messages ("bearing 'main_1'").
/// @throws InputError naming the bearing and the feature key ("oil_holes[0].diameter ...")
///   for: a non-finite value, diameter or width <= 0, an extent outside (0, 2 pi], a negative
///   supply pressure, a feature reaching outside the bearing (|z| + d/2 > L/2), a feature
///   holding no interior node, overlapping features at different pressures.
SupplyMap MarkSupplyNodes(const BearingGrid& grid, const std::vector<OilHole>& holes,
                          const std::vector<Groove>& grooves, const std::string& who);

}  // namespace emb::tribology
