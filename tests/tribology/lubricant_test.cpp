// The lubricant: viscosity-temperature laws (Walther reproduces its two data points, Vogel
// its formula), pressure-viscosity laws (Barus' reduced pressure in closed form and its
// inverse; Roelands' tabulated reduced pressure against an independent quadrature; the
// viscosity derivative against differences), and the checks of bad values.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "libemb/common/error.h"
#include "libemb/tribology/lubricant.h"

namespace emb::tribology {
namespace {

// A representative SAE 10W-30 (SAE J300 grade 30: 9.3 <= nu(100 C) < 12.5 mm^2/s; the
// 40 C value and the density are typical of the grade, not one product's data sheet).
constexpr double kNu40 = 70e-6, kNu100 = 10.5e-6, kDensity = 860.0;  // m^2/s, kg/m^3
constexpr double kAlpha = 1.5e-8;  // pressure-viscosity coefficient [1/Pa], mineral oil, hot

// The closed forms are evaluated with the same operations up to ordering: a few round-offs.
constexpr double kClosedFormTolerance = 1e-13;
// Roelands' table (4096 Gauss-4 intervals, Hermite inverse): the header promises 1e-10.
constexpr double kRoelandsTableTolerance = 1e-10;
// Central differences of exp-type laws with a relative step 1e-6: truncation ~1e-12,
// cancellation ~1e-10.
constexpr double kDifferenceTolerance = 1e-7;

LubricantParameters Walther(double temperature_k) {
  LubricantParameters p;
  p.temperature_law = ViscosityTemperatureLaw::kWalther;
  p.nu_40 = kNu40;
  p.nu_100 = kNu100;
  p.density = kDensity;
  p.temperature = temperature_k;
  return p;
}

TEST(Lubricant, WaltherReproducesItsTwoPoints) {
  EXPECT_NEAR(Lubricant(Walther(313.15), "t").ambient_viscosity(), kDensity * kNu40,
              1e-12 * kDensity * kNu40);
  EXPECT_NEAR(Lubricant(Walther(373.15), "t").ambient_viscosity(), kDensity * kNu100,
              1e-12 * kDensity * kNu100);
  // Monotone in between and beyond (hotter is thinner).
  const double mu80 = Lubricant(Walther(353.15), "t").ambient_viscosity();
  const double mu120 = Lubricant(Walther(393.15), "t").ambient_viscosity();
  EXPECT_GT(mu80, kDensity * kNu100);
  EXPECT_LT(mu80, kDensity * kNu40);
  EXPECT_LT(mu120, kDensity * kNu100);
}

TEST(Lubricant, VogelIsItsFormula) {
  LubricantParameters p;
  p.temperature_law = ViscosityTemperatureLaw::kVogel;
  p.vogel_a = 7e-5;
  p.vogel_b = 900.0;
  p.vogel_c = 180.0;
  p.temperature = 373.15;
  EXPECT_NEAR(Lubricant(p, "t").ambient_viscosity(), 7e-5 * std::exp(900.0 / (373.15 - 180.0)),
              1e-18);
}

TEST(Lubricant, BarusReducedPressureAndItsInverse) {
  LubricantParameters p;
  p.viscosity = 0.0086;
  p.pressure_law = PressureViscosityLaw::kBarus;
  p.pressure_viscosity_coefficient = kAlpha;
  const Lubricant oil(p, "t");
  EXPECT_DOUBLE_EQ(oil.reduced_pressure_limit(), 1.0 / kAlpha);
  for (double pr : {0.0, 1e5, 5e7, 2e8, 1e9}) {
    const double psi = oil.ReducedPressure(pr);
    EXPECT_NEAR(psi, (1.0 - std::exp(-kAlpha * pr)) / kAlpha, kClosedFormTolerance / kAlpha);
    double dp = 0.0;
    EXPECT_NEAR(oil.Pressure(psi, &dp), pr, kClosedFormTolerance * std::max(pr, 1e5) * 1e2);
    EXPECT_NEAR(dp, std::exp(kAlpha * pr), 1e-9 * std::exp(kAlpha * pr));
    EXPECT_NEAR(oil.Viscosity(pr), 0.0086 * std::exp(kAlpha * pr), 1e-15 * std::exp(kAlpha * pr));
  }
  // Sub-ambient pressures keep mu_0 (only the full-Sommerfeld model makes them).
  EXPECT_EQ(oil.ReducedPressure(-1e5), -1e5);
  EXPECT_EQ(oil.Viscosity(-1e5), 0.0086);
}

TEST(Lubricant, RoelandsTableAgainstDirectQuadrature) {
  LubricantParameters p = Walther(373.15);
  p.pressure_law = PressureViscosityLaw::kRoelands;
  p.pressure_viscosity_coefficient = kAlpha;
  const Lubricant oil(p, "t");
  const double mu0 = oil.ambient_viscosity();
  const double k = std::log(mu0) + 9.67, z = kAlpha * 1.96e8 / k;
  auto ratio = [&](double s) { return std::exp(-k * (std::pow(1.0 + s / 1.96e8, z) - 1.0)); };
  for (double pr : {1e6, 3e7, 1e8, 4e8}) {
    // Composite Simpson, 2e5 panels: an independent route (error ~ 1e-16 relative here).
    const int n = 200000;
    const double h = pr / n;
    double psi = ratio(0.0) + ratio(pr);
    for (int i = 1; i < n; ++i) psi += (i % 2 ? 4.0 : 2.0) * ratio(i * h);
    psi *= h / 3.0;
    EXPECT_NEAR(oil.ReducedPressure(pr), psi, kRoelandsTableTolerance * psi) << pr;
    double dp = 0.0;
    EXPECT_NEAR(oil.Pressure(psi, &dp), pr, kRoelandsTableTolerance * pr) << pr;
    EXPECT_NEAR(dp, 1.0 / ratio(pr), kRoelandsTableTolerance / ratio(pr));
    // The same low-pressure slope as Barus.
    EXPECT_NEAR(oil.Viscosity(1.0) / mu0 - 1.0, kAlpha, 1e-6 * kAlpha);
  }
  EXPECT_LT(oil.ReducedPressure(1e8), 1e8);
  EXPECT_GT(oil.reduced_pressure_limit(), oil.ReducedPressure(4e8));
}

TEST(Lubricant, ViscosityDerivativeAgainstDifferences) {
  for (PressureViscosityLaw law : {PressureViscosityLaw::kBarus, PressureViscosityLaw::kRoelands}) {
    LubricantParameters p = Walther(373.15);
    p.pressure_law = law;
    p.pressure_viscosity_coefficient = kAlpha;
    const Lubricant oil(p, "t");
    for (double pr : {1e6, 5e7, 2e8}) {
      double d = 0.0;
      oil.Viscosity(pr, &d);
      const double step = 1e-6 * pr;
      const double fd = (oil.Viscosity(pr + step) - oil.Viscosity(pr - step)) / (2 * step);
      EXPECT_NEAR(d, fd, kDifferenceTolerance * std::abs(fd));
    }
  }
}

void ExpectInputError(const LubricantParameters& p, const std::string& key) {
  try {
    Lubricant(p, "bearing 'main_2'");
    FAIL() << "no error for " << key;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bearing 'main_2'"), std::string::npos) << what;
    EXPECT_NE(what.find(key), std::string::npos) << what;
    EXPECT_NE(what.find("expected"), std::string::npos) << what;
  }
}

TEST(Lubricant, RefusesBadValues) {
  LubricantParameters p;
  for (double mu : {0.0, -1e-3, std::nan("")}) {
    p.viscosity = mu;
    ExpectInputError(p, "viscosity");
  }
  LubricantParameters w = Walther(373.15);
  w.nu_40 = w.nu_100;
  ExpectInputError(w, "nu_40");
  w = Walther(-1.0);
  ExpectInputError(w, "temperature");
  w = Walther(900.0);  // far beyond D341's range: nu < 2 mm^2/s
  ExpectInputError(w, "Walther");
  w = Walther(373.15);
  w.pressure_law = PressureViscosityLaw::kBarus;
  w.pressure_viscosity_coefficient = 0.0;
  ExpectInputError(w, "pressure_viscosity_coefficient");
  LubricantParameters v;
  v.temperature_law = ViscosityTemperatureLaw::kVogel;
  v.vogel_a = 7e-5;
  v.vogel_b = 900.0;
  v.vogel_c = 400.0;
  v.temperature = 373.15;
  ExpectInputError(v, "temperature");
}

}  // namespace
}  // namespace emb::tribology
