// IDA's event location through the DaeProblem root functions, on a ball thrown up under
// gravity with an algebraic copy of its height (an index-1 DAE):
//   h' = v,  v' = -g,  0 = z - h,   root g(t) = z (the ground).
// The first impact is at t* = (v0 + sqrt(v0^2 + 2 g h0)) / g. Checks: the root is located to
// a few unit round-offs of t whatever the output times, its direction is reported, the
// solver goes on after a restart (bounces with restitution e land where the closed form
// says), a problem without roots never stops early, and generalized-alpha refuses events.

#include <gtest/gtest.h>

#include <cmath>

#include "libemb/common/error.h"
#include "libemb/integrators/generalized_alpha.h"
#include "libemb/integrators/ida_solver.h"

namespace emb {
namespace {

constexpr double kGravity = 9.81;     // [m/s^2]
constexpr double kHeight0 = 1.0;      // [m]
constexpr double kVelocity0 = 2.0;    // [m/s], upwards
constexpr double kRestitution = 0.8;  // [-]
// IDA locates a root to ttol = 100 uround (|t| + |h|) and returns y interpolated from the
// step's polynomial (error ~ the local error, well inside rtol).
constexpr double kRootTimeTolerance = 1e-12;  // [s]
constexpr double kRtol = 1e-10;

class BallDae final : public DaeProblem {
 public:
  explicit BallDae(bool with_root) : with_root_(with_root) {}

 protected:
  int DoSize() const override { return 3; }
  bool DoCalcResidual(double, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override {
    r[0] = yp[0] - y[1];
    r[1] = yp[1] + kGravity;
    r[2] = y[2] - y[0];
    return true;
  }
  Eigen::VectorXd DoDifferentialMask() const override { return Eigen::Vector3d(1, 1, 0); }
  int DoNumRoots() const override { return with_root_ ? 1 : 0; }
  bool DoCalcRoots(double, const Eigen::Ref<const Eigen::VectorXd>& y,
                   const Eigen::Ref<const Eigen::VectorXd>&,
                   Eigen::Ref<Eigen::VectorXd> g) const override {
    g[0] = y[2];
    return true;
  }

 private:
  bool with_root_;
};

double ImpactTime(double h0, double v0) {
  return (v0 + std::sqrt(v0 * v0 + 2.0 * kGravity * h0)) / kGravity;
}

IdaOptions Tight() {
  IdaOptions o;
  o.rtol = kRtol;
  o.atol = 1e-12;
  return o;
}

TEST(IdaEvents, RootLocatedIndependentlyOfOutputTimes) {
  const double t_star = ImpactTime(kHeight0, kVelocity0);
  for (const double dt : {0.01, 0.1, 1.0}) {
    BallDae dae(true);
    IdaSolver ida(dae, 0.0, Eigen::Vector3d(kHeight0, kVelocity0, kHeight0),
                  Eigen::Vector3d(kVelocity0, -kGravity, 0.0), Tight());
    IntegratorReport rep;
    for (double t = dt;; t += dt) {
      rep = ida.AdvanceTo(t);
      ASSERT_TRUE(rep.ok()) << rep.message;
      if (rep.root_found) break;
      ASSERT_LT(t, 10.0) << "no impact found";
    }
    EXPECT_NEAR(ida.t(), t_star, kRootTimeTolerance) << "output step " << dt;
    ASSERT_EQ(rep.root_directions.size(), 1u);
    EXPECT_EQ(rep.root_directions[0], -1);  // the height falls through zero
    EXPECT_NEAR(ida.y()[1], -std::sqrt(kVelocity0 * kVelocity0 + 2 * kGravity * kHeight0), 1e-8);
    EXPECT_GT(ida.stats().root_evals, 0);
  }
}

TEST(IdaEvents, BouncesAfterRestartsFollowTheClosedForm) {
  BallDae dae(true);
  IdaSolver ida(dae, 0.0, Eigen::Vector3d(kHeight0, kVelocity0, kHeight0),
                Eigen::Vector3d(kVelocity0, -kGravity, 0.0), Tight());
  // Closed form: after the first impact each flight lasts 2 v_k / g with v_{k+1} = e v_k.
  double t_expected = ImpactTime(kHeight0, kVelocity0);
  double v = std::sqrt(kVelocity0 * kVelocity0 + 2 * kGravity * kHeight0);
  int impacts = 0;
  while (impacts < 4) {
    const IntegratorReport rep = ida.AdvanceTo(10.0);
    ASSERT_TRUE(rep.ok()) << rep.message;
    ASSERT_TRUE(rep.root_found);
    ++impacts;
    EXPECT_NEAR(ida.t(), t_expected, 1e3 * kRootTimeTolerance) << "impact " << impacts;
    // Rebound: v -> -e v at the ground, restart cleanly from consistent values.
    const double up = -kRestitution * ida.y()[1];
    ida.Reinitialize(ida.t(), Eigen::Vector3d(0.0, up, 0.0), Eigen::Vector3d(up, -kGravity, 0));
    v *= kRestitution;
    t_expected += 2.0 * v / kGravity;
  }
}

TEST(IdaEvents, NoRootFunctionsNeverStop) {
  BallDae dae(false);
  IdaSolver ida(dae, 0.0, Eigen::Vector3d(kHeight0, kVelocity0, kHeight0),
                Eigen::Vector3d(kVelocity0, -kGravity, 0.0), Tight());
  const IntegratorReport rep = ida.AdvanceTo(2.0);
  EXPECT_TRUE(rep.ok());
  EXPECT_FALSE(rep.root_found);
  EXPECT_DOUBLE_EQ(ida.t(), 2.0);
}

TEST(IdaEvents, GeneralizedAlphaRefusesEvents) {
  BallDae dae(true);
  GeneralizedAlphaOptions o;
  try {
    GeneralizedAlphaSolver ga(dae, 0.0, Eigen::Vector3d(kHeight0, kVelocity0, kHeight0),
                              Eigen::Vector3d(kVelocity0, -kGravity, 0.0), o);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("event"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb
