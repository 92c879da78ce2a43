// Beam FE natural frequencies against closed forms: a cantilever in bending (Euler–Bernoulli
// with rotary inertia, i.e. Rayleigh, and Timoshenko) with the observed convergence rate for
// the consistent and the lumped mass, a free-free shaft in torsion, and the free-free
// spectrum's structure (six rigid-body modes, degenerate bending pairs kept).

#include "libemb/beam/beam_modal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_model.h"
#include "tests/support/beam_models.h"
#include "tests/support/timoshenko_beam.h"

namespace emb {
namespace {

const IsotropicMaterial kSteel{};

BeamModel MakeShaft(double L, const BeamSection& s, int n, bool shear, bool clamped) {
  return test::MakeUniformShaft(L, s, n, shear, clamped);
}

// Rayleigh beam (Euler–Bernoulli with rotary inertia ρI), clamped at x = 0 and free at L:
//   EI w'''' + ρIω² w'' − ρAω² w = 0,  w = C₁ cosh ax + C₂ sinh ax + C₃ cos bx + C₄ sin bx,
//   a², −b² the roots of EI s⁴ + ρIω² s² − ρAω² = 0; w(0) = w'(0) = 0 gives C₃ = −C₁,
//   C₄ = −(a/b) C₂; the free end w''(L) = 0 and w'''(L) + (ρIω²/EI) w'(L) = 0 leave a 2×2
//   determinant whose sign changes are the natural frequencies (bracketed and bisected).
double RayleighCantileverDeterminant(double EI, double rhoA, double rhoI, double L, double w) {
  const double q = rhoI * w * w / EI;
  const double D = std::sqrt(q * q + 4.0 * rhoA * w * w / EI);
  const double a = std::sqrt(0.5 * (D - q)), b = std::sqrt(0.5 * (D + q));
  // Divided by cosh(aL) to keep the scale bounded.
  const double ch = 1.0, sh = std::tanh(a * L), c = std::cos(b * L) / std::cosh(a * L),
               sn = std::sin(b * L) / std::cosh(a * L);
  const double m1 = a * a * ch + b * b * c, m2 = a * a * sh + a * b * sn;
  const double v1 = a * (a * a + q) * sh - b * (b * b - q) * sn;
  const double v2 = a * (a * a + q) * ch + a * (b * b - q) * c;
  return m1 * v2 - m2 * v1;
}

std::vector<double> RayleighCantileverHz(double EI, double rhoA, double rhoI, double L, int count) {
  std::vector<double> f;
  const double w_ref = std::sqrt(EI / (rhoA * std::pow(L, 4)));
  const double step = w_ref / 200.0;
  double w0 = step, d0 = RayleighCantileverDeterminant(EI, rhoA, rhoI, L, w0);
  while (static_cast<int>(f.size()) < count) {
    const double w1 = w0 + step, d1 = RayleighCantileverDeterminant(EI, rhoA, rhoI, L, w1);
    if (std::signbit(d0) != std::signbit(d1)) {
      double lo = w0, hi = w1, dlo = d0;
      for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        const double dm = RayleighCantileverDeterminant(EI, rhoA, rhoI, L, mid);
        if (std::signbit(dm) == std::signbit(dlo)) {
          lo = mid;
          dlo = dm;
        } else {
          hi = mid;
        }
      }
      f.push_back(test::Hz(0.5 * (lo + hi)));
    }
    w0 = w1;
    d0 = d1;
  }
  return f;
}

struct Case {
  const char* name;
  double L, d;  // [m]
  bool shear;
};

// Error of the first three bending frequencies in the x–y plane for meshes of 2, 4, 8, 16
// elements. Every node is held in u_x, u_z, θ_x, θ_y, so the model has x–y bending only (a
// round shaft's bending pairs are degenerate: the solver may return any mix of the two planes).
void CheckCantilever(const Case& c, BeamMassType mass, double min_rate, double finest_tol) {
  SCOPED_TRACE(std::string(c.name) + ", " + Name(mass) + " mass");
  const BeamSection s = MakeSolidCircleSection(c.d, kSteel.poisson_ratio);
  const double E = kSteel.youngs_modulus, rho = kSteel.density, I = s.second_moment_z;
  std::vector<double> ref;
  if (c.shear) {
    const test::BeamSection ts{E, kSteel.mu(), rho, s.area, I, s.shear_coefficient};
    for (double w : test::TimoshenkoFrequencies(ts, c.L, test::BeamEnd::kClamped,
                                                test::BeamEnd::kFree, 3))
      ref.push_back(test::Hz(w));
  } else {
    ref = RayleighCantileverHz(E * I, rho * s.area, rho * I, c.L, 3);
  }
  std::vector<std::array<double, 3>> err;
  for (int n : {2, 4, 8, 16}) {
    BeamModel model = MakeShaft(c.L, s, n, c.shear, true);
    for (int i = 1; i <= n; ++i)
      model.AddSupport({"plane", i, {true, false, true, true, true, false}});
    const BeamModes m = CalcBeamModes(AssembleBeamSystem(model, mass), {});
    ASSERT_TRUE(m.ok()) << m.message;
    EXPECT_EQ(m.mass_type, mass);
    std::array<double, 3> e;
    for (int k = 0; k < 3; ++k) e[k] = std::abs(m.frequencies_hz[k] - ref[k]) / ref[k];
    err.push_back(e);
  }
  const double rate = std::log2(err[1][0] / err[2][0]);
  std::printf("%s, %s mass: f1 = %.4f Hz, errors f1 %.2e %.2e %.2e %.2e, f3 at n=16 %.2e, "
              "rate %.2f\n",
              c.name, Name(mass), ref[0], err[0][0], err[1][0], err[2][0], err[3][0], err[3][2],
              rate);
  EXPECT_GE(rate, min_rate);
  for (int k = 0; k < 3; ++k) EXPECT_LE(err[3][k], finest_tol) << "mode " << k + 1;
}

// Euler–Bernoulli cubic elements with the consistent mass converge as h⁴ in frequency (seen:
// 3.97), lumped as h² (seen: 1.97). The Timoshenko element's interdependent shape functions
// are exact for statics only: in vibration its rotation field misses the rotary-inertia part
// of the shear, so even the consistent mass converges as h² (seen: 2.12). Rates are measured
// between 4 and 8 elements.
constexpr double kMinRateEulerBernoulliConsistent = 3.5;
constexpr double kMinRateSecondOrder = 1.7;
// At 16 elements the third mode has ~5 elements per half wave (seen: 4e-5 EB consistent,
// 2.5e-3 Timoshenko consistent, 1.0e-2 / 8.9e-3 lumped).
constexpr double kFinestTolEulerBernoulliConsistent = 2e-4;
constexpr double kFinestTolTimoshenkoConsistent = 5e-3;
constexpr double kFinestTolLumped = 2e-2;

TEST(BeamModal, SlenderCantileverEulerBernoulliConverges) {
  const Case c{"Euler-Bernoulli L/d = 25", 1.0, 0.04, false};
  CheckCantilever(c, BeamMassType::kConsistent, kMinRateEulerBernoulliConsistent,
                  kFinestTolEulerBernoulliConsistent);
  CheckCantilever(c, BeamMassType::kLumped, kMinRateSecondOrder, kFinestTolLumped);
}

TEST(BeamModal, StubbyCantileverTimoshenkoConverges) {
  const Case c{"Timoshenko L/d = 5", 0.5, 0.1, true};
  CheckCantilever(c, BeamMassType::kConsistent, kMinRateSecondOrder,
                  kFinestTolTimoshenkoConsistent);
  CheckCantilever(c, BeamMassType::kLumped, kMinRateSecondOrder, kFinestTolLumped);
}

TEST(BeamModal, FreeFreeShaftTorsionMatchesClosedForm) {
  // Free-free uniform shaft: f_n = n/(2L) √(G/ρ) (J = Ip for a circle). Linear torsion
  // elements converge as h² (consistent from above, lumped from below).
  const double L = 1.2;
  const BeamSection s = MakeSolidCircleSection(0.06, kSteel.poisson_ratio);
  const double c = std::sqrt(kSteel.mu() / kSteel.density);
  for (BeamMassType mass : {BeamMassType::kConsistent, BeamMassType::kLumped}) {
    const BeamModes m =
        CalcBeamModes(AssembleBeamSystem(MakeShaft(L, s, 40, true, false), mass), {});
    ASSERT_TRUE(m.ok()) << m.message;
    EXPECT_EQ(m.num_rigid_modes, 6);
    int found = 0;
    for (int i = 0; i < m.shapes.cols() && found < 3; ++i) {
      const Eigen::VectorXd& phi = m.shapes.col(i);
      double tx = 0.0;  // torsion modes have θ_x only
      for (int d = kThetaX; d < phi.size(); d += 6) tx += phi[d] * phi[d];
      if (m.frequencies_hz[i] < 1.0 || tx < 0.99 * phi.squaredNorm()) continue;
      ++found;
      const double exact = found * c / (2 * L);
      // h² error with 40 elements: (π n/40)²/12 ≈ 5e-4 n² relative.
      EXPECT_NEAR(m.frequencies_hz[i], exact, 6e-4 * found * found * exact) << Name(mass);
      if (mass == BeamMassType::kConsistent) {
        EXPECT_GT(m.frequencies_hz[i], exact);
      } else {
        EXPECT_LT(m.frequencies_hz[i], exact);
      }
    }
    EXPECT_EQ(found, 3);
  }
}

TEST(BeamModal, FreeFreeKeepsRigidModesAndDegeneratePairs) {
  const BeamSection s = MakeHollowCircleSection(0.09, 0.086, kSteel.poisson_ratio);
  const BeamModes m =
      CalcBeamModes(AssembleBeamSystem(MakeShaft(1.5, s, 30, true, false), BeamMassType::kConsistent),
                    {});
  ASSERT_TRUE(m.ok()) << m.message;
  EXPECT_EQ(m.num_rigid_modes, 6);
  EXPECT_LE(m.max_backward_error, BeamModalOptions{}.residual_tolerance);
  // The first elastic modes are the bending pair: two equal eigenvalues (round-off apart).
  const double f1 = m.frequencies_hz[6], f2 = m.frequencies_hz[7];
  EXPECT_GT(f1, 1.0);
  EXPECT_NEAR(f1, f2, 1e-10 * f1);
  EXPECT_GT(m.frequencies_hz[8], 1.5 * f2);  // the next pair (second bending) is far above
}

}  // namespace
}  // namespace emb
