#include "libemb/mbs/constraints/primitive.h"

#include <cmath>

#include "libemb/common/skew.h"

namespace emb::mbs {
namespace {

using Eigen::Vector3d;
using Row6 = Eigen::Matrix<double, 1, 6>;

// Gradient of c . p_WM with respect to [dp_WB, dpi_B] of the marker's body.
Row6 PointGradient(const MarkerKinematics& M, const Vector3d& c_W) {
  Row6 g;
  g.head<3>() = c_W.transpose();
  g.tail<3>() = M.s_B.cross(M.R_WB.transpose() * c_W).transpose();
  return g;
}

// Gradient of c . (R_WB a_B) with respect to dpi_B.
Eigen::Matrix<double, 1, 3> AxisGradient(const MarkerKinematics& M, const Vector3d& a_B,
                                         const Vector3d& c_W) {
  return a_B.cross(M.R_WB.transpose() * c_W).transpose();
}

// w x (w x s): the centripetal part of a point's acceleration.
Vector3d Centripetal(const Vector3d& w, const Vector3d& s) { return w.cross(w.cross(s)); }

KernelEval AxisDot(const MarkerKinematics& I, int axis_i, const MarkerKinematics& J, int axis_j) {
  KernelEval e;
  const Vector3d a = I.R_WM.col(axis_i), b = J.R_WM.col(axis_j);
  const Vector3d a_B = I.R_BM.col(axis_i), b_B = J.R_BM.col(axis_j);
  e.value = a.dot(b);
  e.d_i.tail<3>() = AxisGradient(I, a_B, b);
  e.d_j.tail<3>() = AxisGradient(J, b_B, a);
  const Vector3d wa = I.omega_W.cross(a), wb = J.omega_W.cross(b);
  e.rate = wa.dot(b) + a.dot(wb);
  e.quadratic =
      Centripetal(I.omega_W, a).dot(b) + 2.0 * wa.dot(wb) + a.dot(Centripetal(J.omega_W, b));
  return e;
}

}  // namespace

KernelEval EvalKernel(const KernelSpec& spec, const MarkerKinematics& I,
                      const MarkerKinematics& J) {
  KernelEval e;
  const Vector3d d = I.p_WM - J.p_WM;
  const Vector3d d_dot = I.v_WM - J.v_WM;
  const Vector3d centripetal = Centripetal(I.omega_W, I.s_W) - Centripetal(J.omega_W, J.s_W);
  switch (spec.kind) {
    case KernelKind::kPointComponent: {
      const Vector3d ek = Vector3d::Unit(spec.axis_i);
      e.value = d[spec.axis_i];
      e.d_i = PointGradient(I, ek);
      e.d_j = -PointGradient(J, ek);
      e.rate = d_dot[spec.axis_i];
      e.quadratic = centripetal[spec.axis_i];
      return e;
    }
    case KernelKind::kPointOnAxis: {
      const Vector3d a = J.R_WM.col(spec.axis_j);
      const Vector3d a_B = J.R_BM.col(spec.axis_j);
      e.value = d.dot(a);
      e.d_i = PointGradient(I, a);
      e.d_j = -PointGradient(J, a);
      e.d_j.tail<3>() += AxisGradient(J, a_B, d);
      const Vector3d wa = J.omega_W.cross(a);
      e.rate = d_dot.dot(a) + d.dot(wa);
      e.quadratic = centripetal.dot(a) + 2.0 * d_dot.dot(wa) + d.dot(Centripetal(J.omega_W, a));
      return e;
    }
    case KernelKind::kAxisDot:
      return AxisDot(I, spec.axis_i, J, spec.axis_j);
    case KernelKind::kAngle: {
      const KernelEval s = AxisDot(I, 0, J, 1);
      const KernelEval c = AxisDot(I, 0, J, 0);
      const double rho = c.value * c.value + s.value * s.value;
      e.value = std::atan2(s.value, c.value);
      e.d_i = (c.value * s.d_i - s.value * c.d_i) / rho;
      e.d_j = (c.value * s.d_j - s.value * c.d_j) / rho;
      const double num_rate = c.value * s.rate - s.value * c.rate;
      const double rho_rate = 2.0 * (c.value * c.rate + s.value * s.rate);
      e.rate = num_rate / rho;
      e.quadratic =
          (c.value * s.quadratic - s.value * c.quadratic) / rho - num_rate * rho_rate / (rho * rho);
      return e;
    }
  }
  return e;
}

}  // namespace emb::mbs

namespace emb::mbs {
namespace {

using Mat12 = Eigen::Matrix<double, 12, 12>;
using Eigen::Matrix3d;
using Eigen::Vector3d;


// Block offsets in the 12-vector [dp_i, dpi_i, dp_j, dpi_j].
constexpr int kPi = 0, kRi = 3, kPj = 6, kRj = 9;

Mat12 AxisDotHessian(const MarkerKinematics& I, int axis_i, const MarkerKinematics& J, int axis_j) {
  Mat12 K = Mat12::Zero();
  const Vector3d a = I.R_WM.col(axis_i), b = J.R_WM.col(axis_j);
  const Vector3d a_B = I.R_BM.col(axis_i), b_B = J.R_BM.col(axis_j);
  K.block<3, 3>(kRi, kRi) = Skew(a_B) * Skew(I.R_WB.transpose() * b);
  K.block<3, 3>(kRi, kRj) = -Skew(a_B) * I.R_WB.transpose() * J.R_WB * Skew(b_B);
  K.block<3, 3>(kRj, kRj) = Skew(b_B) * Skew(J.R_WB.transpose() * a);
  K.block<3, 3>(kRj, kRi) = -Skew(b_B) * J.R_WB.transpose() * I.R_WB * Skew(a_B);
  return K;
}

Eigen::Matrix<double, 1, 12> Row(const KernelEval& e) {
  Eigen::Matrix<double, 1, 12> g;
  g << e.d_i, e.d_j;
  return g;
}

}  // namespace

Eigen::Matrix<double, 12, 12> EvalKernelHessian(const KernelSpec& spec, const MarkerKinematics& I,
                                                const MarkerKinematics& J) {
  Mat12 K = Mat12::Zero();
  switch (spec.kind) {
    case KernelKind::kPointComponent: {
      const Vector3d ek = Vector3d::Unit(spec.axis_i);
      K.block<3, 3>(kRi, kRi) = Skew(I.s_B) * Skew(I.R_WB.transpose() * ek);
      K.block<3, 3>(kRj, kRj) = -Skew(J.s_B) * Skew(J.R_WB.transpose() * ek);
      return K;
    }
    case KernelKind::kPointOnAxis: {
      const Vector3d a = J.R_WM.col(spec.axis_j);
      const Vector3d a_B = J.R_BM.col(spec.axis_j);
      const Vector3d d = I.p_WM - J.p_WM;
      const Matrix3d Rj = J.R_WB, Ri = I.R_WB;
      const Matrix3d da_dpij = -Rj * Skew(a_B);  // d a / d pi_j
      // G_i = [a; s_i x R_i^T a]
      K.block<3, 3>(kPi, kRj) = da_dpij;
      K.block<3, 3>(kRi, kRi) = Skew(I.s_B) * Skew(Ri.transpose() * a);
      K.block<3, 3>(kRi, kRj) = Skew(I.s_B) * Ri.transpose() * da_dpij;
      // G_j = [-a; -(s_j x a_B) + a_B x (R_j^T d)]
      K.block<3, 3>(kPj, kRj) = -da_dpij;
      const Matrix3d A = Skew(a_B);
      K.block<3, 3>(kRj, kPi) = A * Rj.transpose();
      K.block<3, 3>(kRj, kRi) = -A * Rj.transpose() * Ri * Skew(I.s_B);
      K.block<3, 3>(kRj, kPj) = -A * Rj.transpose();
      K.block<3, 3>(kRj, kRj) = A * (Skew(J.s_B) + Skew(Rj.transpose() * d));
      return K;
    }
    case KernelKind::kAxisDot:
      return AxisDotHessian(I, spec.axis_i, J, spec.axis_j);
    case KernelKind::kAngle: {
      const KernelEval s = EvalKernel({KernelKind::kAxisDot, 0, 1}, I, J);
      const KernelEval c = EvalKernel({KernelKind::kAxisDot, 0, 0}, I, J);
      const Mat12 Ks = AxisDotHessian(I, 0, J, 1), Kc = AxisDotHessian(I, 0, J, 0);
      const auto Gs = Row(s), Gc = Row(c);
      const double rho = c.value * c.value + s.value * s.value;
      const auto Gphi = (c.value * Gs - s.value * Gc);
      K = (c.value * Ks - s.value * Kc) / rho + (Gs.transpose() * Gc - Gc.transpose() * Gs) / rho -
          Gphi.transpose() * (2.0 * (c.value * Gc + s.value * Gs)) / (rho * rho);
      return K;
    }
  }
  return K;
}

}  // namespace emb::mbs
