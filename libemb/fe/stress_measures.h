#pragma once
/// @file
/// Scalar measures of a stress state given in Voigt order (σ_xx, σ_yy, σ_zz, σ_xy, σ_yz,
/// σ_zx) [Pa] (fe/nodal_stress.h).

#include <Eigen/Core>

namespace emb {

using Voigt6 = Eigen::Matrix<double, 6, 1>;

/// von Mises stress √(½[(σx−σy)² + (σy−σz)² + (σz−σx)²] + 3(τxy² + τyz² + τzx²)) [Pa].
double VonMises(const Voigt6& s);

/// Principal stresses σ1 ≥ σ2 ≥ σ3 [Pa] (eigenvalues of the symmetric 3 × 3 tensor).
Eigen::Vector3d PrincipalStresses(const Voigt6& s);

/// von Mises with the sign of the principal stress of the largest magnitude (σ1 if
/// |σ1| ≥ |σ3|, else σ3): a signed equivalent stress for fatigue of multiaxial states that
/// keeps tension and compression apart [Pa].
double SignedVonMises(const Voigt6& s);

}  // namespace emb
