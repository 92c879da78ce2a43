#pragma once
/// @file
/// Oil supply features of a bearing shell: circular oil holes and circumferential grooves
/// (full or partial; a narrow angular extent over most of the length is an axial groove).
/// Each holds its nodes at its supply pressure (gauge, >= 0) and fully flooded (theta = 1).
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

/// Which unknowns are held by a supply feature, and at what pressure.
struct SupplyMap {
  std::vector<int> feature;       ///< per unknown: feature index (holes first), -1 if free
  std::vector<double> pressure;   ///< per feature: supply pressure [Pa]
  std::vector<int> nodes;         ///< the held unknowns, ascending
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
