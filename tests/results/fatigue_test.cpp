// Rainflow counting (results/rainflow.h) against the worked example of ASTM E1049-85
// (section 5.4.4, Fig. 6 / Table 4), periodic counting, and Goodman/Miner damage
// (results/fatigue.h) against closed forms.

#include "libemb/results/fatigue.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "libemb/common/error.h"
#include "libemb/results/rainflow.h"

namespace emb::results {
namespace {

constexpr double kRoundOff = 1e-12;  // relative, a handful of flops

// range -> total count
std::map<double, double> Histogram(const std::vector<RainflowCycle>& cycles) {
  std::map<double, double> h;
  for (const auto& c : cycles) h[c.range] += c.count;
  return h;
}

// ASTM E1049-85, Fig. 6(a): the history A..I = -2, 1, -3, 5, -1, 3, -4, 4, -2 (units);
// Table 4 (rainflow counting): range 3: 0.5, 4: 1.5, 6: 0.5, 8: 1.0, 9: 0.5 cycles.
TEST(Rainflow, AstmE1049Example) {
  const std::vector<double> history{-2, 1, -3, 5, -1, 3, -4, 4, -2};
  const std::map<double, double> expected{{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(Histogram(CountRainflow(history)), expected);
  // Points between reversals change nothing.
  const std::vector<double> dense{-2, 0, 1, -1, -3, 0, 2, 5, 2, -1, 3, 0, -4, 4, 1, -2};
  EXPECT_EQ(Histogram(CountRainflow(dense)), expected);
}

TEST(Rainflow, ReversalsDropRepeatsAndRuns) {
  EXPECT_EQ(Reversals({0, 1, 2, 2, 3, 1, 1, 0, 4}), (std::vector<double>{0, 3, 0, 4}));
}

// A periodic history counted over one period: every range closes, the counts sum to whole
// cycles. Period of a sine with a small ripple: one big cycle of range 2A, one small.
TEST(Rainflow, PeriodicHistoryClosesIntoWholeCycles) {
  // One period: 0, 10, 2, 6, -10, (repeats). Rotated to start at 10 (|max|... -10 ties:
  // the first of the largest magnitude), cycles: (2, 6) range 4 and (10, -10) range 20.
  const std::vector<double> period{0, 10, 2, 6, -10};
  const std::map<double, double> expected{{4, 1.0}, {20, 1.0}};
  EXPECT_EQ(Histogram(CountRainflowPeriodic(period)), expected);
  // The same period started elsewhere gives the same counts.
  EXPECT_EQ(Histogram(CountRainflowPeriodic({6, -10, 0, 10, 2})), expected);
  // Against counting many repetitions: per period the same, up to the residue of the ends.
  std::vector<double> many;
  for (int k = 0; k < 50; ++k) many.insert(many.end(), period.begin(), period.end());
  double big = 0.0;
  for (const auto& c : CountRainflow(many))
    if (c.range == 20) big += c.count;
  EXPECT_NEAR(big / 50.0, 1.0, 1.0 / 50.0);
}

// Basquin: N = ½ (σ_a / σ_f')^(1/b). Goodman: σ_ar = σ_a / (1 − σ_m/σ_u).
TEST(Fatigue, GoodmanMinerClosedForm) {
  SnCurve sn;
  sn.fatigue_strength_coefficient = 1000e6;
  sn.exponent = -0.1;
  sn.ultimate_strength = 800e6;
  sn.Validate("test");
  // σ_a = 100 MPa fully reversed: N = ½ (0.1)^(-10) = 5e9.
  EXPECT_NEAR(sn.CyclesToFailure(100e6), 5e9, kRoundOff * 5e9);
  // Mean 400 MPa halves the allowable: σ_ar = 200 MPa, N = ½ (0.2)^(-10) = 4.8828125e6.
  EXPECT_NEAR(GoodmanAmplitude(100e6, 400e6, sn.ultimate_strength), 200e6, kRoundOff * 200e6);
  EXPECT_EQ(GoodmanAmplitude(100e6, -400e6, sn.ultimate_strength), 100e6);  // no credit
  EXPECT_TRUE(std::isinf(GoodmanAmplitude(100e6, 800e6, sn.ultimate_strength)));
  // Miner: 2 cycles at (range 200, mean 0) + 0.5 at (range 200, mean 400 MPa).
  const std::vector<RainflowCycle> cycles{
      {200e6, 0.0, 1.0}, {200e6, 0.0, 1.0}, {200e6, 400e6, 0.5}};
  const FatigueDamage d = CalcMinerDamage(cycles, sn);
  const double expected = 2.0 / 5e9 + 0.5 / 4.8828125e6;
  EXPECT_NEAR(d.damage, expected, kRoundOff * expected);
  EXPECT_EQ(d.cycles, 2.5);
  EXPECT_EQ(d.max_range, 200e6);
  EXPECT_NEAR(d.max_equivalent, 200e6, kRoundOff * 200e6);
  // Below the endurance limit: no damage.
  sn.endurance_limit = 150e6;
  EXPECT_NEAR(CalcMinerDamage(cycles, sn).damage, 0.5 / 4.8828125e6, kRoundOff * 1e-7);
}

// A tabulated S–N curve: log-log interpolation is exact for points taken from a Basquin law;
// the geometric midpoint of a segment has the geometric mean life; the knee ends the damage.
TEST(Fatigue, TabulatedSnCurveInterpolatesLogLog) {
  SnCurve basquin;
  basquin.fatigue_strength_coefficient = 1000e6;
  basquin.exponent = -0.1;
  basquin.ultimate_strength = 800e6;
  SnCurve table = basquin;
  for (double s : {500e6, 300e6, 200e6}) table.points.push_back({basquin.CyclesToFailure(s), s});
  table.Validate("test");
  for (double s : {600e6, 450e6, 350e6, 250e6, 200e6})  // above the first point: extrapolated
    EXPECT_NEAR(table.CyclesToFailure(s), basquin.CyclesToFailure(s),
                kRoundOff * basquin.CyclesToFailure(s))
        << s;
  EXPECT_TRUE(std::isinf(table.CyclesToFailure(199e6)));  // below the knee
  table.endurance_limit = 150e6;  // the last segment goes on to the endurance limit
  EXPECT_NEAR(table.CyclesToFailure(160e6), basquin.CyclesToFailure(160e6),
              kRoundOff * basquin.CyclesToFailure(160e6));
  EXPECT_TRUE(std::isinf(table.CyclesToFailure(149e6)));
  // Two points, not a power law: at the geometric midpoint the geometric mean of N.
  SnCurve two;
  two.ultimate_strength = 1e9;
  two.points = {{1e3, 800e6}, {1e6, 200e6}};
  two.Validate("test");
  EXPECT_NEAR(two.CyclesToFailure(400e6), std::sqrt(1e3 * 1e6), kRoundOff * 1e5);
  // Miner on the table equals Miner on the law it came from.
  const std::vector<RainflowCycle> cycles{{700e6, 0.0, 3.0}, {500e6, 100e6, 1.5}};
  table.endurance_limit = 0.0;
  EXPECT_NEAR(CalcMinerDamage(cycles, table).damage, CalcMinerDamage(cycles, basquin).damage,
              kRoundOff * CalcMinerDamage(cycles, basquin).damage);
}

TEST(Fatigue, BadSnPointsAreNamed) {
  SnCurve sn;
  sn.ultimate_strength = 8e8;
  const std::vector<std::pair<std::vector<SnPoint>, std::string>> bad{
      {{{1e3, 5e8}}, "at least 2 points"},
      {{{1e3, 5e8}, {1e6, 6e8}}, "sn_points[1]"},
      {{{1e6, 5e8}, {1e3, 2e8}}, "sn_points[1]"},
      {{{-1.0, 5e8}, {1e3, 2e8}}, "sn_points[0]"},
      {{{1e3, 5e8}, {1e6, 0.0}}, "sn_points[1]"}};
  for (const auto& [points, words] : bad) {
    sn.points = points;
    try {
      sn.Validate("stress output 'fillets' fatigue");
      FAIL() << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
}

TEST(Fatigue, BadSnCurveIsNamed) {
  SnCurve ok;
  ok.fatigue_strength_coefficient = 1e9;
  ok.exponent = -0.1;
  ok.ultimate_strength = 8e8;
  for (auto [field, value, name] :
       {std::tuple{&SnCurve::fatigue_strength_coefficient, -1e9, "fatigue_strength_coefficient"},
        std::tuple{&SnCurve::exponent, 0.1, "exponent"},
        std::tuple{&SnCurve::ultimate_strength, -8e8, "ultimate_strength"},
        std::tuple{&SnCurve::endurance_limit, -1.0, "endurance_limit"}}) {
    SnCurve bad = ok;
    bad.*field = value;
    try {
      bad.Validate("stress output 'fillets' fatigue");
      FAIL() << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace emb::results
