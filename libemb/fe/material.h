#pragma once
/// @file
/// Linear isotropic elastic material (SI units).

#include <string>

namespace emb {

struct IsotropicMaterial {
  double youngs_modulus{210e9};  ///< E [Pa]
  double poisson_ratio{0.3};     ///< ν [-], in (−1, 0.5)
  double density{7850.0};        ///< ρ [kg/m³]
  std::string name{"steel"};

  /// Lamé's first parameter λ = Eν / ((1+ν)(1−2ν)) [Pa].
  double lambda() const {
    return youngs_modulus * poisson_ratio / ((1.0 + poisson_ratio) * (1.0 - 2.0 * poisson_ratio));
  }
  /// Shear modulus μ = G = E / (2(1+ν)) [Pa].
  double mu() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }

  /// @throws InputError unless E > 0, ρ > 0 and −1 < ν < 0.5 (all finite).
  void Validate() const;
};

}  // namespace emb
