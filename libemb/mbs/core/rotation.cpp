#include "libemb/mbs/core/rotation.h"

#include <cmath>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::mbs {

Matrix3d RotationFromQuaternion(const Vector4d& e_in) {
  const double n = e_in.norm();
  EMB_CHECK(n > 0.0);
  const Vector4d e = e_in / n;
  const double w = e[0], x = e[1], y = e[2], z = e[3];
  Matrix3d R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

Vector4d QuaternionFromRotation(const Matrix3d& R) {
  const Eigen::Quaterniond q(R);  // Shepperd-type branch selection inside Eigen
  Vector4d e(q.w(), q.x(), q.y(), q.z());
  if (e[0] < 0) e = -e;
  return e.normalized();
}

Eigen::Matrix<double, 4, 3> QuaternionRateMatrix(const Vector4d& e) {
  const double w = e[0], x = e[1], y = e[2], z = e[3];
  Eigen::Matrix<double, 4, 3> Q;
  Q << -x, -y, -z,  //
      w, -z, y,     //
      z, w, -x,     //
      -y, x, w;
  return Q;
}

Vector4d RotateQuaternion(const Vector4d& e, const Vector3d& delta_pi_B) {
  const double angle = delta_pi_B.norm();
  Eigen::Quaterniond dq = Eigen::Quaterniond::Identity();
  if (angle > 0.0) dq = Eigen::Quaterniond(Eigen::AngleAxisd(angle, delta_pi_B / angle));
  const Eigen::Quaterniond q(e[0], e[1], e[2], e[3]);
  const Eigen::Quaterniond r = (q.normalized() * dq).normalized();
  return {r.w(), r.x(), r.y(), r.z()};
}

Matrix3d RotationFromEuler313(double psi, double theta, double phi) {
  const double cs = std::cos(psi), ss = std::sin(psi);
  const double ct = std::cos(theta), st = std::sin(theta);
  const double cp = std::cos(phi), sp = std::sin(phi);
  // Seed eq. (1.20), row by row (its (2,1) entry reads S psi C phi + C psi C theta S phi).
  Matrix3d T;
  T << cs * cp - ss * ct * sp, -cs * sp - ss * ct * cp, ss * st,  //
      ss * cp + cs * ct * sp, -ss * sp + cs * ct * cp, -cs * st,  //
      st * sp, st * cp, ct;
  return T;
}

Vector3d Euler313FromRotation(const Matrix3d& R) {
  const double ct = std::clamp(R(2, 2), -1.0, 1.0);
  const double st = std::hypot(R(0, 2), R(1, 2));
  const double theta = std::atan2(st, ct);
  // Below this sin(theta) the psi/phi split is numerically meaningless (round-off of R).
  constexpr double kSingularSinTheta = 1e-12;
  if (st < kSingularSinTheta) {
    // theta = 0: R = Rz(psi + phi); theta = pi: R = Rz(psi) Rx(pi) Rz(phi) = .. psi - phi.
    return {std::atan2(R(1, 0), R(0, 0)), theta, 0.0};
  }
  const double psi = std::atan2(R(0, 2), -R(1, 2));
  const double phi = std::atan2(R(2, 0), R(2, 1));
  return {psi, theta, phi};
}

Vector3d RotationVectorFromRotation(const Matrix3d& R) {
  return RotationVectorFromQuaternion(QuaternionFromRotation(R));
}

Vector3d RotationVectorFromQuaternion(const Vector4d& e_in) {
  const Vector4d e = e_in[0] < 0.0 ? Vector4d(-e_in) : e_in;
  const Vector3d v = e.tail<3>();
  const double s = v.norm();
  if (s == 0.0) return Vector3d::Zero();
  return (2.0 * std::atan2(s, e[0]) / s) * v;
}

namespace {

// Below this angle beta and beta'/t come from their series: the closed forms cancel
// ~1/t^4 against each other, losing 5 digits at t = 0.25, where the truncated series
// (through t^6) is already accurate to ~1e-11 relative.
constexpr double kSeriesAngle = 0.25;

// beta(t) = 1/t^2 - cot(t/2)/(2t) = 1/12 + t^2/720 + t^4/30240 + t^6/1209600 + ...
double Beta(double t) {
  if (t < kSeriesAngle) {
    const double t2 = t * t;
    return 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 / 1209600.0));
  }
  return 1.0 / (t * t) - 1.0 / (2.0 * t * std::tan(0.5 * t));
}

// beta'(t)/t = -2/t^4 + cot(t/2)/(2 t^3) + 1/(4 t^2 sin^2(t/2))
//            = 1/360 + t^2/7560 + t^4/201600 + t^6/5987520 + ...
double BetaPrimeOverT(double t) {
  if (t < kSeriesAngle) {
    const double t2 = t * t;
    return 1.0 / 360.0 + t2 * (1.0 / 7560.0 + t2 * (1.0 / 201600.0 + t2 / 5987520.0));
  }
  const double s = std::sin(0.5 * t);
  return -2.0 / std::pow(t, 4) + 1.0 / (2.0 * t * t * t * std::tan(0.5 * t)) +
         1.0 / (4.0 * t * t * s * s);
}

}  // namespace

namespace {
// Below this angle the Rodrigues coefficients are evaluated by their series to t^6 (the
// closed forms lose digits to cancellation; the truncation error there is < 1e-16).
constexpr double kRodriguesSeriesAngle = 0.1;

// sin(t)/t, (1 - cos t)/t^2 and (t - sin t)/t^3.
Eigen::Vector3d RodriguesCoefficients(double t) {
  const double t2 = t * t;
  if (t < kRodriguesSeriesAngle)
    return {1.0 - t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0)),
            0.5 - t2 / 24.0 * (1.0 - t2 / 30.0 * (1.0 - t2 / 56.0)),
            1.0 / 6.0 - t2 / 120.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0))};
  return {std::sin(t) / t, (1.0 - std::cos(t)) / t2, (t - std::sin(t)) / (t2 * t)};
}
}  // namespace

namespace {
// a'(t)/t and b'(t)/t of a = (1 - cos t)/t^2 and b = (t - sin t)/t^3: the closed forms
// cancel ~1/t^2 of their terms, so below kRodriguesSeriesAngle the series (to t^6; the next
// term is ~1e-13 relative at t = 0.1) are used.
Eigen::Vector2d RodriguesDerivativesOverT(double t) {
  const double t2 = t * t;
  if (t < kRodriguesSeriesAngle)
    return {-1.0 / 12.0 + t2 * (1.0 / 180.0 + t2 * (-1.0 / 6720.0 + t2 / 453600.0)),
            -1.0 / 60.0 + t2 * (1.0 / 1260.0 + t2 * (-1.0 / 60480.0 + t2 / 4989600.0))};
  const double t4 = t2 * t2;
  return {(t * std::sin(t) - 2.0 + 2.0 * std::cos(t)) / t4,
          (1.0 - std::cos(t)) / t4 - 3.0 * (t - std::sin(t)) / (t4 * t)};
}
}  // namespace

Matrix3d LeftJacobianSO3ProductDerivative(const Vector3d& theta_in, const Vector3d& x,
                                          bool transpose) {
  // J_l(theta)^T = J_l(-theta): the transposed case is the plain one at -theta, times -1
  // for the chain rule.
  const Vector3d theta = transpose ? Vector3d(-theta_in) : theta_in;
  const double t = theta.norm();
  const Eigen::Vector3d c = RodriguesCoefficients(t);
  const Eigen::Vector2d d = RodriguesDerivativesOverT(t);
  const Vector3d tx = theta.cross(x);
  const Matrix3d dtt = theta.dot(x) * Matrix3d::Identity() + theta * x.transpose() -
                       2.0 * x * theta.transpose();
  const Matrix3d D = -c[1] * Skew(x) + d[0] * tx * theta.transpose() + c[2] * dtt +
                     d[1] * theta.cross(tx) * theta.transpose();
  return transpose ? Matrix3d(-D) : D;
}

Matrix3d RotationFromRotationVector(const Vector3d& theta) {
  const Eigen::Vector3d c = RodriguesCoefficients(theta.norm());
  const Matrix3d S = Skew(theta);
  return Matrix3d::Identity() + c[0] * S + c[1] * S * S;
}

Matrix3d LeftJacobianSO3(const Vector3d& theta) {
  const Eigen::Vector3d c = RodriguesCoefficients(theta.norm());
  const Matrix3d S = Skew(theta);
  return Matrix3d::Identity() + c[1] * S + c[2] * S * S;
}

Matrix3d InverseLeftJacobianSO3(const Vector3d& theta) {
  const Matrix3d S = Skew(theta);
  return Matrix3d::Identity() - 0.5 * S + Beta(theta.norm()) * S * S;
}

Matrix3d InverseLeftJacobianSO3ProductDerivative(const Vector3d& theta, const Vector3d& w,
                                                 bool transpose) {
  const double t = theta.norm();
  const Vector3d g = theta.cross(theta.cross(w));
  const Matrix3d dg = theta.dot(w) * Matrix3d::Identity() + theta * w.transpose() -
                      2.0 * w * theta.transpose();
  const double sign = transpose ? -1.0 : 1.0;
  return sign * 0.5 * Skew(w) + Beta(t) * dg + BetaPrimeOverT(t) * g * theta.transpose();
}

double WrapAngle(double a) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double r = std::remainder(a, kTwoPi);  // in [-pi, pi]
  if (r <= -std::numbers::pi) r += kTwoPi;
  return r;
}

}  // namespace emb::mbs
