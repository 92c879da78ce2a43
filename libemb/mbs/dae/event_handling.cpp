#include "libemb/mbs/dae/event_handling.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

void Record(const EventNote& note, int k, const std::string& name, double t, EventLog* log) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  int& open = log->open[static_cast<std::size_t>(k)];
  switch (note.kind) {
    case EventNote::Kind::kContactOnset: {
      ContactRecord c;
      c.element = name;
      c.element_index = k;
      c.side = note.side;
      c.t_onset = t;
      c.impact_velocity = note.velocity;
      c.peak_force = std::abs(note.force);
      c.t_separation = kNaN;
      c.rebound_velocity = kNaN;
      open = static_cast<int>(log->contacts.size());
      log->contacts.push_back(c);
      break;
    }
    case EventNote::Kind::kPeakForce:
      if (open >= 0) {
        ContactRecord& c = log->contacts[static_cast<std::size_t>(open)];
        c.peak_force = std::max(c.peak_force, std::abs(note.force));
      }
      break;
    case EventNote::Kind::kSeparation:
      if (open >= 0) {
        ContactRecord& c = log->contacts[static_cast<std::size_t>(open)];
        c.t_separation = t;
        c.rebound_velocity = note.velocity;
      }
      open = -1;
      break;
  }
}

}  // namespace

bool HandleEvents(const System& system, const GglDae& dae, double t, const Eigen::VectorXd& y,
                  const Eigen::VectorXd& yp, const std::vector<int>& root_directions,
                  EventLog* log) {
  const GglLayout& G = dae.ggl_layout();
  const auto& forces = system.force_elements();
  EMB_CHECK(static_cast<int>(root_directions.size()) == dae.num_roots());
  if (log->open.size() != forces.size()) log->open.assign(forces.size(), -1);
  ++log->num_events;
  const Eigen::VectorXd q = y.segment(G.q(), G.nq());
  const Eigen::VectorXd v = y.segment(G.v(), G.nv());
  const Eigen::VectorXd vdot = yp.segment(G.v(), G.nv());
  const auto bodies = CalcBodyKinematics(system, q, v);
  bool restart = false;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    const int offset = dae.root_offset(static_cast<int>(k));
    if (offset < 0) continue;
    const int n = forces[k]->num_event_functions();
    const int* crossed = root_directions.data() + offset;
    if (std::all_of(crossed, crossed + n, [](int d) { return d == 0; })) continue;
    const ForceContext ctx{
        &system, &bodies, t, &dae.workspace(), system.force_angle_slot(static_cast<int>(k)), nullptr, &vdot};
    const EventResponse r = forces[k]->HandleEvent(ctx, crossed);
    restart = restart || r.restart;
    for (const EventNote& note : r.notes)
      Record(note, static_cast<int>(k), forces[k]->name(), t, log);
  }
  if (restart) ++log->num_restarts;
  return restart;
}

bool SettleEventStates(const System& system, const GglDae& dae, double t, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& v, const Eigen::VectorXd& vdot, EventLog* log) {
  const auto& forces = system.force_elements();
  if (log->open.size() != forces.size()) log->open.assign(forces.size(), -1);
  const auto bodies = CalcBodyKinematics(system, q, v);
  bool changed = false;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    if (dae.root_offset(static_cast<int>(k)) < 0) continue;
    const ForceContext ctx{
        &system, &bodies, t, &dae.workspace(), system.force_angle_slot(static_cast<int>(k)), nullptr, &vdot};
    const EventResponse r = forces[k]->SettleEventState(ctx);
    changed = changed || r.restart;
    for (const EventNote& note : r.notes)
      Record(note, static_cast<int>(k), forces[k]->name(), t, log);
  }
  return changed;
}

}  // namespace emb::mbs
