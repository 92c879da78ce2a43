#pragma once
/// @file
/// Rigid-body mass properties of a meshed solid of uniform density, integrated over the cells
/// with the mass quadrature (exact for straight-sided cells, isoparametric otherwise):
///   m = ρ ∫ dV,  c = (ρ/m) ∫ x dV,  I_c = ρ ∫ (|r|² 1 − r rᵀ) dV with r = x − c.

#include <Eigen/Core>

#include "libemb/mesh/mesh.h"

namespace emb {

struct MassProperties {
  double volume{0.0};                                   ///< [m³]
  double mass{0.0};                                     ///< [kg]
  Eigen::Vector3d center_of_mass{Eigen::Vector3d::Zero()};  ///< [m]
  Eigen::Matrix3d inertia_about_com{Eigen::Matrix3d::Zero()};  ///< [kg·m²]
};

/// @throws InputError for ρ ≤ 0 or a mesh without solid cells.
MassProperties CalcMassProperties(const Mesh& mesh, double density);

}  // namespace emb
