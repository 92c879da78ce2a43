#include "libemb/tribology/film_solver.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libemb/common/error.h"

namespace emb::tribology {
namespace {

// Fischer-Burmeister-Newton stops when the residual (relative to the flow scale) and phi_FB
// are below this: a few hundred times the round-off of the flux sums.
constexpr double kFischerBurmeisterTolerance = 1e-12;
// phi_FB is not differentiable at (0, 0); its generalised derivative there (both partials
// 1 - 1/sqrt(2)) is taken below this radius.
constexpr double kFischerBurmeisterKink = 1e-14;
// The smoothed switch's Newton stops when its steps in the band are below this fraction of
// max(1, |u|) (NewtonSwitch).
constexpr double kSmoothedSwitchStep = 1e-10;

bool Cavitating(CavitationModel m) {
  return m == CavitationModel::kMassConserving || m == CavitationModel::kReynolds;
}

}  // namespace

const char* ToString(FilmStatus s) {
  switch (s) {
    case FilmStatus::kSuccess: return "success";
    case FilmStatus::kJournalTouchesShell: return "journal touches shell";
    case FilmStatus::kNotConverged: return "not converged";
    case FilmStatus::kSingular: return "singular";
    case FilmStatus::kBeyondViscosityLaw: return "beyond viscosity law";
    case FilmStatus::kNegativeFillFraction: return "negative fill fraction";
  }
  return "unknown";
}

FilmSolver::FilmSolver(const ReynoldsBearing& bearing) : bearing_(&bearing), film_(bearing) {
  const int n = bearing.num_unknowns();
  const BearingGrid& g = bearing.grid();
  x_.Resize(n);
  lu_.Resize(g.num_circumferential(), g.num_rows());
  for (auto* v : {&u_, &u_new_, &r_, &rhs_, &fb_a_, &fb_b_, &fb_phi_, &fb_da_, &fb_db_, &alpha_,
                  &beta_, &slack_w_, &work_, &fb_correction_})
    v->setZero(n);
  lambda_.setZero(n, LoadLayout::kNumLoads);
  partials_.d_unknowns.setZero(LoadLayout::kNumLoads, n);
  ResetWarmStart();
}

void FilmSolver::ResetWarmStart() {
  u_.setZero();
  for (int k : bearing_->supply().nodes) u_[k] = bearing_->SupplyUnknown(k);
}

void FilmSolver::SetWarmStart(const Eigen::VectorXd& universal) {
  EMB_THROW_IF(universal.size() != bearing_->num_unknowns(),
               bearing_->who() << ": expected a warm start of " << bearing_->num_unknowns()
                               << " unknowns, got " << universal.size());
  u_ = universal;
}

FilmState FilmSolver::state() const {
  FilmState s;
  s.universal = u_;
  s.content.resize(u_.size());
  for (int k = 0; k < u_.size(); ++k) s.content[k] = x_.theta[k] * film_.film(k);
  return s;
}

double FilmSolver::FlowScale(const StorageInputs& st) const {
  const BearingGrid& g = bearing_->grid();
  const ReynoldsBearingParameters& p = bearing_->parameters();
  const double c = p.clearance;
  double q = std::abs(film_.surface_speed()) * c * g.dz() +
             p.pressure_scale * c * c * c * g.dz() /
                 (12.0 * bearing_->lubricant().ambient_viscosity() * g.radius() * g.dphi());
  double hdot = 0.0;
  for (int k = 0; k < g.num_unknowns(); ++k) hdot = std::max(hdot, std::abs(film_.film_rate(k)));
  q += g.node_area() * hdot;
  if (st.term == StorageTerm::kBackwardEuler) q += g.node_area() * c / st.dt;
  return q;
}

FilmSolveInfo FilmSolver::Fail(FilmStatus s, const std::string& what, FilmSolveInfo info) const {
  info.status = s;
  info.message = what.empty() ? bearing_->who() + ": " + ToString(s) : what;
  return info;
}

bool FilmSolver::FactorizeSwitchJacobian(const StorageInputs& st) {
  lu_.SetZero();
  FillFilmJacobian(film_, x_, st,
                   ColumnWeights{x_.dpsi_du.data(), x_.dtheta_du.data(), x_.dslack_du.data()},
                   &lu_);
  return lu_.Factorize();
}

FilmSolveInfo FilmSolver::NewtonSwitch(const StorageInputs& st, FilmSolveInfo info) {
  const ReynoldsBearing& b = *bearing_;
  const bool cavitating = Cavitating(b.parameters().cavitation);
  const int n = b.num_unknowns();
  const double w =
      b.parameters().cavitation == CavitationModel::kMassConserving ? b.parameters().switch_width : 0.0;
  for (int it = 0; it < b.parameters().max_iterations; ++it) {
    if (!SetUnknownsFromUniversal(b, film_, u_, &x_))
      return Fail(FilmStatus::kBeyondViscosityLaw, b.BeyondViscosityLawMessage(), info);
    CalcFilmResidual(film_, x_, u_, st, &r_, &balance_);
    ++info.iterations;
    ++info.factorizations;
    if (!FactorizeSwitchJacobian(st))
      return Fail(FilmStatus::kSingular,
                  b.who() + ": singular film Jacobian (a cavitated zone with no Couette "
                            "transport: zero mean surface speed?)", info);
    rhs_ = -r_;
    lu_.Solve(rhs_.data());
    // Exact switch: the equations are linear in u on each sign pattern, so a step that
    // changes no sign has solved them. Smoothed switch: also quadratic within the band, so
    // the step itself must have become round-off there (1e-10 of u: 1e-4 Pa, 1e-10 of fill).
    int unsettled = 0;  // nodes that changed sign, or still moved within the band
    for (int k = 0; k < n; ++k) {
      const double un = u_[k] + rhs_[k];
      if (cavitating && !b.is_supply(k)) {
        if ((un >= 0.0) != (u_[k] >= 0.0)) ++unsettled;
        if (std::min(std::abs(un), std::abs(u_[k])) < w &&
            std::abs(rhs_[k]) > kSmoothedSwitchStep * std::max(1.0, std::abs(un)))
          ++unsettled;
      }
      u_[k] = un;
    }
    if (!cavitating || unsettled == 0) return info;
  }
  std::ostringstream os;
  os << b.who() << ": the cavitation pattern did not settle in " << b.parameters().max_iterations
     << " Newton iterations";
  return Fail(FilmStatus::kNotConverged, os.str(), info);
}

FilmSolveInfo FilmSolver::NewtonFischerBurmeister(const StorageInputs& st, FilmSolveInfo info) {
  const ReynoldsBearing& b = *bearing_;
  const int n = b.num_unknowns();
  const double pref = b.parameters().pressure_scale;
  const bool jfo = b.parameters().cavitation == CavitationModel::kMassConserving;
  for (int k = 0; k < n; ++k) {
    fb_a_[k] = std::max(u_[k], 0.0);
    fb_b_[k] = std::max(-u_[k], 0.0);
  }
  const double scale = FlowScale(st);
  bool converged = false;
  for (int it = 0; it < b.parameters().max_iterations; ++it) {
    if (!SetUnknownsFromPairs(b, film_, fb_a_, fb_b_, &x_))
      return Fail(FilmStatus::kBeyondViscosityLaw, b.BeyondViscosityLawMessage(), info);
    u_new_ = fb_a_ - fb_b_;  // supply rows: r = u - u_s
    CalcFilmResidual(film_, x_, u_new_, st, &r_, &balance_);
    double worst = r_.cwiseAbs().maxCoeff() / scale;
    for (int k = 0; k < n; ++k) {
      if (b.is_supply(k)) {
        fb_phi_[k] = 0.0;
        alpha_[k] = pref;
        beta_[k] = slack_w_[k] = 0.0;
        work_[k] = 0.0;
        continue;
      }
      const double a = fb_a_[k], bb = fb_b_[k], norm = std::hypot(a, bb);
      fb_phi_[k] = a + bb - norm;
      worst = std::max(worst, std::abs(fb_phi_[k]));
      const double da = norm > kFischerBurmeisterKink ? 1.0 - a / norm : 1.0 - M_SQRT1_2;
      const double db = norm > kFischerBurmeisterKink ? 1.0 - bb / norm : 1.0 - M_SQRT1_2;
      fb_da_[k] = da;
      fb_db_[k] = db;
      const double sigma = jfo ? 0.0 : x_.slack_scale[k];
      // dr/da = p_ref Pcol, dr/db = -Tcol (JFO) or -sigma e_k (Reynolds); eliminate the
      // variable with the smaller FB partial.
      if (db >= da) {  // primary a: db > 0 here
        alpha_[k] = pref;
        beta_[k] = jfo ? da / db : 0.0;
        slack_w_[k] = jfo ? 0.0 : sigma * da / db;
      } else {  // primary b
        alpha_[k] = -pref * db / da;
        beta_[k] = jfo ? -1.0 : 0.0;
        slack_w_[k] = jfo ? 0.0 : -sigma;
      }
    }
    if (worst < kFischerBurmeisterTolerance) {
      converged = true;
      break;
    }
    ++info.iterations;
    ++info.factorizations;
    // Right-hand side: -r + sum_k (dr/db_k phi_k / db_k | dr/da_k phi_k / da_k).
    for (int k = 0; k < n; ++k) {
      if (b.is_supply(k) || fb_db_[k] >= fb_da_[k]) {
        work_[k] = 0.0;  // reused below as the correction's alpha
      } else {
        work_[k] = pref * fb_phi_[k] / fb_da_[k];
      }
    }
    // beta/slack corrections of the primary-a nodes go through u_new_ and fb_phi_ scratch.
    for (int k = 0; k < n; ++k) {
      const bool primary_a = !b.is_supply(k) && fb_db_[k] >= fb_da_[k];
      u_new_[k] = primary_a && jfo ? -fb_phi_[k] / fb_db_[k] : 0.0;
      r_[k] = -r_[k];
    }
    Eigen::VectorXd& slack_corr = rhs_;
    for (int k = 0; k < n; ++k) {
      const bool primary_a = !b.is_supply(k) && fb_db_[k] >= fb_da_[k];
      slack_corr[k] = primary_a && !jfo ? -x_.slack_scale[k] * fb_phi_[k] / fb_db_[k] : 0.0;
    }
    fb_correction_.setZero();
    AddFilmJacobianRowSums(film_, x_, st,
                           ColumnWeights{work_.data(), u_new_.data(), slack_corr.data()},
                           &fb_correction_);
    for (int k = 0; k < n; ++k) rhs_[k] = r_[k] + (b.is_supply(k) ? 0.0 : fb_correction_[k]);
    lu_.SetZero();
    FillFilmJacobian(film_, x_, st, ColumnWeights{alpha_.data(), beta_.data(), slack_w_.data()},
                     &lu_);
    if (!lu_.Factorize())
      return Fail(FilmStatus::kSingular, b.who() + ": singular film Jacobian (FB-Newton)", info);
    lu_.Solve(rhs_.data());
    for (int k = 0; k < n; ++k) {
      const double dk = rhs_[k];
      if (b.is_supply(k)) {
        fb_a_[k] += dk;
      } else if (fb_db_[k] >= fb_da_[k]) {
        fb_a_[k] += dk;
        fb_b_[k] += -(fb_phi_[k] + fb_da_[k] * dk) / fb_db_[k];
      } else {
        fb_b_[k] += dk;
        fb_a_[k] += -(fb_phi_[k] + fb_db_[k] * dk) / fb_da_[k];
      }
    }
  }
  if (!converged) {
    std::ostringstream os;
    os << b.who() << ": Fischer-Burmeister-Newton did not converge in "
       << b.parameters().max_iterations << " iterations";
    return Fail(FilmStatus::kNotConverged, os.str(), info);
  }
  for (int k = 0; k < n; ++k) u_[k] = fb_a_[k] >= fb_b_[k] ? fb_a_[k] : -fb_b_[k];
  // Polish at the pattern (one switch iteration when FB found it) and factorise for the loads.
  return NewtonSwitch(st, info);
}

FilmSolveInfo FilmSolver::Solve(const StorageInputs& st, const JournalKinematics& kin,
                                BearingLoads* loads, LoadJacobian* jacobian) {
  FilmSolveInfo info;
  const ReynoldsBearing& b = *bearing_;
  std::string message;
  if (!film_.Set(kin, &message)) return Fail(FilmStatus::kJournalTouchesShell, message, info);
  if (!u_.allFinite()) ResetWarmStart();
  for (int k : b.supply().nodes) u_[k] = b.SupplyUnknown(k);
  const bool fb = b.parameters().complementarity == ComplementaritySolver::kFischerBurmeister &&
                  Cavitating(b.parameters().cavitation);
  info = fb ? NewtonFischerBurmeister(st, info) : NewtonSwitch(st, info);
  if (!info.ok()) return info;
  // The last Newton update has not been mapped yet: it may have left the viscosity law's range.
  if (!SetUnknownsFromUniversal(b, film_, u_, &x_))
    return Fail(FilmStatus::kBeyondViscosityLaw,
                b.who() + ": the converged film pressure exceeds the pressure-viscosity law's "
                          "range (reduced pressure at its limit)", info);
  CalcFilmResidual(film_, x_, u_, st, &r_, &balance_);
  info.residual = r_.cwiseAbs().maxCoeff() / FlowScale(st);
  if (b.parameters().cavitation == CavitationModel::kMassConserving) {
    int worst = 0;
    for (int k = 0; k < b.num_unknowns(); ++k)
      if (x_.theta[k] < x_.theta[worst]) worst = k;
    // The fill fraction comes from u = theta - 1: round-off of u (its film Jacobian's
    // condition times 1e-16) is not an emptied cavity.
    constexpr double kFillFractionRoundOff = 1e-10;
    if (x_.theta[worst] < -kFillFractionRoundOff) {
      std::ostringstream os;
      const BearingGrid& g = b.grid();
      os << b.who() << ": fill fraction " << x_.theta[worst] << " < 0 at phi = "
         << g.angle(g.column_of(worst)) << " rad, z = " << g.axial(g.row_of(worst))
         << " m: the squeeze empties the cavity faster than the Couette flow fills it; the "
            "quasi-static film is ill-posed there (use the transient film)";
      return Fail(FilmStatus::kNegativeFillFraction, os.str(), info);
    }
  }
  BearingLoads unused;  // a caller may want the film state only
  CalcBearingLoads(film_, x_, balance_, loads ? loads : &unused, jacobian ? &partials_ : nullptr);
  if (!jacobian) return info;
  // Adjoint: J^T Lambda = (dy/du)^T with the factorisation of the final pattern.
  lambda_ = partials_.d_unknowns.transpose();
  lu_.SolveTransposed(lambda_.data(), LoadLayout::kNumLoads);
  jacobian->d_position = partials_.d_position;
  jacobian->d_velocity = partials_.d_velocity;
  AddAdjointKinematicTerms(film_, x_, st, lambda_, &adjoint_rows_, &jacobian->d_position,
                           &jacobian->d_velocity);
  return info;
}

FilmSolveInfo FilmSolver::SolveQuasiStatic(const JournalKinematics& kin, BearingLoads* loads,
                                           LoadJacobian* jacobian) {
  StorageInputs st;
  st.term = StorageTerm::kQuasiStatic;
  return Solve(st, kin, loads, jacobian);
}

FilmSolveInfo FilmSolver::Step(const FilmState& previous, double dt, const JournalKinematics& kin,
                               FilmState* next, BearingLoads* loads, LoadJacobian* jacobian) {
  const ReynoldsBearing& b = *bearing_;
  EMB_THROW_IF(b.parameters().cavitation != CavitationModel::kMassConserving,
               b.who() << ": the transient film needs the mass-conserving cavitation model");
  EMB_THROW_IF(!(std::isfinite(dt) && dt > 0.0),
               b.who() << ": expected a positive time step, got " << dt << " s");
  EMB_THROW_IF(previous.universal.size() != b.num_unknowns() ||
                   previous.content.size() != b.num_unknowns(),
               b.who() << ": expected a film state of " << b.num_unknowns() << " unknowns, got "
                       << previous.universal.size() << " and " << previous.content.size());
  u_ = previous.universal;
  StorageInputs st;
  st.term = StorageTerm::kBackwardEuler;
  st.previous_content = &previous.content;
  st.dt = dt;
  const FilmSolveInfo info = Solve(st, kin, loads, jacobian);
  if (info.ok() && next) *next = state();
  return info;
}

}  // namespace emb::tribology
