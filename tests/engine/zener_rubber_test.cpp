// Frequency-dependent damper rubber (libemb/engine/zener_rubber.h): the supplier fit puts the
// Zener's loss peak at the given frequency with the given height and |k*|; the junction-ring
// realisation of the Maxwell arms, linearised as a multibody model (ring on a grounded hub),
// has the ring-side dynamic stiffness of the closed-form k*(w) within the stated bound up to
// the band, and exactly the junction transfer function of the header comment.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "libemb/common/error.h"
#include "libemb/engine/torsional_damper.h"
#include "libemb/engine/zener_rubber.h"
#include "libemb/mbs/dae/linearization.h"
#include "libemb/mbs/constraints/assembly.h"

namespace emb {
namespace {

using Complex = std::complex<double>;
using Eigen::Matrix3d;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

// Double round-off on a handful of operations (|k*| and eta from the fitted k_inf, k_1, tau).
constexpr double kRoundOff = 1e-13;

TEST(ZenerRubber, SupplierFitReproducesDynamicStiffnessAndLossFactorAtItsPeak) {
  for (const double eta : {0.05, 0.1, 0.18, 0.25, 0.6, 1.0}) {
    constexpr double kDynamic = 2.5e4, kHz = 380.0;  // [N m/rad], [Hz]
    const engine::ZenerRubber z = engine::FitZenerAtLossPeak(kDynamic, eta, kHz);
    ASSERT_EQ(z.arms.size(), 1u);
    const double w = 2 * kPi * kHz;
    EXPECT_NEAR(std::abs(engine::CalcComplexStiffness(z, w)) / kDynamic, 1.0, kRoundOff) << eta;
    EXPECT_NEAR(engine::CalcLossFactor(z, w) / eta, 1.0, kRoundOff) << eta;
    // The peak: eta_max = k1 / (2 sqrt(k_inf (k_inf + k1))) at w tau = sqrt(k_inf/(k_inf+k1)).
    const double kinf = z.static_stiffness, k1 = z.arms[0].stiffness;
    EXPECT_NEAR(k1 / (2 * std::sqrt(kinf * (kinf + k1))) / eta, 1.0, kRoundOff);
    EXPECT_NEAR(w * z.arms[0].relaxation_time / std::sqrt(kinf / (kinf + k1)), 1.0, kRoundOff);
    for (const double s : {0.98, 1.02})
      EXPECT_LT(engine::CalcLossFactor(z, s * w), eta) << "not a peak at " << s << " f";
  }
  // Dynamic-to-static ratio |k*(f)| / k_inf for the typical loss factors 0.1 .. 0.25.
  EXPECT_NEAR(2.5e4 / engine::FitZenerAtLossPeak(2.5e4, 0.25, 380.0).static_stiffness, 1.281,
              1e-3);
  EXPECT_THROW(engine::FitZenerAtLossPeak(2.5e4, 0.0, 380.0), InputError);
  EXPECT_THROW(engine::FitZenerAtLossPeak(2.5e4, 1.5, 380.0), InputError);
  EXPECT_THROW(engine::FitZenerAtLossPeak(-1.0, 0.2, 380.0), InputError);
  EXPECT_THROW(engine::FitZenerAtLossPeak(2.5e4, 0.2, 0.0), InputError);
}

TEST(ZenerRubber, JunctionInertiaKeepsTheArmErrorBelowTheBoundUpToTheBand) {
  constexpr double kBandHz = 2000.0, kDelta = 1e-3;
  // Relaxation times below, inside and above the band (w_max tau = 0.06 .. 60).
  for (const double tau : {5e-6, 1e-4, 5e-3}) {
    const engine::MaxwellArm arm{3e4, tau};
    const double eps = engine::CalcJunctionInertia(arm, kBandHz, kDelta);
    double worst = 0.0;
    for (double f = 1.0; f <= kBandHz * (1 + 1e-12); f *= 1.05) {
      const double w = 2 * kPi * f;
      const double e = engine::CalcJunctionArmError(arm, eps, w).Max();
      EXPECT_LE(e, engine::CalcJunctionArmErrorBound(arm, eps, w) * (1 + kRoundOff)) << f;
      worst = std::max(worst, e);
    }
    const double w = 2 * kPi * kBandHz;
    EXPECT_LE(engine::CalcJunctionArmErrorBound(arm, eps, w), kDelta * (1 + kRoundOff));
    EXPECT_LE(worst, kDelta);
    // The bound is attained to within a factor of a few, not vacuous.
    EXPECT_GT(worst, 0.2 * kDelta) << "tau " << tau;
  }
  EXPECT_THROW(engine::CalcJunctionInertia({3e4, 0.0}, kBandHz, kDelta), InputError);
  EXPECT_THROW(engine::CalcJunctionInertia({3e4, 1e-4}, kBandHz, 1.0), InputError);
}

// The ring on a grounded hub: its dynamic stiffness T / theta + J_r w^2 from the linearised
// multibody model, (K - w^2 M + i w G) x = F on null(C).
class GroundedRing {
 public:
  explicit GroundedRing(const engine::TorsionalDamperSpec& spec) {
    sys_.AddMarker("hub", "ground", Vector3d::Zero(), Matrix3d::Identity());
    parts_ = engine::AddTorsionalDamper(&sys_, spec);
    sys_.Finalize();
    rz_ = sys_.layout().angular_velocity(parts_.ring_body) + 2;
    mbs::ConstraintWorkspace ws(sys_);
    lin_ = mbs::CalcLinearizedModel(sys_, sys_.InitialPositions(), Eigen::VectorXd(), 0.0,
                                    Eigen::VectorXd::Zero(sys_.num_equations()), &ws);
    ring_inertia_ = spec.ring_inertia;
  }
  Complex DynamicStiffness(double w) const {
    Eigen::VectorXcd F = Eigen::VectorXcd::Zero(lin_.M.rows());
    F[rz_] = 1.0;
    const Eigen::MatrixXcd Z = lin_.Z.cast<Complex>();
    const Eigen::MatrixXcd A = Z.adjoint() *
                               (lin_.K.cast<Complex>() - w * w * lin_.M.cast<Complex>() +
                                Complex(0.0, w) * lin_.G.cast<Complex>()) *
                               Z;
    const Eigen::VectorXcd x = Z * A.partialPivLu().solve(Z.adjoint() * F);
    return 1.0 / x[rz_] + ring_inertia_ * w * w;
  }
  const engine::TorsionalDamperParts& parts() const { return parts_; }

 private:
  mbs::System sys_;
  engine::TorsionalDamperParts parts_;
  int rz_{-1};
  double ring_inertia_{0.0};
  mbs::LinearizedModel lin_;
};

TEST(ZenerRubber, JunctionRingRealisationHasTheClosedFormDynamicStiffness) {
  engine::TorsionalDamperSpec s;
  s.name = "tvd";
  s.hub_marker = "hub";
  s.ring_mass = 1.5;
  s.ring_inertia = 4e-3;
  s.stiffness = 1.8e4;  // k_inf [N m/rad]
  // Two arms: a Zener-like one relaxing near 400 Hz and a slow one (a broader loss peak).
  s.arms = {{6e3, 3e-4}, {3e3, 3e-3}};
  s.band_hz = 2500.0;
  s.junction_error = 1e-3;
  const GroundedRing ring(s);
  ASSERT_EQ(ring.parts().junction_inertia.size(), 2u);
  engine::ZenerRubber ideal{s.stiffness, s.arms};
  double worst = 0.0;
  for (double f = 5.0; f <= s.band_hz * (1 + 1e-12); f *= 1.1) {
    const double w = 2 * kPi * f;
    const Complex model = ring.DynamicStiffness(w);
    const Complex k = engine::CalcComplexStiffness(ideal, w);
    // The exact realisation: k* + sum_j (D_gg,j - D0_j) (zener_rubber.h).
    Complex exact = k;
    for (std::size_t j = 0; j < s.arms.size(); ++j) {
      const engine::MaxwellArm& a = s.arms[j];
      const double c = a.stiffness * a.relaxation_time;
      const Complex D0 = Complex(0.0, w * c) * a.stiffness / Complex(a.stiffness, w * c);
      exact += D0 * engine::CalcJunctionArmError(a, ring.parts().junction_inertia[j], w).ring;
    }
    // Dense LU of the linearised model's few coordinates; 1/x loses the ring's inertia term
    // J_r w^2, up to 1e2 |k*| at the band top: round-off times that.
    constexpr double kModelRoundOff = 1e-9;
    EXPECT_NEAR(std::abs(model / exact - 1.0), 0.0, kModelRoundOff) << f << " Hz";
    const double e = std::abs(model / k - 1.0);
    EXPECT_LE(e, s.junction_error) << f << " Hz";
    worst = std::max(worst, e);
  }
  std::cout << "largest |k*_model / k*_Zener - 1| up to " << s.band_hz << " Hz: " << worst
            << " (bound " << s.junction_error << "); junction inertias "
            << ring.parts().junction_inertia[0] << ", " << ring.parts().junction_inertia[1]
            << " kg m^2\n";
}

}  // namespace
}  // namespace emb
