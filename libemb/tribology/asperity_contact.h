#pragma once
/// @file
/// Greenwood-Tripp asperity contact pressure for thin films (mixed lubrication): what keeps a
/// run going when the journal nears the shell.
///
/// Greenwood & Tripp (1970-71), Proc. IMechE 185, for two rough surfaces with composite
/// roughness sigma, asperity density eta_s and asperity tip radius beta:
///   p_c(h) = K E' F_{5/2}(h / sigma),   K = (16 sqrt(2) / 15) pi (eta_s beta sigma)^2
///                                                                 sqrt(sigma / beta),    (G1)
///   F_{5/2}(lambda) = (1/sqrt(2 pi)) int_lambda^inf (s - lambda)^{5/2} exp(-s^2/2) ds,  (G2)
/// with F_{5/2} either
///   kTabulatedIntegral  (G2) itself, tabulated once (lambda in [-10, 6] by 0.01, values and
///                       the exact slope dF_{5/2}/dlambda = -(5/2) F_{3/2} by Simpson on
///                       s - lambda = w^2), cubic Hermite in between (relative error < 1e-7
///                       where F > 1e-12: asperity_contact_test), 0 above 6, linear below -10;
///   kArcoumanisFit      the closed form of Arcoumanis et al. (1997), widely used in engine
///                       tribology:  F_{5/2} = 4.4086e-5 (4 - lambda)^6.804 for lambda < 4.   (G3)
///                       Measured against (G2): -11 % at lambda = 0, within 10 % on [0.3, 2.1],
///                       but -35 % at 2.5, -74 % at 3 and -98 % at 3.5 (the onset of contact is
///                       underestimated by orders of magnitude). Kept for comparison with
///                       codes that use it; the default is the integral.
/// Both are finite for lambda <= 0, so a journal driven through its nominal clearance meets a
/// steep but finite pressure. Boundary friction: shear f_b p_c opposing the sliding speed.

#include <string>

namespace emb::tribology {

enum class GreenwoodTrippFunction { kTabulatedIntegral, kArcoumanisFit };

struct AsperityContactParameters {
  double roughness{0.0};           ///< sigma, composite RMS roughness [m]
  double roughness_parameter{0.04};  ///< eta_s beta sigma [-] (typically 0.03-0.07)
  double slope_parameter{1e-3};    ///< sigma / beta [-] (typically 1e-4 to 1e-2)
  double composite_modulus{0.0};   ///< E' = 2 / ((1-nu1^2)/E1 + (1-nu2^2)/E2) [Pa]
  double boundary_friction{0.1};   ///< f_b, shear / contact pressure [-]
  GreenwoodTrippFunction function{GreenwoodTrippFunction::kTabulatedIntegral};
};

class AsperityContact {
 public:
  /// @throws InputError naming `who` and the key for non-finite or non-positive values
  ///   (f_b may be 0).
  AsperityContact(const AsperityContactParameters& p, const std::string& who);
  /// p_c(h) [Pa] and dp_c/dh [Pa/m] (G1, G3); any finite h.
  double Pressure(double h, double* dp_dh = nullptr) const;
  /// F_{5/2}(lambda) (G2, tabulated) or the fit (G3), and the derivative.
  static double F52(double lambda, double* dF = nullptr);
  static double F52Fit(double lambda, double* dF = nullptr);
  double roughness() const { return p_.roughness; }
  double boundary_friction() const { return p_.boundary_friction; }

 private:
  AsperityContactParameters p_;
  double scale_{0.0};  // K E' [Pa]
};

}  // namespace emb::tribology
