#pragma once
/// @file
/// What one film evaluation gives a force element and an engineer: loads on the journal, the
/// friction torques, flows, minimum film, peak pressure, power loss (notation.h for the
/// formulas), and the partial derivatives of the loads at fixed film unknowns (film_solver.h
/// turns them into total derivatives with one adjoint solve per load).
///
/// Quadrature: node sums with the control-volume areas A = R dphi dz (A/2 on the edge rows,
/// where the pressure is ambient but Couette shear and asperity contact act). The Couette
/// shear of an edge node uses the fill fraction of its interior neighbour and mu_0. For the
/// models other than kMassConserving the Couette shear acts on the whole surface (theta = 1,
/// as in Petroff's and Ocvirk's formulas); kHalfSommerfeld drops sub-ambient pressures.
///
/// Minimum film: without a film offset the rigid film's exact minimum,
///   h_min = c - max(|e(-L/2)|, |e(L/2)|)   (|e(z)| is convex in z; T1),
/// at phi = the angle of e(z) at that edge (at the mid-plane when aligned); with an offset the
/// smallest node value refined by a parabola through it and its two circumferential
/// neighbours. Peak pressure: the largest node value (a node value: it converges with the
/// grid, see the benchmark).

#include <Eigen/Dense>

#include "libemb/tribology/film_assembly.h"

namespace emb::tribology {

/// Rows of load Jacobians.
struct LoadLayout {
  static constexpr int kNumLoads = 6;
  static constexpr int kFx = 0, kFy = 1, kMx = 2, kMy = 3, kJournalTorque = 4, kShellTorque = 5;
};

struct BearingLoads {
  Eigen::Vector2d force{0.0, 0.0};   ///< F on the journal, shell axes (film + asperities) [N]
  Eigen::Vector2d moment{0.0, 0.0};  ///< M on the journal about its mid-plane centre [N m]
  double journal_torque{0.0};        ///< T_j about z_S on the journal [N m]
  double shell_torque{0.0};          ///< T_s about z_S on the shell (about its axis) [N m]
  Eigen::Vector2d contact_force{0.0, 0.0};  ///< the asperity part of `force` [N]
  double max_contact_pressure{0.0};         ///< [Pa]
  double side_flow{0.0};     ///< out through both edges [m^3/s]
  double supply_flow{0.0};   ///< out of the oil holes and grooves [m^3/s]
  double storage_rate{0.0};  ///< d/dt of the film content of the non-supply nodes [m^3/s]
  double content{0.0};       ///< sum A theta h over the non-supply nodes [m^3]
  double min_film{0.0};        ///< h_min [m]
  double min_film_angle{0.0};  ///< phi of h_min [rad]
  double min_film_axial{0.0};  ///< z of h_min [m]
  double max_pressure{0.0};        ///< peak film pressure [Pa]
  double max_pressure_angle{0.0};  ///< [rad]
  double max_pressure_axial{0.0};  ///< [m]
  /// Mechanical power the film takes from journal and shell:
  /// -(F . e_dot + M_y gamma_dot_x - M_x gamma_dot_y + T_j omega_j + T_s omega_s) [W].
  double power_loss{0.0};
  double cavitated_fraction{0.0};  ///< share of free nodes with p = 0 and theta < 1 (or slack)
  /// (F_x, F_y, M_x, M_y, T_j, T_s) in LoadLayout order.
  Eigen::Matrix<double, 6, 1> Stacked() const {
    Eigen::Matrix<double, 6, 1> y;
    y << force, moment, journal_torque, shell_torque;
    return y;
  }
};

/// Partial derivatives of the stacked loads at fixed unknowns: d/du (6 x n, with the Newton
/// variable's weights dPsi/du, dtheta/du), d/dx (6 x 5) and d/dv (6 x 6) (KinematicsLayout;
/// at fixed unknowns the loads do not depend on the journal angle).
struct LoadPartials {
  Eigen::Matrix<double, 6, Eigen::Dynamic> d_unknowns;
  Eigen::Matrix<double, 6, KinematicsLayout::kNumPositions> d_position;
  Eigen::Matrix<double, 6, 6> d_velocity;
};

/// Loads and outputs of the film; `partials` if not null.
void CalcBearingLoads(const FilmFields& film, const FilmUnknowns& x, const FilmBalance& balance,
                      BearingLoads* loads, LoadPartials* partials);

}  // namespace emb::tribology
