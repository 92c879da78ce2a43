#pragma once
/// @file
/// The lubricant of a Reynolds bearing: viscosity at an effective oil temperature (no thermal
/// model) and, optionally, its rise with pressure.
///
/// Viscosity-temperature laws (T the effective oil temperature [K]):
///   constant   mu_0 given [Pa s]
///   Vogel      mu_0 = a exp(b / (T - c)),  a [Pa s], b [K], c [K]
///   Walther    ASTM D341: log10 log10(nu + 0.7) = A - B log10 T (nu in mm^2/s, T in K),
///              A and B through nu(40 C) and nu(100 C); mu_0 = rho nu. D341's form holds
///              for nu >= 2 mm^2/s.
/// Pressure-viscosity laws (p gauge >= 0; sub-ambient pressures, which only the full-
/// Sommerfeld model produces, keep mu_0):
///   Barus      mu(p) = mu_0 exp(alpha p)
///   Roelands   mu(p) = mu_0 exp((ln(mu_0 / 1 Pa s) + 9.67) ((1 + p / p_r)^Z - 1)),
///              p_r = 1.96e8 Pa, Z = alpha p_r / (ln(mu_0 / 1 Pa s) + 9.67) (the same
///              low-pressure slope alpha as Barus).
/// The reduced pressure Psi(p) = int_0^p mu_0 / mu(s) ds (notation.h, T4) is
///   Barus      Psi = (1 - exp(-alpha p)) / alpha,   p = -ln(1 - alpha Psi) / alpha,
///   Roelands   tabulated at construction (4096 intervals to Psi's limit, 4-point Gauss per
///              interval) and inverted by cubic Hermite interpolation with the exact slope
///              dp/dPsi = mu(p)/mu_0 and one Newton step on Psi(p) (relative error < 1e-10
///              against direct quadrature: lubricant_test). Both laws bound Psi: Psi_max = 1/alpha for Barus; a
///              pressure that would need Psi >= Psi_max is a numerical outcome of the solve.

#include <string>
#include <vector>

namespace emb::tribology {

enum class ViscosityTemperatureLaw { kConstant, kVogel, kWalther };
enum class PressureViscosityLaw { kNone, kBarus, kRoelands };

struct LubricantParameters {
  ViscosityTemperatureLaw temperature_law{ViscosityTemperatureLaw::kConstant};
  double viscosity{0.0};    ///< kConstant: mu_0 [Pa s]
  double vogel_a{0.0};      ///< kVogel: a [Pa s]
  double vogel_b{0.0};      ///< kVogel: b [K]
  double vogel_c{0.0};      ///< kVogel: c [K]
  double nu_40{0.0};        ///< kWalther: kinematic viscosity at 40 C [m^2/s]
  double nu_100{0.0};       ///< kWalther: kinematic viscosity at 100 C [m^2/s]
  double density{0.0};      ///< kWalther: density at the effective temperature [kg/m^3]
  double temperature{0.0};  ///< kVogel, kWalther: effective oil temperature [K]
  PressureViscosityLaw pressure_law{PressureViscosityLaw::kNone};
  double pressure_viscosity_coefficient{0.0};  ///< alpha [1/Pa] (Barus, Roelands)
};

class Lubricant {
 public:
  /// @throws InputError naming `who` and the key for non-finite or non-positive values,
  ///   nu_40 <= nu_100, T <= c (Vogel), nu below D341's 2 mm^2/s at T (Walther), or a
  ///   Roelands law with mu_0 <= exp(-9.67) Pa s (its exponent would change sign).
  Lubricant(const LubricantParameters& p, const std::string& who);

  double ambient_viscosity() const { return mu0_; }  ///< mu_0 [Pa s]
  bool piezoviscous() const { return law_ != PressureViscosityLaw::kNone; }
  /// mu(p) [Pa s] and, if requested, dmu/dp [s].
  double Viscosity(double p, double* dmu_dp = nullptr) const;
  /// Psi(p) [Pa].
  double ReducedPressure(double p) const;
  /// p(Psi) [Pa] and, if requested, dp/dPsi = mu(p)/mu_0. @pre Psi < reduced_pressure_limit().
  double Pressure(double psi, double* dp_dpsi = nullptr) const;
  /// sup Psi [Pa] (infinity without a pressure-viscosity law).
  double reduced_pressure_limit() const { return psi_max_; }

 private:
  double RoelandsExponent(double p) const;  // ln(mu(p)/mu_0)

  double mu0_{0.0};
  PressureViscosityLaw law_{PressureViscosityLaw::kNone};
  double alpha_{0.0};
  double roelands_k_{0.0}, roelands_z_{0.0};
  double psi_max_{0.0};
  std::vector<double> table_p_, table_psi_, table_slope_;  // Roelands: p_k, Psi_k, dp/dPsi
};

}  // namespace emb::tribology
