// Bad input to the flexible-body builders (mbs/flexible/flexible_body.h), in C++: every error
// names the part (and the source or the interface) and says what was expected.

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "tests/support/flexible_bar.h"
#include "tests/support/input_error.h"

namespace emb {
namespace {

const ReducedBody& Bar() {
  testing::BarSpec bar;
  bar.modes = 4;
  return testing::FlexibleBar(bar);
}

void ExpectInputError(const std::function<void()>& f, const std::vector<std::string>& words) {
  EXPECT_TRUE(test::ContainsAll(test::InputErrorMessage(f), words));
}

TEST(FlexibleBodyErrors, UnknownInterfaceListsTheAvailableOnes) {
  mbs::System sys;
  const mbs::FlexiblePart part = mbs::AddFlexibleBody(&sys, "bar", Bar(), "bar.h5");
  ExpectInputError([&] { mbs::AddInterfaceMarker(&sys, part, "m", "x9"); },
                   {"part 'bar'", "bar.h5", "no interface 'x9'", "did you mean 'x0'", "x0"});
}

TEST(FlexibleBodyErrors, MoreModesThanTheBodyHas) {
  mbs::FlexibleBodyOptions o;
  o.modes.max_modes = 1000;
  ExpectInputError([&] { mbs::MakeFlexibleBody("bar", Bar(), "bar.h5", o); },
                   {"part 'bar'", "1000 modes requested", "bar.h5", "elastic modes"});
}

TEST(FlexibleBodyErrors, EmptyFrequencyBand) {
  mbs::FlexibleBodyOptions o;
  o.modes.fmax_hz = 1.0;
  ExpectInputError([&] { mbs::MakeFlexibleBody("bar", Bar(), "bar.h5", o); },
                   {"part 'bar'", "no elastic mode", "1 Hz", "the lowest is"});
}

TEST(FlexibleBodyErrors, GeometricStiffeningRequiredButAbsent) {
  ReducedBody without = Bar();
  without.geometric_stiffness = {};
  mbs::FlexibleBodyOptions o;
  o.geometric_stiffening = mbs::GeometricStiffening::kOn;
  ExpectInputError([&] { mbs::MakeFlexibleBody("bar", without, "old.h5", o); },
                   {"part 'bar'", "old.h5", "no geometric stiffness data"});
  // Asked only if available, or off: a flexible body without it.
  for (const auto gs : {mbs::GeometricStiffening::kIfAvailable, mbs::GeometricStiffening::kOff}) {
    o.geometric_stiffening = gs;
    const mbs::FlexibleBodyModel m = mbs::MakeFlexibleBody("bar", without, "old.h5", o);
    ASSERT_NE(m.body.elastic, nullptr);
    EXPECT_FALSE(m.body.elastic->geometric_stiffening);
  }
}

TEST(FlexibleBodyErrors, InitialModalCoordinatesOfTheWrongSize) {
  mbs::System sys;
  mbs::FlexibleBodyOptions o;
  o.modes.max_modes = 2;
  ExpectInputError(
      [&] { mbs::AddFlexibleBody(&sys, "bar", Bar(), "bar.h5", o, {}, Eigen::VectorXd::Zero(3)); },
      {"part 'bar'", "expected 2 initial modal coordinates", "got 3"});
  ExpectInputError(
      [&] {
        mbs::AddFlexibleBody(&sys, "bar", Bar(), "bar.h5", o, {}, {}, Eigen::VectorXd::Zero(1));
      },
      {"part 'bar'", "expected 2 initial modal rates", "got 1"});
}

TEST(FlexibleBodyErrors, StaleMeshHashAndMissingFile) {
  testing::BarSpec bar;
  bar.modes = 4;
  const std::string file = testing::FlexibleBarFile(bar);
  ExpectInputError([&] { mbs::ReadPartBodyFile(file, "bar", "not-this-mesh"); },
                   {"part 'bar'", "stale"});
  ExpectInputError([&] { mbs::ReadPartBodyFile("/nonexistent/c.h5", "crank"); },
                   {"part 'crank'", "/nonexistent/c.h5"});
  // The file's own hash passes.
  EXPECT_NO_THROW(mbs::ReadPartBodyFile(file, "bar", MeshHash(bar.MakeMesh())));
}

// A rigid part (`flexible = false`, or no mode kept) takes the reduced body's mass properties
// and has no elastic model; its interface markers are plain markers at the interface points.
TEST(FlexibleBodyErrors, RigidPartsHaveTheMassPropertiesAndNoModes) {
  for (const bool by_option : {true, false}) {
    mbs::FlexibleBodyOptions o;
    if (by_option)
      o.flexible = false;
    else
      o.modes.max_modes = 0;
    mbs::System sys;
    const mbs::FlexiblePart part = mbs::AddFlexibleBody(&sys, "bar", Bar(), "bar.h5", o);
    const mbs::RigidBody& b = sys.body(part.body);
    EXPECT_EQ(b.elastic, nullptr);
    EXPECT_FALSE(part.flexible);
    EXPECT_EQ(part.num_modes(), 0);
    EXPECT_DOUBLE_EQ(b.mass, Bar().invariants.mass);
    EXPECT_TRUE(b.inertia_B.isApprox(Bar().invariants.InertiaAboutCom(), 1e-14));
    const int m = mbs::AddInterfaceMarker(&sys, part, "root", "x0");
    EXPECT_TRUE(sys.marker(m).shape_t.size() == 0);
    EXPECT_LT((sys.marker(m).p_BM - (Bar().interfaces[0].point - part.com_mesh)).norm(), 1e-15);
    EXPECT_NE(part.note.find(by_option ? "rigid" : "0 of"), std::string::npos) << part.note;
  }
}

}  // namespace
}  // namespace emb
