#pragma once
/// @file
/// Rigid-body mass properties of a meshed solid of uniform density, integrated over the cells
/// with the mass quadrature (exact for straight-sided cells, isoparametric otherwise):
///   m = ρ ∫ dV,  c = (ρ/m) ∫ x dV,  I_c = ρ ∫ (|r|² 1 − r rᵀ) dV with r = x − c.

#include "libemb/common/mass_properties.h"
#include "libemb/mesh/mesh.h"

namespace emb {

/// @throws InputError for ρ ≤ 0 or a mesh without solid cells.
MassProperties CalcMassProperties(const Mesh& mesh, double density);

}  // namespace emb
