#include "libemb/mbs/linear/rotating_modes.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <Eigen/Eigenvalues>

#include "libemb/common/error.h"
#include "libemb/common/skew.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

Eigen::MatrixXd CalcFrameRotationRate(const System& system, const Eigen::VectorXd& q,
                                      const Eigen::VectorXd& v) {
  const StateLayout& L = system.layout();
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(L.nv(), L.nv());
  if (v.size() == 0) return W;
  const auto bodies = CalcBodyKinematics(system, q, v);
  for (int b = 1; b < system.num_bodies(); ++b) {
    if (L.is_ground(b)) continue;
    const int r = L.angular_velocity(b);
    W.block<3, 3>(r, r) = Skew(bodies[b].omega_B);
  }
  return W;
}

RotatingModes CalcRotatingModes(const System& system, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const LinearizedModel& model,
                                double fmax_hz, bool stationary_frame) {
  EMB_THROW_IF(HasQuasiStaticCoordinates(system),
               "rotating modes: the model has massless (quasi-static) elastic coordinates; "
               "expected every coordinate to carry mass (use the body's full basis)");
  Eigen::MatrixXd G = model.G;
  if (stationary_frame && v.size()) G -= model.M * CalcFrameRotationRate(system, q, v);
  const Eigen::MatrixXd& Z = model.Z;
  return CalcReducedRotatingModes(Z.transpose() * model.M * Z, Z.transpose() * G * Z,
                                  Z.transpose() * model.K * Z, Z, model.M, fmax_hz);
}

RotatingModes CalcReducedRotatingModes(const Eigen::MatrixXd& Mz, const Eigen::MatrixXd& Gz,
                                       const Eigen::MatrixXd& Kz, const Eigen::MatrixXd& Z,
                                       const Eigen::MatrixXd& M, double fmax_hz) {
  RotatingModes out;
  out.mass = M;
  const int n = static_cast<int>(Z.cols());
  out.num_free = n;
  const int nv = static_cast<int>(M.rows());
  out.frequencies_hz.resize(0);
  out.decay.resize(0);
  out.shapes.resize(nv, 0);
  if (n == 0) return out;
  const Eigen::LLT<Eigen::MatrixXd> llt(0.5 * (Mz + Mz.transpose()));
  if (llt.info() != Eigen::Success) EMB_THROW(NumericalError, "rotating modes: the reduced mass matrix is not positive definite");
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -llt.solve(Kz);
  A.bottomRightCorner(n, n) = -llt.solve(Gz);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(A, true);
  if (es.info() != Eigen::Success) EMB_THROW(NumericalError, "rotating modes: the eigen-solve of the first-order form failed");
  struct Found {
    double hz, decay;
    Eigen::Index column;
  };
  // Rigid-body motions (a free spin, a free drift) are zero eigenvalues, of a Jordan block
  // when a coordinate and its rate are both free: round-off moves them to
  // ~sqrt(eps |A|) * (their scale), far below kZeroFrequency sqrt(|A|), which in turn is far
  // below any vibration (|A| ~ omega_max^2: 1e-6 omega_max).
  constexpr double kZeroFrequency = 1e-6;
  const double zero = kZeroFrequency * std::sqrt(A.cwiseAbs().maxCoeff());
  std::vector<Found> found;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
    const std::complex<double> s = es.eigenvalues()[i];
    const double hz = s.imag() / (2 * std::numbers::pi);
    if (std::abs(s) <= zero) continue;
    if (s.imag() > 0.0 && (fmax_hz <= 0.0 || hz <= fmax_hz)) found.push_back({hz, -s.real(), i});
  }
  std::sort(found.begin(), found.end(), [](const Found& a, const Found& b) { return a.hz < b.hz; });
  const Eigen::MatrixXcd X = es.eigenvectors();
  const Eigen::MatrixXcd Mc = M.cast<std::complex<double>>();
  out.frequencies_hz.resize(static_cast<Eigen::Index>(found.size()));
  out.decay.resize(out.frequencies_hz.size());
  out.shapes.resize(nv, out.frequencies_hz.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    out.frequencies_hz[i] = found[k].hz;
    out.decay[i] = found[k].decay;
    // The lower half of x is y' = s y: the velocity phasor.
    Eigen::VectorXcd phi = Z.cast<std::complex<double>>() * X.col(found[k].column).tail(n);
    const double norm2 = (phi.adjoint() * Mc * phi)(0, 0).real();
    if (!(norm2 > 0.0)) EMB_THROW(NumericalError, "rotating modes: a mode without kinetic energy");
    out.shapes.col(i) = phi / std::sqrt(norm2);
  }
  return out;
}

}  // namespace emb::mbs
