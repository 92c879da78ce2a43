#include "libemb/fe/material.h"

#include <cmath>

#include "libemb/common/error.h"

namespace emb {

void IsotropicMaterial::Validate() const {
  EMB_THROW_IF(!(std::isfinite(youngs_modulus) && youngs_modulus > 0.0),
               "material '" << name << "': Young's modulus E: expected > 0 Pa, got "
                            << youngs_modulus);
  EMB_THROW_IF(!(std::isfinite(density) && density > 0.0),
               "material '" << name << "': density rho: expected > 0 kg/m^3, got " << density);
  EMB_THROW_IF(!(std::isfinite(poisson_ratio) && poisson_ratio > -1.0 && poisson_ratio < 0.5),
               "material '" << name << "': Poisson's ratio nu: expected -1 < nu < 0.5, got "
                            << poisson_ratio);
}

}  // namespace emb
