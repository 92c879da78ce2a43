// The run's event bookkeeping (libemb/mbs/dae/event_handling.h) on a scripted element whose
// answers the test chooses: only elements whose event functions crossed are asked, their
// notes become contact records (onset, the largest force of the contact, separation, a new
// record for the next closing), a restart is asked when any element switched, and the
// counters follow. The physics of real stops is in the driveline's tests; this is the
// dispatch they rely on.

#include "libemb/mbs/dae/event_handling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "tests/support/test_models.h"

namespace emb::mbs {
namespace {

// Two event functions; its answer to the next HandleEvent / SettleEventState is scripted.
class ScriptedStop final : public ForceElement {
 public:
  explicit ScriptedStop(std::string name) : ForceElement(std::move(name)) {}
  mutable EventResponse next;  // the test's script (a test element may keep state)
  mutable int calls{0};
  mutable std::vector<int> last_crossed;

 protected:
  void DoAddForces(const ForceContext&, Eigen::Ref<Eigen::VectorXd>) const override {}
  void DoAddForceJacobian(const ForceContext&, ForceJacobianSink*) const override {}
  std::vector<int> DoMarkers() const override { return {}; }
  int DoNumEventFunctions() const override { return 2; }
  void DoCalcEventFunctions(const ForceContext&, Eigen::Ref<Eigen::VectorXd> g) const override {
    g.setOnes();
  }
  EventResponse DoHandleEvent(const ForceContext&, const int* crossed) const override {
    ++calls;
    last_crossed.assign(crossed, crossed + 2);
    return next;
  }
  EventResponse DoSettleEventState(const ForceContext&) const override { return next; }
};

EventNote Note(EventNote::Kind kind, int side, double velocity, double force) {
  EventNote n;
  n.kind = kind;
  n.side = side;
  n.velocity = velocity;
  n.force = force;
  return n;
}

// A pendulum (a rod on a revolute joint) with two scripted stops.
struct Fixture {
  System sys;
  std::shared_ptr<ScriptedStop> a, b;
  std::unique_ptr<GglDae> dae;
  Eigen::VectorXd y, yp;
  Fixture() {
    sys.AddBody(testing::Rod("rod", 1.0, 0.5, Eigen::Vector3d(0.25, 0, 0), 0.0));
    sys.AddMarker("pivot_ground", "ground", Eigen::Vector3d::Zero(), testing::AxesZ());
    sys.AddMarker("pivot_rod", "rod", Eigen::Vector3d(-0.25, 0, 0), testing::AxesZ());
    sys.AddJoint("pivot", JointType::kRevolute, "pivot_rod", "pivot_ground");
    sys.SetGravity(Eigen::Vector3d(0, -9.81, 0));
    a = std::make_shared<ScriptedStop>("stop_a");
    b = std::make_shared<ScriptedStop>("stop_b");
    sys.AddForceElement(a);
    sys.AddForceElement(b);
    sys.Finalize();
    dae = std::make_unique<GglDae>(sys);
    y = Eigen::VectorXd::Zero(dae->size());
    yp = Eigen::VectorXd::Zero(dae->size());
    const PreparedRun run = PrepareRun(sys, AnalysisSettings{});
    y.segment(dae->ggl_layout().q(), dae->ggl_layout().nq()) = run.q0;
  }
  // Root directions: element a's two functions, then b's.
  bool Event(double t, std::vector<int> directions, EventLog* log) {
    return HandleEvents(sys, *dae, t, y, yp, directions, log);
  }
};

TEST(EventHandling, OnlyElementsWhoseFunctionsCrossedAreAsked) {
  Fixture f;
  ASSERT_EQ(f.dae->num_roots(), 4);
  EventLog log;
  EXPECT_FALSE(f.Event(0.1, {0, -1, 0, 0}, &log));
  EXPECT_EQ(f.a->calls, 1);
  EXPECT_EQ(f.b->calls, 0);
  EXPECT_EQ(f.a->last_crossed, (std::vector<int>{0, -1}));
  EXPECT_EQ(log.num_events, 1);
  EXPECT_EQ(log.num_restarts, 0);
  EXPECT_TRUE(log.contacts.empty());
}

TEST(EventHandling, NotesBecomeContactRecordsFromOnsetToSeparation) {
  Fixture f;
  EventLog log;
  f.a->next = {true, {Note(EventNote::Kind::kContactOnset, +1, 0.7, -40.0)}};
  EXPECT_TRUE(f.Event(0.10, {1, 0, 0, 0}, &log));
  f.a->next = {false, {Note(EventNote::Kind::kPeakForce, +1, 0.0, -250.0)}};
  EXPECT_FALSE(f.Event(0.11, {0, 1, 0, 0}, &log));
  f.a->next = {false, {Note(EventNote::Kind::kPeakForce, +1, 0.0, 120.0)}};  // a lower peak
  f.Event(0.115, {0, 1, 0, 0}, &log);
  f.a->next = {true, {Note(EventNote::Kind::kSeparation, +1, -0.5, 0.0)}};
  EXPECT_TRUE(f.Event(0.12, {-1, 0, 0, 0}, &log));
  f.a->next = {true, {Note(EventNote::Kind::kContactOnset, -1, 0.3, 10.0)}};
  f.Event(0.2, {1, 0, 0, 0}, &log);

  ASSERT_EQ(log.contacts.size(), 2u);
  const ContactRecord& c = log.contacts[0];
  EXPECT_EQ(c.element, "stop_a");
  EXPECT_EQ(c.side, +1);
  EXPECT_EQ(c.t_onset, 0.10);
  EXPECT_EQ(c.impact_velocity, 0.7);
  EXPECT_EQ(c.peak_force, 250.0);  // the largest |force| of the contact
  EXPECT_EQ(c.t_separation, 0.12);
  EXPECT_EQ(c.rebound_velocity, -0.5);
  const ContactRecord& d = log.contacts[1];  // the next closing: a record of its own, open
  EXPECT_EQ(d.side, -1);
  EXPECT_EQ(d.peak_force, 10.0);
  EXPECT_TRUE(std::isnan(d.t_separation));
  EXPECT_EQ(log.open[0], 1);
  EXPECT_EQ(log.num_events, 5);
  EXPECT_EQ(log.num_restarts, 3);
}

TEST(EventHandling, ARestartIsAskedWhenAnyElementSwitched) {
  Fixture f;
  EventLog log;
  f.a->next = {false, {}};
  f.b->next = {true, {}};
  EXPECT_TRUE(f.Event(0.3, {1, 0, 0, -1}, &log));
  EXPECT_EQ(f.a->calls, 1);
  EXPECT_EQ(f.b->calls, 1);
  EXPECT_EQ(log.num_restarts, 1);
}

TEST(EventHandling, SettlingRecordsNotesAndSaysWhetherAStateChanged) {
  Fixture f;
  EventLog log;
  const Eigen::VectorXd q = f.y.segment(f.dae->ggl_layout().q(), f.dae->ggl_layout().nq());
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(f.dae->ggl_layout().nv());
  f.a->next = {false, {}};
  f.b->next = {false, {}};
  EXPECT_FALSE(SettleEventStates(f.sys, *f.dae, 0.0, q, v, v, &log));
  f.b->next = {true, {Note(EventNote::Kind::kContactOnset, +1, 0.0, 5.0)}};
  EXPECT_TRUE(SettleEventStates(f.sys, *f.dae, 0.0, q, v, v, &log));
  ASSERT_EQ(log.contacts.size(), 1u);
  EXPECT_EQ(log.contacts[0].element, "stop_b");
  EXPECT_EQ(log.open[1], 0);
  EXPECT_EQ(log.num_events, 0);  // settling is not an integrator event
}

}  // namespace
}  // namespace emb::mbs
