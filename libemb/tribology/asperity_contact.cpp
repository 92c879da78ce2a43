#include "libemb/tribology/asperity_contact.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "libemb/common/error.h"

namespace emb::tribology {
namespace {
constexpr double kFitScale = 4.4086e-5;  // Arcoumanis et al. (1997)
constexpr double kFitExponent = 6.804;
constexpr double kFitEnd = 4.0;

// The table of (G2): lambda in [kTableStart, kTableEnd] by kTableStep. Above kTableEnd
// F_{5/2} < 1e-10 (0.6 at lambda = 0).
constexpr double kTableStart = -10.0, kTableEnd = 6.0, kTableStep = 0.01;
constexpr int kTablePoints = 1601;
// Simpson panels of the w-integral (w^2 = s - lambda, w in [0, kTailW]): the integrands
// w^6 and w^4 times a Gaussian in w^2 + lambda are smooth; 400 panels resolve them to
// round-off, and exp(-(kTailW^2 + lambda)^2 / 2) underflows for lambda >= -10.
constexpr int kPanels = 400;

struct Table {
  std::vector<double> f, df;  // F_{5/2}, dF_{5/2}/dlambda = -(5/2) F_{3/2}
};

const Table& GreenwoodTrippTable() {
  static const Table table = [] {
    Table t;
    t.f.resize(kTablePoints);
    t.df.resize(kTablePoints);
    for (int i = 0; i < kTablePoints; ++i) {
      const double lambda = kTableStart + i * kTableStep;
      // s = lambda + w^2 from max(lambda, -9) on: below -9 the Gaussian is < 1e-17.
      const double w0 = lambda < -9.0 ? std::sqrt(-9.0 - lambda) : 0.0;
      const double w1 = std::sqrt(std::max(9.0 - lambda, 1.0)) + 1.0;
      const double h = (w1 - w0) / kPanels;
      double f52 = 0.0, f32 = 0.0;
      for (int k = 0; k <= kPanels; ++k) {
        const double w = w0 + k * h, s = lambda + w * w;
        const double g = std::exp(-0.5 * s * s);
        const double weight = (k == 0 || k == kPanels) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        // (s - lambda)^{5/2} ds = w^5 2w dw; (s - lambda)^{3/2} ds = w^3 2w dw.
        f52 += weight * 2.0 * std::pow(w, 6) * g;
        f32 += weight * 2.0 * std::pow(w, 4) * g;
      }
      const double norm = h / 3.0 / std::sqrt(2.0 * std::numbers::pi);
      t.f[i] = f52 * norm;
      t.df[i] = -2.5 * f32 * norm;
    }
    return t;
  }();
  return table;
}

}  // namespace

AsperityContact::AsperityContact(const AsperityContactParameters& p, const std::string& who)
    : p_(p) {
  auto positive = [&](double v, const char* key) {
    EMB_THROW_IF(!(std::isfinite(v) && v > 0.0),
                 who << ": expected a positive asperity_contact." << key << ", got " << v);
  };
  positive(p.roughness, "roughness");
  positive(p.roughness_parameter, "roughness_parameter");
  positive(p.slope_parameter, "slope_parameter");
  positive(p.composite_modulus, "composite_modulus");
  EMB_THROW_IF(!(std::isfinite(p.boundary_friction) && p.boundary_friction >= 0.0),
               who << ": expected asperity_contact.boundary_friction >= 0, got "
                   << p.boundary_friction);
  const double K = 16.0 * std::numbers::sqrt2 / 15.0 * std::numbers::pi *
                   p.roughness_parameter * p.roughness_parameter * std::sqrt(p.slope_parameter);
  scale_ = K * p.composite_modulus;
}

double AsperityContact::F52(double lambda, double* dF) {
  const Table& t = GreenwoodTrippTable();
  if (lambda >= kTableEnd) {
    if (dF) *dF = 0.0;
    return 0.0;
  }
  if (lambda <= kTableStart) {  // linear beyond the table (a journal 10 sigma too deep)
    if (dF) *dF = t.df[0];
    return t.f[0] + t.df[0] * (lambda - kTableStart);
  }
  const double x = (lambda - kTableStart) / kTableStep;
  const int i = std::min(static_cast<int>(x), kTablePoints - 2);
  const double s = x - i, s2 = s * s, s3 = s2 * s;
  const double m0 = t.df[i] * kTableStep, m1 = t.df[i + 1] * kTableStep;
  const double f = (2 * s3 - 3 * s2 + 1) * t.f[i] + (s3 - 2 * s2 + s) * m0 +
                   (-2 * s3 + 3 * s2) * t.f[i + 1] + (s3 - s2) * m1;
  if (dF)
    *dF = ((6 * s2 - 6 * s) * t.f[i] + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * t.f[i + 1] +
           (3 * s2 - 2 * s) * m1) /
          kTableStep;
  return f;
}

double AsperityContact::F52Fit(double lambda, double* dF) {
  if (lambda >= kFitEnd) {
    if (dF) *dF = 0.0;
    return 0.0;
  }
  const double d = kFitEnd - lambda;
  const double f = kFitScale * std::pow(d, kFitExponent);
  if (dF) *dF = -kFitExponent * f / d;
  return f;
}

double AsperityContact::Pressure(double h, double* dp_dh) const {
  double dF = 0.0;
  const double lambda = h / p_.roughness;
  const double f = p_.function == GreenwoodTrippFunction::kArcoumanisFit
                       ? F52Fit(lambda, dp_dh ? &dF : nullptr)
                       : F52(lambda, dp_dh ? &dF : nullptr);
  if (dp_dh) *dp_dh = scale_ * dF / p_.roughness;
  return scale_ * f;
}

}  // namespace emb::tribology
