// The quasi-static elastic start (quasi_static_start.h) on a bar clamped to a hub spinning
// at a constant Omega about an axis through its root: centrifugal loading stretches it
// steadily, the tip moving out by u = rho Omega^2 L^3 / (3 E) (uniform bar, root on the
// axis). Started undeformed, the bar rings axially about that stretch with an amplitude of
// u itself; the quasi-static start begins on it, so it stays there.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/flexible/flexible_body.h"
#include "tests/support/spinning_bar.h"

namespace emb {
namespace {

constexpr double kOmega = 200.0;  // hub speed [rad/s]

// Radial tip position relative to the hub over 2 ms (about four axial periods).
std::vector<double> TipStretch(mbs::ElasticStart start, std::string* note) {
  const mbs::System sys =
      testing::SpinningBar(testing::SpinningBarSpec(), kOmega, testing::StiffenedOptions());
  mbs::AnalysisSettings settings;
  settings.t_end = 2e-3;
  settings.output_step = 1e-5;
  settings.ida.rtol = 1e-8;
  settings.ida.atol = 1e-12;
  settings.elastic_start = start;
  const mbs::PreparedRun run = mbs::PrepareRun(sys, settings);
  *note = run.start_note;
  std::vector<double> x;
  const mbs::RunResult r = mbs::RunAnalysis(
      run, settings, [&](const mbs::Sample& s) { x.push_back(s.sensors(0, 0)); }, {});
  EXPECT_TRUE(r.ok()) << r.message;
  return x;
}

TEST(QuasiStaticStart, SpinningBarStartsOnItsCentrifugalStretch) {
  const testing::BarSpec bar;
  const double rho = bar.Material().density;  // [kg/m^3]
  const double u = rho * kOmega * kOmega * std::pow(bar.length, 3) / (3.0 * bar.youngs_modulus);
  std::string note;
  const std::vector<double> given = TipStretch(mbs::ElasticStart::kAsGiven, &note);
  EXPECT_TRUE(note.empty());
  const std::vector<double> smooth = TipStretch(mbs::ElasticStart::kQuasiStatic, &note);
  EXPECT_NE(note.find("quasi-static elastic start"), std::string::npos) << note;
  ASSERT_EQ(given.size(), smooth.size());
  const double L0 = given.front();  // the undeformed tip position
  auto swing = [&](const std::vector<double>& x) {
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    return *hi - *lo;
  };
  // The smooth start is stretched by u from the first sample on: the linear displacement
  // field of the tip constraint mode is the Galerkin solution whose tip value is exact for
  // this linear load; 2 % covers the Hex20 bar's shear/Poisson effects.
  EXPECT_NEAR((smooth.front() - L0) / u, 1.0, 0.02);
  // Undeformed start: rings between 0 and about 2u. Smooth start: stays within 1 % of u
  // (the remaining slow drift of geometric stiffening and the integration error).
  EXPECT_GT(swing(given), 1.5 * u);
  EXPECT_LT(swing(smooth), 0.01 * u);
}

}  // namespace
}  // namespace emb
