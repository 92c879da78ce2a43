#pragma once
/// @file
/// Cross-section properties of a prismatic beam, in the beam frame B (x_B along the axis,
/// y_B and z_B the principal axes of the section). SI units.
///
///   A  = ∫ dA                       [m²]
///   Iy = ∫ z² dA  (about y_B)       [m⁴]   bending in the x_B–z_B plane
///   Iz = ∫ y² dA  (about z_B)       [m⁴]   bending in the x_B–y_B plane (the seed's I_{q³})
///   J  torsion constant             [m⁴]   (= Iy + Iz for solid and hollow circles)
///   Ip = Iy + Iz polar moment       [m⁴]   (rotary inertia of torsion: ρ Ip per length)
///   κ  shear coefficient            [-]    (Cowper; shear area κA in both planes)

#include <string>

namespace emb {

/// The section of a prismatic beam. Build it with one of the Make*Section functions.
struct BeamSection {
  std::string shape{"general"};  ///< "solid circle", "hollow circle" or "general"
  double area{0.0};              ///< A [m²]
  double second_moment_y{0.0};   ///< Iy = ∫ z² dA [m⁴]
  double second_moment_z{0.0};   ///< Iz = ∫ y² dA [m⁴]
  double torsion_constant{0.0};  ///< J [m⁴]
  double shear_coefficient{0.0}; ///< κ [-], 0 < κ ≤ 1 for real sections
  double outer_diameter{0.0};    ///< circles only [m], 0 otherwise
  double inner_diameter{0.0};    ///< hollow circles only [m], 0 otherwise

  /// Ip = Iy + Iz [m⁴].
  double polar_moment() const { return second_moment_y + second_moment_z; }
};

/// Solid circle of diameter d: A = πd²/4, Iy = Iz = πd⁴/64, J = πd⁴/32,
/// κ = 6(1+ν)/(7+6ν) (Cowper).
/// @throws InputError unless d > 0 and −1 < ν < 0.5.
BeamSection MakeSolidCircleSection(double diameter, double poisson_ratio);

/// Tube of outer diameter D and inner diameter d (0 ≤ d < D): A = π(D²−d²)/4,
/// Iy = Iz = π(D⁴−d⁴)/64, J = π(D⁴−d⁴)/32, Cowper's κ with m = d/D:
///   κ = 6(1+ν)(1+m²)² / ((7+6ν)(1+m²)² + (20+12ν)m²).
/// @throws InputError unless D > 0, 0 ≤ d < D and −1 < ν < 0.5.
BeamSection MakeHollowCircleSection(double outer_diameter, double inner_diameter,
                                    double poisson_ratio);

/// Any section given by its properties (principal axes y_B, z_B).
/// @throws InputError unless all are finite and > 0 (κ also ≤ 1).
BeamSection MakeGeneralSection(double area, double second_moment_y, double second_moment_z,
                               double torsion_constant, double shear_coefficient);

/// @throws InputError "<what>: section <property>: expected > 0 <unit>, got <value>" for a
///         non-positive or non-finite property, or κ > 1.
void ValidateSection(const BeamSection& section, const std::string& what);

}  // namespace emb
