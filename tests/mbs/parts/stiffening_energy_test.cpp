// Geometric stiffening must not create energy (issue 12). A 10 m cantilever (Hex20 bar, root
// RBE2 and tip RBE3 interfaces, every elastic coordinate kept, its torsion too, no damping)
// driven at a constant 6 rad/s about a vertical axis through its root, sagging under
// gravity and released from a bend. With the centrifugal stiffening as a force on the
// elastic coordinates alone, -K_G(omega) eta, IDA failed after 2.2 s: the frame's transverse
// angular velocity follows the root's elastic rotation (eta'), so that force had a part
// proportional to eta' that did work, and the bent, spinning beam's torsion grew. The
// stiffening now derives from a kinetic energy -1/2 eta^T K_G(omega) eta (elastic_model.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "libemb/cms/geometric_stiffening.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "tests/support/spinning_bar.h"

namespace emb {
namespace {

// 10 m x 0.3 m x 0.2 m steel, Hex20 20 x 1 x 1: flap (z) 1.7 Hz, lag 2.5 Hz; 12 elastic
// coordinates (6 fixed-interface modes and the tip interface's 6 constraint modes: its
// twist is the torsion).
testing::BarSpec Bar() {
  testing::BarSpec bar;
  bar.length = 10.0;
  bar.width = 0.3;
  bar.height = 0.2;
  bar.nx = 20;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.stiffening_supports = {"x0"};
  bar.modes = 6;
  return bar;
}

constexpr double kSpin = 6.0;  // [rad/s]

// The bar clamped to a hub driven at kSpin about the world z axis through the centre of the
// bar's root face, gravity along -z, released from a bend of its first two coordinates.
mbs::System DrivenBar() {
  const testing::BarSpec bar = Bar();
  Eigen::VectorXd eta0 = Eigen::VectorXd::Zero(6 * 2 + bar.modes - 6);
  eta0.head(2).setConstant(1.0);  // [kg^0.5 m]: ~15 mm at the tip (4710 kg)
  return testing::SpinningBar(bar, kSpin, testing::StiffenedOptions(), eta0, {0, 0, -9.81});
}

// Power identity of the inertia terms of one flexible body at a state V = [v, w, eta']:
// with the elastic force removed, V^T f + 1/2 V^T M' V = 0 (M' = dM/dt along eta'), i.e. the
// velocity-dependent forces and the stiffening do no work against the kinetic energy
// 1/2 V^T M V; the energy of an undamped free body is then conserved. Gravity is off.
TEST(StiffeningEnergy, InertiaAndStiffeningTermsDoNoWork) {
  mbs::ElasticModel model = mbs::MakeElasticModel(testing::FlexibleBar(Bar()), "bar");
  model.geometric_stiffening = true;
  for (auto& k : model.kg_translational) k.setZero();  // a_B = 0 below anyway
  model.D.setZero();
  const int ne = model.num_modes();
  Eigen::VectorXd eta(ne), eta_dot(ne);
  for (int i = 0; i < ne; ++i) {
    eta[i] = 0.3 * std::sin(1.0 + i);
    eta_dot[i] = 2.0 * std::cos(0.5 + 2.0 * i);
  }
  const Eigen::Vector3d v(0.4, -1.0, 0.7), w(0.5, -0.8, kSpin), zero = Eigen::Vector3d::Zero();
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  auto terms = [&](const Eigen::VectorXd& e) {
    return mbs::CalcFlexibleTerms(model, zero, R, v, w, e, eta_dot, zero, zero, false);
  };
  const mbs::FlexibleTerms t = terms(eta);
  Eigen::VectorXd V(6 + ne);
  V << v, w, eta_dot;
  Eigen::VectorXd f = t.force;
  f.tail(ne) += model.K * eta;  // the strain energy's own force
  // dM/dt by central differences along eta' (M is quadratic in eta: exact up to round-off).
  constexpr double kStep = 1e-4;
  const Eigen::MatrixXd Mdot =
      (terms(eta + kStep * eta_dot).mass - terms(eta - kStep * eta_dot).mass) / (2 * kStep);
  // The power of the stiffening force on eta alone: eta'^T K_G(w) eta.
  const Eigen::Matrix<double, 6, 1> c = CentrifugalProducts(w);
  double stiffening_power = 0.0;
  for (int p = 0; p < 6; ++p) stiffening_power += c[p] * eta_dot.dot(model.kg_centrifugal[p] * eta);
  const double power = V.dot(f) + 0.5 * V.dot(Mdot * V);
  // Relative to the stiffening's own power: measured 1.7e-9 (the differences' round-off,
  // eps |M| / kStep; the terms themselves are ~600 W here); as a force on eta alone the
  // residual was the whole eta'^T K_G eta.
  constexpr double kRoundOff = 1e-7;
  EXPECT_LT(std::abs(power), kRoundOff * std::abs(stiffening_power)) << power;
  ASSERT_GT(std::abs(stiffening_power), 0.0);
}

// Tens of seconds of the driven, bent, spinning cantilever: it runs to the end, and its
// Jacobi integral H = E - W (total energy less the drive's work W = integral of V^T (M V' -
// f) dt, the constraint forces' power: only the drive's is not zero) stays at its start.
TEST(StiffeningEnergy, DrivenBentSpinningCantileverStaysBounded) {
  const mbs::System sys = DrivenBar();
  mbs::AnalysisSettings settings;
  settings.t_end = 30.0;
  settings.output_step = 0.005;
  settings.ida.rtol = 1.0e-7;
  const mbs::PreparedRun run = mbs::PrepareRun(sys, settings);
  std::vector<double> t, E, P;
  const mbs::RunResult r = mbs::RunAnalysis(run, settings, [&](const mbs::Sample& s) {
    const auto bodies = mbs::CalcBodyKinematics(run.system, s.q, s.v);
    const Eigen::VectorXd f = mbs::CalcGeneralizedForces(run.system, bodies, s.t, nullptr, &s.vdot);
    t.push_back(s.t);
    E.push_back(s.energies.total());
    P.push_back(s.v.dot(mbs::CalcMassMatrix(run.system, bodies) * s.vdot - f));
  });
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_NEAR(r.t_reached, settings.t_end, 1e-9);
  // The vibration's energy scale: the swing of E about its mean (the drive exchanges the
  // lag vibration's energy with the spin).
  const auto [lo, hi] = std::minmax_element(E.begin(), E.end());
  const double swing = *hi - *lo;
  double W = 0.0, worst = 0.0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    W += 0.5 * (P[k] + P[k - 1]) * (t[k] - t[k - 1]);
    const double drift = std::abs(E[k] - W - E[0]);
    worst = std::max(worst, drift);
  }
  RecordProperty("energy_swing_J", ::testing::PrintToString(swing));
  RecordProperty("jacobi_drift_J", ::testing::PrintToString(worst));
  RecordProperty("steps", ::testing::PrintToString(r.ida_stats.steps));
  // Measured: the energy swings by 3.6e5 J (the drive takes and returns up to 1.7e5 J) and
  // H stays within 4.8e3 J (1.4 %) of its start over the 30 s, without a trend: the
  // trapezoidal work of a power oscillating at the stiff modes, and the translational
  // stiffening -a_B K_a eta, which is a force on eta alone (a_B is ~180 m/s^2 here). The
  // undriven torsion would show as growth through this bound (before: failure at 2.2 s).
  constexpr double kJacobiTolerance = 0.03;
  EXPECT_LT(worst, kJacobiTolerance * swing);
}

}  // namespace
}  // namespace emb

