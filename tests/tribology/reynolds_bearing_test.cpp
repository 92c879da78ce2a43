// The bearing model's checks: every bad value a user can give is an InputError naming the
// bearing and the key with "expected X, got Y"; a valid bearing builds its grid and supply
// map. (Lubricant, contact and supply-feature keys have their own tests; here they are seen
// through the bearing.)

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include "libemb/common/error.h"
#include "libemb/tribology/reynolds_bearing.h"

namespace emb::tribology {
namespace {

// A passenger-car main bearing: R = 30 mm, L = 20 mm, c = 30 um, hot SAE 10W-30.
ReynoldsBearingParameters Main() {
  ReynoldsBearingParameters p;
  p.radius = 0.03;
  p.length = 0.02;
  p.clearance = 30e-6;
  p.grid = {48, 8};
  p.lubricant.viscosity = 0.0086;
  return p;
}

void ExpectInputError(const std::function<void(ReynoldsBearingParameters&)>& edit,
                      const std::string& key) {
  ReynoldsBearingParameters p = Main();
  edit(p);
  try {
    ReynoldsBearing("main_3", p);
    FAIL() << "no error for " << key;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bearing 'main_3'"), std::string::npos) << what;
    EXPECT_NE(what.find(key), std::string::npos) << what;
    EXPECT_NE(what.find("expected"), std::string::npos) << what;
    EXPECT_NE(what.find("got"), std::string::npos) << what;
  }
}

TEST(ReynoldsBearing, BuildsAValidBearing) {
  ReynoldsBearingParameters p = Main();
  p.oil_holes.push_back({3.14159, 0.0, 4e-3, 3e5});
  const ReynoldsBearing b("main_3", p);
  EXPECT_EQ(b.num_unknowns(), 48 * 7);
  EXPECT_EQ(b.who(), "bearing 'main_3'");
  EXPECT_FALSE(b.supply().empty());
  EXPECT_GT(b.SupplyUnknown(b.supply().nodes.front()), 0.0);
}

TEST(ReynoldsBearing, RefusesBadGeometry) {
  const double nan = std::nan("");
  for (double v : {0.0, -0.01, nan, std::numeric_limits<double>::infinity()}) {
    ExpectInputError([&](auto& p) { p.radius = v; }, "radius");
    ExpectInputError([&](auto& p) { p.length = v; }, "length");
    ExpectInputError([&](auto& p) { p.clearance = v; }, "clearance");
  }
  ExpectInputError([](auto& p) { p.clearance = 0.05; }, "clearance smaller than the radius");
  ExpectInputError([](auto& p) { p.lubricant.viscosity = 0.0; }, "viscosity");
  ExpectInputError([](auto& p) { p.lubricant.viscosity = -1.0; }, "viscosity");
  ExpectInputError([](auto& p) { p.grid.circumferential = 4; }, "grid.circumferential");
  ExpectInputError([](auto& p) { p.grid.axial = 1; }, "grid.axial");
}

TEST(ReynoldsBearing, RefusesMisalignmentBeyondTheClearance) {
  // 30 um over L/2 = 10 mm: a slope of 3e-3 takes all of it at the edge; 4e-3 is beyond.
  ExpectInputError([](auto& p) { p.bore_tilt = Eigen::Vector2d(3.2e-3, 2.4e-3); },
                   "bore_tilt");
  ReynoldsBearingParameters ok = Main();
  ok.bore_tilt = Eigen::Vector2d(1e-3, 0.0);
  EXPECT_NO_THROW(ReynoldsBearing("main_3", ok));
}

TEST(ReynoldsBearing, RefusesBadSupplyFeatures) {
  // Outside the bearing: |z| + d/2 > L/2.
  ExpectInputError([](auto& p) { p.oil_holes.push_back({0.0, 8e-3, 5e-3, 3e5}); },
                   "oil_holes[0]");
  ExpectInputError([](auto& p) { p.grooves.push_back({9e-3, 4e-3, 0.0, 3.0, 3e5}); },
                   "grooves[0]");
  // Negative supply pressure.
  ExpectInputError([](auto& p) { p.oil_holes.push_back({0.0, 0.0, 5e-3, -1e5}); },
                   "supply pressure");
  ExpectInputError([](auto& p) { p.grooves.push_back({0.0, 4e-3, 0.0, 3.0, -2e5}); },
                   "supply pressure");
  // Too small for the grid (R dphi = 3.9 mm, dz = 2.5 mm): a 1 mm hole between nodes.
  ExpectInputError([](auto& p) { p.oil_holes.push_back({0.06, 1.2e-3, 1e-3, 3e5}); },
                   "too coarse");
  // A groove narrower than the node spacing, between two node rows.
  ExpectInputError([](auto& p) { p.grooves.push_back({1.2e-3, 1e-3, 0.0, 2.0 * std::numbers::pi, 3e5}); },
                   "too coarse");
  // Bad sizes and extents.
  ExpectInputError([](auto& p) { p.oil_holes.push_back({0.0, 0.0, 0.0, 3e5}); }, "diameter");
  ExpectInputError([](auto& p) { p.grooves.push_back({0.0, -1e-3, 0.0, 3.0, 3e5}); }, "width");
  ExpectInputError([](auto& p) { p.grooves.push_back({0.0, 4e-3, 0.0, 7.0, 3e5}); },
                   "angular_extent");
  // Two features on one node at different pressures.
  ExpectInputError(
      [](auto& p) {
        p.oil_holes.push_back({0.0, 0.0, 5e-3, 3e5});
        p.grooves.push_back({0.0, 5e-3, 6.0, 1.0, 4e5});
      },
      "overlaps");
}

TEST(ReynoldsBearing, RefusesBadJournalOilHoles) {
  const double nan = std::nan("");
  auto hole = [](double angle, double z, double d, double ps) {
    return [=](ReynoldsBearingParameters& p) {
      p.journal_oil_holes.push_back({0.0, 0.0, 5e-3, 3e5});  // a good one first
      p.journal_oil_holes.push_back({angle, z, d, ps});
    };
  };
  ExpectInputError(hole(nan, 0.0, 5e-3, 3e5), "journal_oil_holes[1].angle");
  ExpectInputError(hole(0.0, nan, 5e-3, 3e5), "journal_oil_holes[1].axial_position");
  ExpectInputError(hole(0.0, 0.0, 0.0, 3e5), "journal_oil_holes[1].diameter");
  ExpectInputError(hole(0.0, 0.0, 5e-3, -1.0), "journal_oil_holes[1].supply_pressure");
  ExpectInputError(  // a long bearing (L 80 mm > R 30 mm), where such a hole fits axially
      [&](auto& p) {
        p.length = 0.08;
        hole(0.0, 0.0, 0.035, 3e5)(p);
      },
      "journal_oil_holes[1].diameter below");
  ExpectInputError(hole(0.0, 0.008, 5e-3, 3e5), "journal_oil_holes[1] reaches outside");
  ExpectInputError([](auto& p) { p.journal_feed_ratio = 0.0; }, "journal_feed_ratio");
  ExpectInputError([&](auto& p) { p.journal_feed_ratio = nan; }, "journal_feed_ratio");
}

TEST(ReynoldsBearing, RefusesBadNumericalSettings) {
  ExpectInputError([](auto& p) { p.pressure_scale = 0.0; }, "pressure_scale");
  ExpectInputError([](auto& p) { p.max_iterations = 0; }, "max_iterations");
  ExpectInputError([](auto& p) { p.film_floor = -1.0; }, "film_floor");
  ExpectInputError([](auto& p) { p.switch_width = 0.6; }, "switch_width");
  ExpectInputError([](auto& p) { p.switch_width = -0.01; }, "switch_width");
  ExpectInputError(
      [](auto& p) {
        p.switch_width = 0.01;
        p.complementarity = ComplementaritySolver::kFischerBurmeister;
      },
      "Fischer-Burmeister");
  ExpectInputError(
      [](auto& p) {
        p.asperity_contact = AsperityContactParameters{};  // roughness 0
      },
      "roughness");
}

}  // namespace
}  // namespace emb::tribology
