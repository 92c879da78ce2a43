#include "libemb/engine/film_bearing.h"

#include <cmath>
#include <optional>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/skew.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/forces/relative_motion.h"
#include "libemb/tribology/film_dae.h"
#include "libemb/tribology/film_solver.h"

namespace emb::mbs {

using tribology::KinematicsLayout;

/// What one run keeps per bearing: the quasi-static solver (warm start), the film as DAE
/// states, and the scratch of the evaluations (sized once: an iteration matrix allocates
/// nothing after the first).
class FilmBearing::Data final : public ForceElementData {
 public:
  explicit Data(const tribology::ReynoldsBearing& b) : solver(b) {
    const int n = b.num_unknowns();
    if (b.parameters().cavitation == tribology::CavitationModel::kMassConserving) dae.emplace(b);
    u.setZero(n);
    u_dot.setZero(n);
    dR_dX.setZero(n, 12);
    dR_dV.setZero(n, 12);
    df6.setZero(6, n);
    dF_du.setZero(3, n);
    dT_du.setZero(3, n);
  }
  tribology::FilmSolver solver;
  std::optional<tribology::FilmDae> dae;
  tribology::BearingLoads loads;
  tribology::FilmDaeJacobian film;  ///< with states
  tribology::LoadJacobian total;    ///< without: the loads' total derivatives
  /// The loads' derivatives by the kinematics used for the forces (6 x 5, 6 x 6).
  Eigen::Matrix<double, 6, KinematicsLayout::kNumPositions> loads_position;
  Eigen::Matrix<double, 6, 6> loads_velocity;
  Eigen::VectorXd u, u_dot, r;
  Eigen::MatrixXd dR_dX, dR_dV, df6, dF_du, dT_du;
};

namespace {

// The 2 x 12 derivative of gamma = a_xy / a_z given da (3 x 12).
Eigen::Matrix<double, 2, 12> TiltDerivative(const Eigen::Vector3d& a,
                                            const Eigen::Matrix<double, 3, 12>& da) {
  const Eigen::Vector2d gamma = a.head<2>() / a.z();
  return (da.topRows<2>() - gamma * da.row(2)) / a.z();
}

}  // namespace

bool CalcFilmBearingMotion(const MarkerKinematics& I, const MarkerKinematics& J,
                           bool derivatives, FilmBearing::Motion* m) {
  const RelativeMotion rel = CalcRelativeMotion(I, J);
  const Eigen::Vector3d z_I = I.R_WM.col(2);
  const Eigen::Vector3d a = rel.R_JW * z_I;
  if (!(a.z() > 0.0)) return false;
  const Eigen::Vector3d a_dot = rel.w.cross(a);
  tribology::JournalKinematics& k = m->kin;
  k.eccentricity = rel.x.head<2>();
  k.eccentricity_rate = rel.x_dot.head<2>();
  k.tilt = a.head<2>() / a.z();
  k.tilt_rate = (a_dot.head<2>() - k.tilt * a_dot.z()) / a.z();
  k.journal_speed = rel.w.z();
  k.shell_speed = 0.0;
  // psi: the angle of the journal's x axis in the shell's plane, b = R_JW x_I.
  const Eigen::Vector3d x_I = I.R_WM.col(0);
  const Eigen::Vector3d b = rel.R_JW * x_I;
  k.journal_angle = std::atan2(b.y(), b.x());
  if (!derivatives) return true;

  MarkerPairDerivatives& dm = m->markers;
  dm = {DifferentiateMarker(I, 0, 2), DifferentiateMarker(J, 1, 2)};
  const RelativeMotionDerivatives dr = DifferentiateRelativeMotion(rel, I, J, dm.dI, dm.dJ);
  using M3 = Eigen::Matrix<double, 3, 12>;
  const M3 w_x = dr.w_x, w_v = dr.w_v;
  // a = R_JW z_I: da = R_JW [z_I x] (dphi_J - dphi_I) (virtual rotations in W).
  const M3 da = rel.R_JW * Skew(z_I) * (dm.dJ.rotation_x - dm.dI.rotation_x);
  // a' = w x a.
  const M3 da_dot_x = -Skew(a) * w_x + Skew(rel.w) * da;
  const M3 da_dot_v = -Skew(a) * w_v;
  const Eigen::Matrix<double, 2, 12> dgamma = TiltDerivative(a, da);
  const Eigen::Vector2d& gamma_dot = k.tilt_rate;
  // gamma' = (a'_xy - gamma a'_z) / a_z.
  const auto tilt_rate = [&](const M3& d_a_dot, bool with_position) {
    Eigen::Matrix<double, 2, 12> out = (d_a_dot.topRows<2>() - k.tilt * d_a_dot.row(2)) / a.z();
    if (with_position) out -= (a_dot.z() * dgamma + gamma_dot * da.row(2)) / a.z();
    return out;
  };
  // db as da; dpsi = (b_x db_y - b_y db_x) / (b_x^2 + b_y^2) (b_xy != 0 while a_z > 0).
  const M3 db = rel.R_JW * Skew(x_I) * (dm.dJ.rotation_x - dm.dI.rotation_x);
  m->position_x.middleRows<2>(KinematicsLayout::kEx) = dr.x_x.topRows<2>();
  m->position_x.middleRows<2>(KinematicsLayout::kTiltX) = dgamma;
  m->position_x.row(KinematicsLayout::kJournalAngle) =
      (b.x() * db.row(1) - b.y() * db.row(0)) / b.head<2>().squaredNorm();
  m->velocity_x.setZero();
  m->velocity_v.setZero();
  m->velocity_x.middleRows<2>(KinematicsLayout::kEdotX) = dr.x_dot_x.topRows<2>();
  m->velocity_v.middleRows<2>(KinematicsLayout::kEdotX) = dr.x_dot_v.topRows<2>();
  m->velocity_x.middleRows<2>(KinematicsLayout::kTiltDotX) = tilt_rate(da_dot_x, true);
  m->velocity_v.middleRows<2>(KinematicsLayout::kTiltDotX) = tilt_rate(da_dot_v, false);
  m->velocity_x.row(KinematicsLayout::kOmegaJournal) = w_x.row(2);
  m->velocity_v.row(KinematicsLayout::kOmegaJournal) = w_v.row(2);
  return true;
}

FilmBearing::FilmBearing(std::string name, int marker_i, int marker_j,
                         const tribology::ReynoldsBearingParameters& p)
    : ForceElement(name),
      i_(marker_i),
      j_(marker_j),
      bearing_(std::move(name), p),
      states_(p.cavitation == tribology::CavitationModel::kMassConserving) {}

int FilmBearing::DoNumContinuousStates() const { return states_ ? bearing_.num_unknowns() : 0; }

// u is p / p_ref in the full film (p_ref 1 MPa by default) and theta - 1 in the cavity: 1e-6
// is 1 Pa and a millionth of the fill fraction, below what the loads resolve.
double FilmBearing::DoStateTolerance(int) const { return 1e-6; }

std::string FilmBearing::DoStateName(int i) const {
  const tribology::BearingGrid& g = bearing_.grid();
  std::ostringstream o;
  o << "bearing '" << name() << "' film u at phi = " << g.angle(g.column_of(i)) << " rad, z = "
    << g.axial(g.row_of(i)) << " m";
  return o.str();
}

std::unique_ptr<ForceElementData> FilmBearing::DoMakeData() const {
  return std::make_unique<Data>(bearing_);
}

FilmBearing::Data& FilmBearing::GetData(const ForceContext& ctx, std::unique_ptr<Data>* own) const {
  if (ForceElementData* d = ElementData(ctx, *this)) return static_cast<Data&>(*d);
  *own = std::make_unique<Data>(bearing_);
  return **own;
}

namespace {

bool Motion(const ForceContext& ctx, const FilmBearing& b, const MarkerKinematics& I,
            const MarkerKinematics& J, bool derivatives, FilmBearing::Motion* m) {
  if (CalcFilmBearingMotion(I, J, derivatives, m)) return true;
  std::ostringstream o;
  o << b.bearing().who() << ": at t = " << ctx.t
    << " s the journal axis is turned 90 degrees or more from the bore's axis";
  ctx.Fail(o.str());
  return false;
}

}  // namespace

/// The preamble of every evaluation: the markers, the motion, the run's data and (if `film`)
/// the film at the context's state; `ok` false if any failed (reported through ctx).
struct FilmBearing::Evaluation {
  Evaluation(const FilmBearing& b, const ForceContext& ctx, bool derivatives, bool film = true)
      : markers(ctx, b.i_, b.j_) {
    if (!mbs::Motion(ctx, b, markers.I, markers.J, derivatives, &motion)) return;
    d = &b.GetData(ctx, &own);
    ok = !film || b.Evaluate(ctx, motion, *d, derivatives);
  }
  MarkerPair markers;
  Motion motion;
  std::unique_ptr<Data> own;
  Data* d{nullptr};
  bool ok{false};
};

bool FilmBearing::Evaluate(const ForceContext& ctx, const Motion& m, Data& d, bool jacobian) const {
  tribology::FilmSolveInfo info;
  if (StatesInContext(ctx)) {
    const int n = bearing_.num_unknowns();
    d.u = Eigen::Map<const Eigen::VectorXd>(ctx.z, n);
    d.u_dot = Eigen::Map<const Eigen::VectorXd>(ctx.z_dot, n);
    if (jacobian) {
      info = d.dae->CalcJacobian(d.u, d.u_dot, m.kin, &d.film, &d.loads);
      d.loads_position = d.film.loads.d_position;
      d.loads_velocity = d.film.loads.d_velocity;
    } else {
      info = d.dae->CalcResidual(d.u, d.u_dot, m.kin, &d.r, &d.loads);
    }
  } else {
    tribology::LoadJacobian* total = jacobian ? &d.total : nullptr;
    info = d.solver.SolveQuasiStatic(m.kin, &d.loads, total);
    if (jacobian && info.ok()) {
      d.loads_position = d.total.d_position;
      d.loads_velocity = d.total.d_velocity;
    }
  }
  if (info.ok()) return true;
  std::ostringstream o;
  o << info.message << " (at t = " << ctx.t << " s)";
  ctx.Fail(o.str());
  return false;
}

namespace {

// The journal's wrench in W from the stacked loads (LoadLayout): F = R_WJ [F; 0],
// T = R_WJ [M; T_j].
void WorldWrench(const Eigen::Matrix3d& R_WJ, const tribology::BearingLoads& l,
                 Eigen::Vector3d* F, Eigen::Vector3d* T) {
  *F = R_WJ.leftCols<2>() * l.force;
  *T = R_WJ * Eigen::Vector3d(l.moment.x(), l.moment.y(), l.journal_torque);
}

}  // namespace

void FilmBearing::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const Evaluation ev(*this, ctx, false);
  if (!ev.ok) return;
  Eigen::Vector3d F, T;
  WorldWrench(ev.markers.J.R_WM, ev.d->loads, &F, &T);
  AddWrenchPair(ctx.system->layout(), ev.markers.I, ev.markers.J, F, T, f);
}

bool FilmBearing::DoCalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* out) const {
  const Evaluation ev(*this, ctx, false);
  if (!ev.ok) return false;
  const tribology::BearingLoads& l = ev.d->loads;
  *out << l.force, 0.0, l.moment, l.journal_torque;
  return true;
}

std::vector<ElementOutput> FilmBearing::DoOutputs() const {
  return {{"h_min", "m"},           {"h_min_angle", "rad"},       {"p_max", "Pa"},
          {"p_max_angle", "rad"},   {"friction_power", "W"},      {"side_flow", "m^3/s"},
          {"supply_flow", "m^3/s"}, {"eccentricity_ratio", "-"}, {"cavitated_fraction", "-"},
          {"contact_force", "N"},   {"eccentricity_x", "m"},      {"eccentricity_y", "m"}};
}

bool FilmBearing::DoCalcOutputs(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> out) const {
  const Evaluation ev(*this, ctx, false);
  if (!ev.ok) return false;
  const tribology::BearingLoads& l = ev.d->loads;
  out << l.min_film, l.min_film_angle, l.max_pressure, l.max_pressure_angle, l.power_loss,
      l.side_flow, l.supply_flow,
      ev.motion.kin.eccentricity.norm() / bearing_.parameters().clearance, l.cavitated_fraction,
      l.contact_force.norm(), ev.motion.kin.eccentricity.x(), ev.motion.kin.eccentricity.y();
  return true;
}

double FilmBearing::DoCalcDissipatedPower(const ForceContext& ctx) const {
  const Evaluation ev(*this, ctx, false);
  return ev.ok ? ev.d->loads.power_loss : 0.0;
}

void FilmBearing::DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  const Evaluation ev(*this, ctx, true);
  if (!ev.ok) return;
  const MarkerKinematics& I = ev.markers.I;
  const MarkerKinematics& J = ev.markers.J;
  const Motion& m = ev.motion;
  Data& d = *ev.d;
  const auto& [dI, dJ] = m.markers;
  const Eigen::Matrix3d& R_WJ = J.R_WM;
  Eigen::Vector3d F, T;
  WorldWrench(R_WJ, d.loads, &F, &T);
  // Stacked loads y (6) by X and V: dy/dX = Y_pos dpos/dX + Y_vel dvel/dX, dy/dV = Y_vel dvel/dV.
  const Eigen::Matrix<double, 6, 12> dy_x =
      d.loads_position * m.position_x + d.loads_velocity * m.velocity_x;
  const Eigen::Matrix<double, 6, 12> dy_v = d.loads_velocity * m.velocity_v;
  // d(R_WJ a) = R_WJ da - [R_WJ a x] dphi_J.
  const SlotRows<3> dF_x = R_WJ.leftCols<2>() * dy_x.topRows<2>() - Skew(F) * dJ.rotation_x;
  const SlotRows<3> dT_x = R_WJ * dy_x.middleRows<3>(2) - Skew(T) * dJ.rotation_x;
  const SlotRows<3> dF_v = R_WJ.leftCols<2>() * dy_v.topRows<2>();
  const SlotRows<3> dT_v = R_WJ * dy_v.middleRows<3>(2);
  ScatterWrenchPairJacobian(I, J, dI, dJ, F, T, dF_x, dT_x, dF_v, dT_v, sink);
}

void FilmBearing::DoCalcStateResidual(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> r) const {
  const Evaluation ev(*this, ctx, false);
  if (ev.ok) r = ev.d->r;
}

void FilmBearing::DoAddStateJacobian(const ForceContext& ctx, double cj,
                                     StateJacobianSink* sink) const {
  const Evaluation ev(*this, ctx, true);
  if (!ev.ok) return;
  Data& d = *ev.d;
  const tribology::FilmDaeJacobian& jac = d.film;
  const Motion& m = ev.motion;
  // dR/du + cj dR/du': entry by entry on the film's fixed five-point pattern (a dense n x n
  // block would fill the iteration matrix), then the diagonal's cj term.
  for (int col = 0; col < jac.dr_du.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(jac.dr_du, col); it; ++it)
      sink->AddStateBlock(static_cast<int>(it.row()), col, Eigen::Matrix<double, 1, 1>(it.value()));
  for (int k = 0; k < jac.dr_du_dot.size(); ++k)
    sink->AddStateBlock(k, k, Eigen::Matrix<double, 1, 1>(cj * jac.dr_du_dot[k]));
  // dR/d(X, V) through the kinematics.
  d.dR_dX.noalias() = jac.dr_dx * m.position_x;
  d.dR_dX.noalias() += jac.dr_dv * m.velocity_x;
  d.dR_dV.noalias() = jac.dr_dv * m.velocity_v;
  const MarkerKinematics& I = ev.markers.I;
  const MarkerKinematics& J = ev.markers.J;
  sink->AddMarkerStateRows(0, I, d.dR_dX.leftCols<6>(), d.dR_dV.leftCols<6>());
  sink->AddMarkerStateRows(0, J, d.dR_dX.rightCols<6>(), d.dR_dV.rightCols<6>());
  // The forces by u: F_W and T_W (WorldWrench) at p_WI, on I's virtual body (arm s_WI) and,
  // opposite, on J's (arm p_WI - its origin).
  const Eigen::Matrix3d& R_WJ = J.R_WM;
  const auto& dy_du = jac.loads.d_unknowns;
  d.dF_du.noalias() = R_WJ.leftCols<2>() * dy_du.topRows<2>();
  d.dT_du.noalias() = R_WJ * dy_du.middleRows<3>(2);
  d.df6.topRows<3>() = d.dF_du;
  d.df6.bottomRows<3>().noalias() = I.R_WB.transpose() * d.dT_du;
  d.df6.bottomRows<3>().noalias() += I.R_WB.transpose() * Skew(I.s_W) * d.dF_du;
  sink->AddMarkerForceByState(I, 0, d.df6);
  const Eigen::Vector3d arm_J = I.p_WM - (J.p_WM - J.s_W);
  d.df6.topRows<3>() = -d.dF_du;
  d.df6.bottomRows<3>().noalias() = -J.R_WB.transpose() * d.dT_du;
  d.df6.bottomRows<3>().noalias() -= J.R_WB.transpose() * Skew(arm_J) * d.dF_du;
  sink->AddMarkerForceByState(J, 0, d.df6);
}

void FilmBearing::DoCalcSteadyStates(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> z,
                                     Eigen::Ref<Eigen::VectorXd> z_dot) const {
  z_dot.setZero();
  const Evaluation ev(*this, ctx, false, /*film=*/false);
  if (ev.d == nullptr) return;
  const tribology::FilmSolveInfo info = ev.d->solver.SolveQuasiStatic(ev.motion.kin, nullptr);
  if (info.ok()) {
    z = ev.d->solver.universal();
    return;
  }
  std::ostringstream o;
  o << info.message << " (the steady film at t = " << ctx.t << " s)";
  ctx.Fail(o.str());
}

}  // namespace emb::mbs
