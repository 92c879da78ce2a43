#include "libemb/engine/journal_bearing.h"

#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/mbs/forces/force_jacobian.h"
#include "libemb/mbs/forces/relative_motion.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

// Gauss-Legendre rule on the half circle u in [-pi/2, pi/2] (angle from the direction of
// the whirl-relative velocity). 64 points; the error grows as the film's pole
// (1 - eps cos = 0) nears the real axis: measured values in the header.
constexpr int kNodes = 64;
struct HalfCircleRule {
  std::array<double, kNodes> cos_u, sin_u, weight;
};

const HalfCircleRule& Rule() {
  static const HalfCircleRule rule = [] {
    HalfCircleRule r;
    // Legendre roots by Newton from Chebyshev guesses (three-term recurrence).
    for (int k = 0; k < kNodes; ++k) {
      double x = std::cos(std::numbers::pi * (k + 0.75) / (kNodes + 0.5));
      double dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = x;
        for (int n = 2; n <= kNodes; ++n) {
          const double p2 = ((2.0 * n - 1.0) * x * p1 - (n - 1.0) * p0) / n;
          p0 = p1;
          p1 = p2;
        }
        dp = kNodes * (x * p1 - p0) / (x * x - 1.0);
        const double dx = p1 / dp;
        x -= dx;
        if (std::abs(dx) < 1e-16) break;
      }
      const double half = std::numbers::pi / 2;
      const double u = half * x;  // [-1, 1] -> [-pi/2, pi/2]
      r.cos_u[k] = std::cos(u);
      r.sin_u[k] = std::sin(u);
      r.weight[k] = half * 2.0 / ((1.0 - x * x) * dp * dp);
    }
    return r;
  }();
  return rule;
}

// z x a in the plane.
Eigen::Vector2d Perp(const Eigen::Vector2d& a) { return {-a.y(), a.x()}; }

}  // namespace

JournalBearing::JournalBearing(std::string name, int marker_i, int marker_j,
                               const JournalBearingParameters& p)
    : ForceElement(std::move(name)), i_(marker_i), j_(marker_j), p_(p) {
  const std::string who = "journal bearing '" + this->name() + "'";
  auto positive = [&](double v, const char* key) {
    EMB_THROW_IF(!(std::isfinite(v) && v > 0.0),
                 who << ": expected a positive " << key << ", got " << v);
  };
  positive(p.radius, "radius");
  positive(p.length, "length");
  positive(p.clearance, "clearance");
  positive(p.viscosity, "viscosity");
  EMB_THROW_IF(p.clearance >= p.radius, who << ": expected a clearance smaller than the radius, got c = "
                                           << p.clearance << " m, R = " << p.radius << " m");
  // Short-bearing (Ocvirk) theory drops the circumferential pressure flow; it over-predicts
  // the load of bearings longer than their diameter, which are refused.
  constexpr double kMaxLengthOverDiameter = 1.0;
  EMB_THROW_IF(p.length > kMaxLengthOverDiameter * 2.0 * p.radius,
               who << ": the short-bearing model needs L/D <= " << kMaxLengthOverDiameter
                   << ", got L/D = " << p.length / (2.0 * p.radius));
}

std::string JournalBearing::TouchMessage(const Eigen::Vector2d& e, double t) const {
  std::ostringstream o;
  o << "journal bearing '" << name() << "': the journal touches the shell at t = " << t
    << " s: eccentricity ratio " << e.norm() / p_.clearance << " >= 1 (clearance "
    << p_.clearance << " m)";
  return o.str();
}

void JournalBearing::CheckEccentricity(const Eigen::Vector2d& e, double t) const {
  if (!Inside(e)) throw NumericalError(TouchMessage(e, t));
}

bool JournalBearing::Inside(const ForceContext& ctx, const RelativeMotion& rel) const {
  if (Inside(rel.x.head<2>())) return true;
  ctx.Fail(TouchMessage(rel.x.head<2>(), ctx.t));
  return false;
}

Eigen::Vector2d JournalBearing::FilmForce(const Eigen::Vector2d& e, const Eigen::Vector2d& u,
                                          Eigen::Matrix2d* dF_de, Eigen::Matrix2d* dF_du) const {
  // Nodes n_k = cos u_k a + sin u_k b with a = u/|u|, b = z x a (a = x for u = 0: then F = 0
  // and the derivatives are those along x, a one-sided choice).
  const HalfCircleRule& r = Rule();
  const double un = u.norm();
  const Eigen::Vector2d a = un > 0.0 ? Eigen::Vector2d(u / un) : Eigen::Vector2d::UnitX();
  const Eigen::Vector2d b = Perp(a);
  const double scale = -p_.viscosity * p_.radius * std::pow(p_.length, 3);
  Eigen::Vector2d F = Eigen::Vector2d::Zero();
  Eigen::Matrix2d Fe = Eigen::Matrix2d::Zero(), Fu = Eigen::Matrix2d::Zero();
  for (int k = 0; k < kNodes; ++k) {
    const Eigen::Vector2d n = r.cos_u[k] * a + r.sin_u[k] * b;
    const Eigen::Vector2d tn = Perp(n);  // dn/dpsi
    const double h = p_.clearance - n.dot(e);
    const double c = r.weight[k] * r.cos_u[k];  // (n . u) = |u| cos u_k
    const double h3 = 1.0 / (h * h * h);
    F += c * un * h3 * n;
    if (dF_de) Fe += c * 3.0 * un * h3 / h * n * n.transpose();
    // d(|u| n / h^3)/du = [n a^T + t b^T + 3 (e . t)/h n b^T] / h^3 (dn/du = t b^T / |u|).
    if (dF_du)
      Fu += c * h3 * (n * a.transpose() + tn * b.transpose() + 3.0 * e.dot(tn) / h * n * b.transpose());
  }
  if (dF_de) *dF_de = scale * Fe;
  if (dF_du) *dF_du = scale * Fu;
  return scale * F;
}

JournalBearing::FilmLoad JournalBearing::CalcFilmLoad(const Eigen::Vector2d& e,
                                                      const Eigen::Vector2d& e_dot, double w,
                                                      double t) const {
  CheckEccentricity(e, t);
  const Eigen::Vector2d u = e_dot - 0.5 * w * Perp(e);
  FilmLoad load;
  load.force = FilmForce(e, u, nullptr, nullptr);
  const double eps2 = e.squaredNorm() / (p_.clearance * p_.clearance);
  const double petroff = 2.0 * std::numbers::pi * p_.viscosity * std::pow(p_.radius, 3) *
                         p_.length / p_.clearance;
  load.torque = -0.5 * (e.x() * load.force.y() - e.y() * load.force.x()) -
                petroff * w / std::sqrt(1.0 - eps2);
  return load;
}

JournalBearing::FilmLoad JournalBearing::CalcFilmLoad(const RelativeMotion& rel, double t) const {
  return CalcFilmLoad(rel.x.head<2>(), rel.x_dot.head<2>(), rel.w.z(), t);
}

void JournalBearing::DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const {
  const MarkerPair markers(ctx, i_, j_);
  const MarkerKinematics& I = markers.I;
  const MarkerKinematics& J = markers.J;
  const RelativeMotion rel = CalcRelativeMotion(I, J);
  if (!Inside(ctx, rel)) return;  // reported through the context
  const FilmLoad load = CalcFilmLoad(rel, ctx.t);
  const Eigen::Vector3d F_W = J.R_WM * Eigen::Vector3d(load.force.x(), load.force.y(), 0.0);
  const Eigen::Vector3d T_W = J.R_WM.col(2) * load.torque;
  AddWrenchPair(ctx.system->layout(), I, J, F_W, T_W, f);
}

bool JournalBearing::DoCalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* out) const {
  const RelativeMotion rel = CalcRelativeMotion(MarkerPair(ctx, i_, j_));
  if (!Inside(ctx, rel)) return false;
  const FilmLoad load = CalcFilmLoad(rel, ctx.t);
  *out << load.force.x(), load.force.y(), 0.0, 0.0, 0.0, load.torque;
  return true;
}

void JournalBearing::DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const {
  using Eigen::Matrix2d;
  using Eigen::Matrix3d;
  using MatrixXd = SlotMatrix;  // fixed capacity: no allocation
  using Eigen::Vector2d;
  using Eigen::Vector3d;
  const MarkerPair markers(ctx, i_, j_);
  const MarkerKinematics& I = markers.I;
  const MarkerKinematics& J = markers.J;
  const RelativeMotion rel = CalcRelativeMotion(markers);
  const Vector2d e = rel.x.head<2>(), e_dot = rel.x_dot.head<2>();
  const double w = rel.w.z();
  if (!Inside(ctx, rel)) return;  // reported through the context
  const auto [dI, dJ] = DifferentiateMarkerPair(markers);
  const Matrix3d R_WJ = J.R_WM;

  // e = (x, y of I in J), e' and w = z . (relative angular velocity in J): relative_motion.h.
  const RelativeMotionDerivatives dr = DifferentiateRelativeMotion(rel, I, J, dI, dJ);
  const MatrixXd& de_x = dr.x_x;
  const MatrixXd& dedot_x = dr.x_dot_x;
  const MatrixXd& dedot_v = dr.x_dot_v;
  const MatrixXd dw_x = dr.w_x.bottomRows<1>();
  const MatrixXd dw_v = dr.w_v.bottomRows<1>();

  // u = e' - (w/2) z x e = e' + (w/2) (e_y, -e_x).
  const Vector2d u = e_dot - 0.5 * w * Perp(e);
  Matrix2d minus_perp;  // d(-z x e)/de
  minus_perp << 0, 1, -1, 0;
  const Vector2d half_minus_perp_e = 0.5 * minus_perp * e;
  const MatrixXd de2_x = de_x.topRows<2>();
  const MatrixXd du_x = dedot_x.topRows<2>() + half_minus_perp_e * dw_x +
                        0.5 * w * minus_perp * de2_x;
  const MatrixXd du_v = dedot_v.topRows<2>() + half_minus_perp_e * dw_v;

  Matrix2d Fe, Fu;
  const Vector2d F2 = FilmForce(e, u, &Fe, &Fu);
  const MatrixXd dF2_x = Fe * de2_x + Fu * du_x;
  const MatrixXd dF2_v = Fu * du_v;

  // T = -(e_x F_y - e_y F_x)/2 - k w / sqrt(1 - eps^2), k = 2 pi mu R^3 L / c.
  const double c2 = p_.clearance * p_.clearance;
  const double s = 1.0 - e.squaredNorm() / c2;
  const double k = 2.0 * std::numbers::pi * p_.viscosity * std::pow(p_.radius, 3) * p_.length /
                   p_.clearance;
  const double torque = -0.5 * (e.x() * F2.y() - e.y() * F2.x()) - k * w / std::sqrt(s);
  const Eigen::RowVector2d dT_de(-0.5 * F2.y() - k * w * std::pow(s, -1.5) * e.x() / c2,
                                 0.5 * F2.x() - k * w * std::pow(s, -1.5) * e.y() / c2);
  const Eigen::RowVector2d dT_dF(0.5 * e.y(), -0.5 * e.x());
  const MatrixXd dtorque_x = dT_de * de2_x + dT_dF * dF2_x - (k / std::sqrt(s)) * dw_x;
  const MatrixXd dtorque_v = dT_dF * dF2_v - (k / std::sqrt(s)) * dw_v;

  // F = R_WJ [F2; 0], T = z_J torque (d(R_WJ a) = R_WJ da - [R_WJ a x] dphi_J).
  const Vector3d F = R_WJ.leftCols<2>() * F2;
  const Vector3d T = R_WJ.col(2) * torque;
  const MatrixXd dF_x = R_WJ.leftCols<2>() * dF2_x - Skew(F) * dJ.rotation_x;
  const MatrixXd dF_v = R_WJ.leftCols<2>() * dF2_v;
  const MatrixXd dT_x = R_WJ.col(2) * dtorque_x - Skew(T) * dJ.rotation_x;
  const MatrixXd dT_v = R_WJ.col(2) * dtorque_v;
  ScatterWrenchPairJacobian(I, J, dI, dJ, F, T, dF_x, dT_x, dF_v, dT_v, sink);
}

std::vector<ElementOutput> JournalBearing::DoOutputs() const {
  return {{"h_min", "m"}, {"eccentricity_ratio", "-"}, {"friction_power", "W"}};
}

bool JournalBearing::DoCalcOutputs(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> out) const {
  const RelativeMotion rel = CalcRelativeMotion(MarkerPair(ctx, i_, j_));
  if (!Inside(ctx, rel)) return false;
  const double e = rel.x.head<2>().norm();
  out << p_.clearance - e, e / p_.clearance, DoCalcDissipatedPower(ctx);
  return true;
}

double JournalBearing::DoCalcDissipatedPower(const ForceContext& ctx) const {
  const RelativeMotion rel = CalcRelativeMotion(MarkerPair(ctx, i_, j_));
  if (!Inside(ctx, rel)) return 0.0;
  const FilmLoad load = CalcFilmLoad(rel, ctx.t);
  return -(load.force.dot(rel.x_dot.head<2>()) + load.torque * rel.w.z());
}

}  // namespace emb::mbs
