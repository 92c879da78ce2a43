#include "libemb/tribology/lubricant.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"

namespace emb::tribology {
namespace {

constexpr double kKelvinAt40C = 313.15;
constexpr double kKelvinAt100C = 373.15;
constexpr double kRoelandsPressure = 1.96e8;     // p_r [Pa]
constexpr double kRoelandsViscosityLog = 9.67;   // -ln(6.31e-5 Pa s)
constexpr double kWaltherOffset = 0.7;           // ASTM D341 [mm^2/s]
constexpr double kWaltherMinimum = 2.0;          // D341's two-term form holds above [mm^2/s]
constexpr int kRoelandsIntervals = 4096;
// The Roelands table ends where mu_0/mu < 1e-17: beyond it Psi gains less than a double's
// resolution of Psi_max.
constexpr double kRoelandsTailRatio = 1e-17;

// 4-point Gauss-Legendre on [-1, 1].
constexpr std::array<double, 4> kGaussX = {-0.8611363115940526, -0.3399810435848563,
                                           0.3399810435848563, 0.8611363115940526};
constexpr std::array<double, 4> kGaussW = {0.3478548451374538, 0.6521451548625461,
                                           0.6521451548625461, 0.3478548451374538};

}  // namespace

Lubricant::Lubricant(const LubricantParameters& p, const std::string& who) {
  auto positive = [&](double v, const char* key, const char* unit) {
    EMB_THROW_IF(!(std::isfinite(v) && v > 0.0),
                 who << ": expected a positive lubricant." << key << ", got " << v << " " << unit);
  };
  switch (p.temperature_law) {
    case ViscosityTemperatureLaw::kConstant:
      positive(p.viscosity, "viscosity", "Pa s");
      mu0_ = p.viscosity;
      break;
    case ViscosityTemperatureLaw::kVogel:
      positive(p.vogel_a, "vogel_a", "Pa s");
      positive(p.vogel_b, "vogel_b", "K");
      EMB_THROW_IF(!std::isfinite(p.vogel_c),
                   who << ": expected a finite lubricant.vogel_c, got " << p.vogel_c);
      positive(p.temperature, "temperature", "K");
      EMB_THROW_IF(p.temperature <= p.vogel_c,
                   who << ": expected lubricant.temperature above Vogel's c = " << p.vogel_c
                       << " K, got " << p.temperature << " K");
      mu0_ = p.vogel_a * std::exp(p.vogel_b / (p.temperature - p.vogel_c));
      break;
    case ViscosityTemperatureLaw::kWalther: {
      positive(p.nu_40, "nu_40", "m^2/s");
      positive(p.nu_100, "nu_100", "m^2/s");
      positive(p.density, "density", "kg/m^3");
      positive(p.temperature, "temperature", "K");
      EMB_THROW_IF(p.nu_40 <= p.nu_100, who << ": expected lubricant.nu_40 > nu_100, got "
                                           << p.nu_40 << " and " << p.nu_100 << " m^2/s");
      auto loglog = [](double nu_si) {
        return std::log10(std::log10(nu_si * 1e6 + kWaltherOffset));
      };
      const double b = (loglog(p.nu_40) - loglog(p.nu_100)) /
                       (std::log10(kKelvinAt100C) - std::log10(kKelvinAt40C));
      const double a = loglog(p.nu_40) + b * std::log10(kKelvinAt40C);
      const double nu_cst =
          std::pow(10.0, std::pow(10.0, a - b * std::log10(p.temperature))) - kWaltherOffset;
      EMB_THROW_IF(!(nu_cst >= kWaltherMinimum),
                   who << ": the Walther (ASTM D341) law holds for nu >= " << kWaltherMinimum
                       << " mm^2/s: expected a lubricant.temperature where it does, got nu = " << nu_cst << " mm^2/s at lubricant.temperature = "
                       << p.temperature << " K");
      mu0_ = p.density * nu_cst * 1e-6;
      break;
    }
  }
  law_ = p.pressure_law;
  psi_max_ = std::numeric_limits<double>::infinity();
  if (law_ == PressureViscosityLaw::kNone) return;
  positive(p.pressure_viscosity_coefficient, "pressure_viscosity_coefficient", "1/Pa");
  alpha_ = p.pressure_viscosity_coefficient;
  if (law_ == PressureViscosityLaw::kBarus) {
    psi_max_ = 1.0 / alpha_;
    return;
  }
  roelands_k_ = std::log(mu0_) + kRoelandsViscosityLog;
  EMB_THROW_IF(!(roelands_k_ > 0.0),
               who << ": the Roelands law expected mu_0 > exp(-9.67) Pa s = 6.3e-5 Pa s, got "
                   << mu0_ << " Pa s");
  roelands_z_ = alpha_ * kRoelandsPressure / roelands_k_;
  // Tail: mu_0/mu = kRoelandsTailRatio.
  const double p_end =
      kRoelandsPressure *
      (std::pow(1.0 - std::log(kRoelandsTailRatio) / roelands_k_, 1.0 / roelands_z_) - 1.0);
  const double dp = p_end / kRoelandsIntervals;
  table_p_.resize(kRoelandsIntervals + 1);
  table_psi_.resize(kRoelandsIntervals + 1);
  table_slope_.resize(kRoelandsIntervals + 1);
  double psi = 0.0;
  for (int k = 0; k <= kRoelandsIntervals; ++k) {
    const double pk = k * dp;
    if (k > 0) {
      const double mid = pk - 0.5 * dp;
      for (int g = 0; g < 4; ++g)
        psi += 0.5 * dp * kGaussW[g] * std::exp(-RoelandsExponent(mid + 0.5 * dp * kGaussX[g]));
    }
    table_p_[k] = pk;
    table_psi_[k] = psi;
    table_slope_[k] = std::exp(RoelandsExponent(pk));
  }
  psi_max_ = psi;
}

double Lubricant::RoelandsExponent(double p) const {
  return roelands_k_ * (std::pow(1.0 + p / kRoelandsPressure, roelands_z_) - 1.0);
}

double Lubricant::Viscosity(double p, double* dmu_dp) const {
  if (dmu_dp) *dmu_dp = 0.0;
  if (p <= 0.0) return mu0_;
  switch (law_) {
    case PressureViscosityLaw::kNone:
      return mu0_;
    case PressureViscosityLaw::kBarus: {
      const double mu = mu0_ * std::exp(alpha_ * p);
      if (dmu_dp) *dmu_dp = alpha_ * mu;
      return mu;
    }
    case PressureViscosityLaw::kRoelands: {
      const double mu = mu0_ * std::exp(RoelandsExponent(p));
      if (dmu_dp)
        *dmu_dp = mu * roelands_k_ * roelands_z_ / kRoelandsPressure *
                  std::pow(1.0 + p / kRoelandsPressure, roelands_z_ - 1.0);
      return mu;
    }
  }
  return mu0_;
}

double Lubricant::ReducedPressure(double p) const {
  if (p <= 0.0 || law_ == PressureViscosityLaw::kNone) return p;
  if (law_ == PressureViscosityLaw::kBarus) return -std::expm1(-alpha_ * p) / alpha_;
  // Roelands: the table interval holding p, then Gauss on the remainder.
  const double dp = table_p_[1];
  const int k = std::min(static_cast<int>(p / dp), kRoelandsIntervals - 1);
  if (p >= table_p_.back()) return psi_max_;
  const double a = table_p_[k], half = 0.5 * (p - a), mid = a + half;
  double psi = table_psi_[k];
  for (int g = 0; g < 4; ++g) psi += half * kGaussW[g] * std::exp(-RoelandsExponent(mid + half * kGaussX[g]));
  return psi;
}

double Lubricant::Pressure(double psi, double* dp_dpsi) const {
  if (psi <= 0.0 || law_ == PressureViscosityLaw::kNone) {
    if (dp_dpsi) *dp_dpsi = 1.0;
    return psi;
  }
  if (law_ == PressureViscosityLaw::kBarus) {
    const double s = 1.0 - alpha_ * psi;  // = mu_0 / mu(p)
    if (dp_dpsi) *dp_dpsi = 1.0 / s;
    return -std::log(s) / alpha_;
  }
  // Roelands: binary search in Psi_k, cubic Hermite in Psi with the exact end slopes.
  const auto it = std::upper_bound(table_psi_.begin(), table_psi_.end(), psi);
  const int k = std::clamp(static_cast<int>(it - table_psi_.begin()) - 1, 0,
                           kRoelandsIntervals - 1);
  const double h = table_psi_[k + 1] - table_psi_[k];
  const double s = (psi - table_psi_[k]) / h;
  const double p0 = table_p_[k], p1 = table_p_[k + 1];
  const double m0 = table_slope_[k] * h, m1 = table_slope_[k + 1] * h;
  const double s2 = s * s, s3 = s2 * s;
  double p = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 +
             (s3 - s2) * m1;
  // The Hermite step is good to ~(dPsi)^4 p''''/384 (~5e-7 relative at low pressure); one
  // Newton step on Psi(p) = psi with the exact Psi squares that.
  const double slope = std::exp(RoelandsExponent(p));  // dp/dPsi
  p -= (ReducedPressure(p) - psi) * slope;
  if (dp_dpsi) *dp_dpsi = std::exp(RoelandsExponent(p));
  return p;
}

}  // namespace emb::tribology
