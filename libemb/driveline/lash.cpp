#include "libemb/driveline/lash.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/mbs/constraints/constraint_eval.h"

namespace emb::driveline {
namespace {

// Event function index of side s (+1 upper: 0, -1 lower: 1).
int Index(int s) { return s > 0 ? 0 : 1; }

mbs::EventNote Note(mbs::EventNote::Kind kind, int side, double velocity, double force) {
  mbs::EventNote n;
  n.kind = kind;
  n.side = side;
  n.velocity = velocity;
  n.force = force;
  return n;
}

}  // namespace

Lash::Lash(std::string name, std::vector<CoordinateTerm> terms, const LashParameters& parameters)
    : ForceElement(std::move(name)),
      terms_(std::move(terms)),
      p_(parameters),
      law_(parameters.contact, "lash '" + this->name() + "'") {
  const std::string who = "lash '" + this->name() + "'";
  EMB_THROW_IF(terms_.empty() || terms_.size() > 2,
               who << ": expected one or two joint coordinates, got " << terms_.size());
  CheckNumber(who + " lower stop", p_.lower, NumberRange::Finite());
  CheckNumber(who + " upper stop", p_.upper, NumberRange::Finite());
  EMB_THROW_IF(p_.upper < p_.lower,
               who << ": expected a lash (upper - lower stop) >= 0, got " << p_.upper - p_.lower);
  for (const CoordinateTerm& t : terms_) {
    CheckNumber(who + " coordinate coefficient (ratio)", t.coeff, NumberRange::Finite());
    EMB_THROW_IF(t.coeff == 0.0, who << ": expected a non-zero coordinate coefficient (a ratio "
                                        "of 0 leaves joint2 out of x: give joint1 alone)");
  }
  if (terms_.size() == 2) {
    const CoordinateTerm &a = terms_[0], &b = terms_[1];
    EMB_THROW_IF(a.marker_i == b.marker_i && a.marker_j == b.marker_j &&
                     a.kernel.kind == b.kernel.kind && a.kernel.axis_i == b.kernel.axis_i &&
                     a.kernel.axis_j == b.kernel.axis_j,
                 who << ": joint1 and joint2 are the same coordinate of one joint (x would be "
                        "(1 - ratio) times it); expected two different joint coordinates");
  }
  if (p_.squeeze_film) {
    const SqueezeFilmParameters& s = *p_.squeeze_film;
    CheckNumber(who + " squeeze film viscosity", s.viscosity, NumberRange::Positive("Pa s"));
    CheckNumber(who + " squeeze film width", s.width, NumberRange::Positive("m"));
    CheckNumber(who + " squeeze film radius", s.radius, NumberRange::Positive("m"));
    CheckNumber(who + " squeeze film lever", s.lever, NumberRange::Positive());
    CheckNumber(who + " squeeze film min_film", s.min_film, NumberRange::Positive("m"));
  }
}

std::vector<int> Lash::DoMarkers() const {
  std::vector<int> m;
  for (const CoordinateTerm& t : terms_) {
    m.push_back(t.marker_i);
    m.push_back(t.marker_j);
  }
  return m;
}

unsigned Lash::DoMarkerLoads(int marker) const {
  unsigned loads = 0;
  for (const CoordinateTerm& t : terms_)
    if (marker == t.marker_i || marker == t.marker_j)
      loads |= t.angle() ? mbs::kMarkerMoment : mbs::kMarkerForceAndMoment;
  return loads;
}

int Lash::state_slot(const mbs::ForceContext& ctx) const {
  return ctx.angle_slot < 0 ? -1 : ctx.angle_slot + NumAngleTerms(terms_);
}

double Lash::RoundOff(const CoordinateValue& x) const {
  // A few ulps of the larger of x and the stop.
  return 64.0 * std::numeric_limits<double>::epsilon() *
         (1.0 + std::abs(x.value) + std::max(std::abs(p_.lower), std::abs(p_.upper)));
}

double Lash::Penetration(const CoordinateValue& x, int s) const {
  return s > 0 ? x.value - p_.upper : p_.lower - x.value;
}

Lash::Mode Lash::CurrentMode(const mbs::ForceContext& ctx, const CoordinateValue& x) const {
  const int slot = state_slot(ctx);
  const bool stored = ctx.workspace != nullptr && ctx.workspace->events_active() && slot >= 0;
  if (stored && !std::isnan(ctx.workspace->state(slot)))
    return {static_cast<int>(ctx.workspace->state(slot)), ctx.workspace->state(slot + 1)};
  // The state the configuration implies: closed where the stop is penetrated. Its closing
  // speed is unknown: x' into the stop when the state is kept (a run's first state), else
  // the Hunt-Crossley floor (state-independent, so that the force stays a function of
  // (x, x') whose derivatives are the analytic ones).
  Mode m;
  for (int s : {+1, -1})
    if (Penetration(x, s) > 0.0) {
      m.side = s;
      m.impact_velocity = stored ? std::max(s * x.rate, p_.contact.min_impact_velocity)
                                 : p_.contact.min_impact_velocity;
    }
  if (stored) StoreMode(ctx, m);
  return m;
}

void Lash::StoreMode(const mbs::ForceContext& ctx, const Mode& m) const {
  const int slot = state_slot(ctx);
  ctx.workspace->set_state(slot, m.side);
  ctx.workspace->set_state(slot + 1, m.impact_velocity);
}

ContactForce Lash::SqueezeForce(const CoordinateValue& x) const {
  ContactForce out;
  if (!p_.squeeze_film) return out;
  const SqueezeFilmParameters& q = *p_.squeeze_film;
  const double C =
      3.0 * std::numbers::pi * q.width * q.viscosity / std::sqrt(2.0) * std::pow(q.radius, 1.5);
  for (int s : {+1, -1}) {
    const double delta = Penetration(x, s), approach = q.lever * s * x.rate;  // -h'
    if (!(approach > 0.0)) continue;
    const double h = q.lever * std::max(-delta, 0.0) + q.min_film;
    const double W = C * std::pow(h, -1.5) * approach;
    // P = s R W on x; dP/dx = R dW/d delta (d delta/dx = s), dP/dx' = R dW/d delta'.
    out.force += s * q.lever * W;
    if (delta < 0.0) out.d_delta += q.lever * (-1.5 * W / h) * (-q.lever);
    out.d_rate += q.lever * C * std::pow(h, -1.5) * q.lever;
  }
  return out;
}

ContactForce Lash::CoordinateForce(const CoordinateValue& x, const Mode& m) const {
  if (m.side == 0) return SqueezeForce(x);
  const int s = m.side;
  ContactForce F = law_.Eval(Penetration(x, s), s * x.rate, m.impact_velocity);
  // On x: P = s F, dP/dx = F_delta, dP/dx' = F_rate (d delta/dx = s, s^2 = 1).
  F.force *= s;
  return F;
}

void Lash::DoAddForces(const mbs::ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const CoordinateValue x = EvalCoordinate(ctx, terms_, ctx.angle_slot);
  const Mode m = CurrentMode(ctx, x);
  ContactForce P = CoordinateForce(x, m);
  // Without event location the contact is closed wherever delta > 0 and never pulls.
  if (m.side != 0 && !(ctx.workspace && ctx.workspace->events_active()) && m.side * P.force < 0)
    P.force = 0.0;
  AddCoordinateForce(ctx, x, P.force, f);
}

void Lash::DoAddForceJacobian(const mbs::ForceContext& ctx, mbs::ForceJacobianSink* sink) const {
  const CoordinateValue x = EvalCoordinate(ctx, terms_, ctx.angle_slot);
  const Mode m = CurrentMode(ctx, x);
  ContactForce P = CoordinateForce(x, m);
  if (m.side != 0 && !(ctx.workspace && ctx.workspace->events_active()) && m.side * P.force < 0)
    P = {};
  // Always the same blocks (the sparse structure is fixed), zeros while free.
  AddCoordinateForceJacobian(terms_, x, P.force, P.d_delta, P.d_rate, sink);
}

double Lash::DoCalcPotentialEnergy(const mbs::ForceContext& ctx) const {
  const CoordinateValue x = EvalCoordinate(ctx, terms_, ctx.angle_slot);
  const Mode m = CurrentMode(ctx, x);
  return m.side == 0 ? 0.0 : law_.PotentialEnergy(Penetration(x, m.side));
}

double Lash::DoCalcDissipatedPower(const mbs::ForceContext& ctx) const {
  const CoordinateValue x = EvalCoordinate(ctx, terms_, ctx.angle_slot);
  const Mode m = CurrentMode(ctx, x);
  // The film's generalised force is -P dx/dX: it removes P x' >= 0.
  if (m.side == 0) return SqueezeForce(x).force * x.rate;
  return law_.DissipatedPower(Penetration(x, m.side), m.side * x.rate, m.impact_velocity);
}

bool Lash::DoCalcLoad(const mbs::ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const {
  const CoordinateValue x = EvalCoordinate(ctx, terms_, ctx.angle_slot);
  const Mode m = CurrentMode(ctx, x);
  load->setZero();
  (*load)[terms_.front().angle() ? 5 : 2] = CoordinateForce(x, m).force;
  return true;
}

double Lash::CalcCoordinate(const mbs::ForceContext& ctx) const {
  return EvalCoordinate(ctx, terms_, ctx.angle_slot).value;
}

int Lash::CalcSide(const mbs::ForceContext& ctx) const {
  return CurrentMode(ctx, EvalCoordinate(ctx, terms_, ctx.angle_slot)).side;
}

void Lash::DoCalcEventFunctions(const mbs::ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> g) const {
  const CoordinateValue x = EvalCoordinate(ctx, terms_, ctx.angle_slot);
  const Mode m = CurrentMode(ctx, x);
  if (m.side == 0) {
    // Shifted by the round-off of delta, so that a stop touched exactly (delta = 0 at a
    // start) is not a zero IDA would stop watching until it leaves zero.
    const double tol = RoundOff(x);
    for (int s : {+1, -1}) {
      const double delta = Penetration(x, s);
      g[Index(s)] = std::min(delta - tol, law_.Eval(delta, s * x.rate, m.impact_velocity).force);
    }
    return;
  }
  const int s = m.side;
  const ContactForce F = law_.Eval(Penetration(x, s), s * x.rate, m.impact_velocity);
  g[Index(s)] = F.force;
  // dF/dt = F_delta delta' + F_rate delta'' (needs the accelerations).
  g[Index(-s)] = ctx.vdot ? F.d_delta * s * x.rate + F.d_rate * s * x.accel : 0.0;
}

mbs::EventResponse Lash::DoHandleEvent(const mbs::ForceContext& ctx, const int* crossed) const {
  using Kind = mbs::EventNote::Kind;
  const CoordinateValue x = EvalCoordinate(ctx, terms_, ctx.angle_slot);
  const Mode m = CurrentMode(ctx, x);
  mbs::EventResponse r;
  if (m.side == 0) {
    // A stop closed: the function of its side rose through 0 (falls mean nothing here).
    int side = 0;
    for (int s : {+1, -1})
      if (crossed[Index(s)] > 0 && (side == 0 || Penetration(x, s) > Penetration(x, side)))
        side = s;
    if (side == 0) return r;
    const Mode closed{side, std::max(0.0, side * x.rate)};
    StoreMode(ctx, closed);
    r.restart = true;
    r.notes.push_back(
        Note(Kind::kContactOnset, side, closed.impact_velocity,
             law_.Eval(Penetration(x, side), side * x.rate, closed.impact_velocity).force));
    return r;
  }
  const int s = m.side;
  if (crossed[Index(s)] < 0) {  // the contact force fell to zero: separation
    StoreMode(ctx, {0, m.impact_velocity});
    r.restart = true;
    r.notes.push_back(Note(Kind::kSeparation, s, -s * x.rate, 0.0));
  } else if (crossed[Index(-s)] < 0) {  // dF/dt fell through zero: a force maximum
    r.notes.push_back(Note(Kind::kPeakForce, s, s * x.rate,
                           law_.Eval(Penetration(x, s), s * x.rate, m.impact_velocity).force));
  }
  return r;
}

mbs::EventResponse Lash::DoSettleEventState(const mbs::ForceContext& ctx) const {
  using Kind = mbs::EventNote::Kind;
  const CoordinateValue x = EvalCoordinate(ctx, terms_, ctx.angle_slot);
  const Mode m = CurrentMode(ctx, x);
  const double tol = RoundOff(x);
  // Round-off of x' and x'' (differences of the bodies' rates and accelerations).
  constexpr double kUlps = 64.0 * std::numeric_limits<double>::epsilon();
  const double tol_v = kUlps * x.rate_scale, tol_a = kUlps * x.accel_scale;
  // +1 entering the stop (delta going positive), -1 leaving it, 0 at rest on it.
  auto heading = [&](int s) {
    const double d = Penetration(x, s), v = s * x.rate, a = s * x.accel;
    if (d > tol) return +1;
    if (d < -tol) return -2;  // clear of it
    if (std::abs(v) > tol_v) return v > 0 ? +1 : -1;
    if (std::abs(a) > tol_a) return a > 0 ? +1 : -1;
    return 0;
  };
  // F, dF/dt and their round-off from that of delta, delta', delta''.
  double F_tol = 0.0, dF_tol = 0.0;
  auto force = [&](int s, double v_impact, double* rate) {
    const ContactForce F = law_.Eval(Penetration(x, s), s * x.rate, v_impact);
    *rate = F.d_delta * s * x.rate + F.d_rate * s * x.accel;
    F_tol = std::abs(F.d_delta) * tol + std::abs(F.d_rate) * tol_v;
    dF_tol = std::abs(F.d_delta) * tol_v + std::abs(F.d_rate) * tol_a;
    return F.force;
  };
  mbs::EventResponse r;
  double dF = 0.0;
  if (m.side == 0) {
    for (int s : {+1, -1}) {
      const double v_impact = std::max(0.0, s * x.rate);
      const double F = force(s, v_impact, &dF);
      const int h = heading(s);
      const bool at_stop = std::abs(Penetration(x, s)) <= tol;
      const bool zero = std::abs(F) <= F_tol;
      if (h > 0 && (F > F_tol || (zero && (at_stop || dF > dF_tol)))) {
        StoreMode(ctx, {s, v_impact});
        r.restart = true;
        r.notes.push_back(Note(Kind::kContactOnset, s, v_impact, F));
        return r;
      }
    }
    return r;
  }
  const int s = m.side;
  const double F = force(s, m.impact_velocity, &dF);
  const int h = heading(s);
  if (F < -F_tol || (std::abs(F) <= F_tol && dF < -dF_tol) || h == -1 || h == -2) {
    StoreMode(ctx, {0, m.impact_velocity});
    r.restart = true;
    r.notes.push_back(Note(Kind::kSeparation, s, -s * x.rate, 0.0));
  }
  return r;
}

}  // namespace emb::driveline
