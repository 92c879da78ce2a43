#include "libemb/mbs/linear/cycle_average.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "libemb/common/error.h"
#include "libemb/mbs/linear/mode_tracking.h"
#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

// A row of Z joins the common coordinates if the part of it outside the span of the rows
// already chosen is at least this fraction of its norm (scale-free: rows are m/s, rad/s or
// modal rates). Rows of bodies that follow the rotor are combinations of the rotor's rows
// to round-off; a genuinely new direction is O(1).
constexpr double kIndependentRow = 1e-6;
// At every angle the common rows of Z, each scaled to unit norm, must keep a smallest
// singular value above this: below it a dependent body's motion (e.g. a rod's swing, zero
// at mid-stroke) would be standing in for an independent coordinate.
constexpr double kCommonRowsConditioning = 1e-8;
// The march along the motion: rotor steps of at most this angle [rad] (5 degrees: the
// first-order predictor is then within ~r h^2 / 2 ~ 1e-4 m of the assembled dependent
// bodies, where Newton converges in a few iterations).
constexpr double kMaxMarchStep = 5.0 * std::numbers::pi / 180.0;
constexpr int kMarchNewtonIterations = 25;
// A frozen mode at an angle is the averaged mode's partner above this MAC (mode_tracking.h).
constexpr double kSpreadMinMac = 0.5;

// Rows of Z independent at the start: the rotor's velocity rows first, then the rest in order.
std::vector<int> SelectCommonRows(const System& sys, const Eigen::MatrixXd& Z, int rotor) {
  const StateLayout& L = sys.layout();
  std::vector<int> order;
  auto add_body = [&](int b) {
    for (int i = 0; i < StateLayout::kVPerBody; ++i) order.push_back(L.velocity(b) + i);
    for (int i = 0; i < L.num_elastic(b); ++i) order.push_back(L.elastic_v(b) + i);
  };
  add_body(rotor);
  for (int b = 1; b < sys.num_bodies(); ++b)
    if (b != rotor) add_body(b);
  const Eigen::Index n = Z.cols();
  std::vector<int> rows;
  Eigen::MatrixXd basis(n, 0);  // orthonormal columns spanning the chosen rows
  for (int r : order) {
    if (static_cast<Eigen::Index>(rows.size()) == n) break;
    const Eigen::VectorXd z = Z.row(r).transpose();
    const double norm = z.norm();
    if (!(norm > 0.0)) continue;
    Eigen::VectorXd rest = z - basis * (basis.transpose() * z);
    rest -= basis * (basis.transpose() * rest);  // re-orthogonalise
    if (rest.norm() <= kIndependentRow * norm) continue;
    basis.conservativeResize(n, basis.cols() + 1);
    basis.col(basis.cols() - 1) = rest.normalized();
    rows.push_back(r);
  }
  if (static_cast<Eigen::Index>(rows.size()) != n)
    EMB_THROW(NumericalError, "cycle average: only " << rows.size() << " of " << n
                                                     << " independent velocity rows found");
  return rows;
}

Eigen::MatrixXd Rows(const Eigen::MatrixXd& A, const std::vector<int>& rows) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows.size()), A.cols());
  for (std::size_t i = 0; i < rows.size(); ++i)
    out.row(static_cast<Eigen::Index>(i)) = A.row(rows[i]);
  return out;
}

// T = Z (Z_S)^-1: v = T y with y = v_S. @throws NumericalError if Z_S is near singular.
Eigen::MatrixXd CommonTransform(const Eigen::MatrixXd& Z, const std::vector<int>& rows, double t) {
  Eigen::MatrixXd ZS = Rows(Z, rows);
  Eigen::MatrixXd scaled = ZS;
  for (Eigen::Index i = 0; i < scaled.rows(); ++i) scaled.row(i).normalize();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled);
  const double smin = svd.singularValues().size() ? svd.singularValues().minCoeff() : 1.0;
  if (!(smin > kCommonRowsConditioning))
    EMB_THROW(NumericalError,
              "cycle average: the coordinates chosen at the start angle are "
              "dependent at t = "
                  << t << " s (smallest singular value " << smin
                  << "); use the frozen linearisation");
  return Z * ZS.inverse();
}

// x with the entries `dependent` set to the least-squares solution d of C_D d = rhs
// (C_D: the columns `dependent` of C), the others kept.
void SolveDependent(const Eigen::MatrixXd& C, const std::vector<int>& dependent,
                    const Eigen::VectorXd& rhs, Eigen::VectorXd* x) {
  Eigen::MatrixXd CD(C.rows(), static_cast<Eigen::Index>(dependent.size()));
  for (std::size_t j = 0; j < dependent.size(); ++j)
    CD.col(static_cast<Eigen::Index>(j)) = C.col(dependent[j]);
  const Eigen::VectorXd d = CD.completeOrthogonalDecomposition().solve(rhs);
  for (std::size_t j = 0; j < dependent.size(); ++j)
    (*x)[dependent[j]] = d[static_cast<Eigen::Index>(j)];
}

// The dependent velocities for independent rows v_S (others solved from C v + Phi_t = 0).
Eigen::VectorXd Velocities(const ConstraintEval& c, const std::vector<int>& common,
                           const std::vector<int>& dependent, const Eigen::VectorXd& vS, int nv) {
  const Eigen::MatrixXd C(c.jacobian);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(nv);
  for (std::size_t i = 0; i < common.size(); ++i) v[common[i]] = vS[static_cast<Eigen::Index>(i)];
  SolveDependent(C, dependent, -(C * v + c.phi_t), &v);
  return v;
}

// Advances (q, t) along the steady motion with the common velocities vS held: a predictor
// along v, then Newton on the dependent coordinates alone (the rotor stays where its constant
// spin puts it).
void March(const System& sys, const std::vector<int>& common, const std::vector<int>& dependent,
           const Eigen::VectorXd& vS, double spin, double t_to, Eigen::VectorXd* q, double* t,
           ConstraintWorkspace* ws) {
  const int nv = sys.layout().nv();
  const double span = t_to - *t;
  const int steps = std::max(0, static_cast<int>(std::ceil(std::abs(span) * spin / kMaxMarchStep)));
  const Eigen::VectorXd no_v;
  for (int s = 0; s < steps; ++s) {
    const double h = span / steps;
    ConstraintEval c = CalcConstraints(sys, CalcBodyKinematics(sys, *q, no_v), *t, ws);
    *q = ApplyDisplacement(sys, *q, h * Velocities(c, common, dependent, vS, nv));
    *t += h;
    double residual = std::numeric_limits<double>::infinity();
    for (int it = 0; it < kMarchNewtonIterations; ++it) {
      c = CalcConstraints(sys, CalcBodyKinematics(sys, *q, no_v), *t, ws);
      residual = c.phi.size() ? c.phi.cwiseAbs().maxCoeff() : 0.0;
      if (residual <= AssemblyOptions{}.tolerance) break;
      Eigen::VectorXd dx = Eigen::VectorXd::Zero(nv);
      SolveDependent(Eigen::MatrixXd(c.jacobian), dependent, -c.phi, &dx);
      *q = ApplyDisplacement(sys, *q, dx);
    }
    if (!(residual <= AssemblyOptions{}.tolerance))
      EMB_THROW(NumericalError,
                "cycle average: the bodies do not re-assemble about the rotor at t = "
                    << *t << " s (residual " << residual << ")");
  }
}

struct Reduced {
  Eigen::MatrixXd M, G, K;            // n x n in y (frozen: T' = 0)
  Eigen::MatrixXd T, M_full, G_full;  // v = T y; M, G - M W (nv x nv)
};

// The periodic spectral differentiation matrix on N equally spaced samples of one period
// (d/dtheta, theta in [0, 2 pi)): exact for the harmonics below N / 2 (Trefethen, Spectral
// Methods in MATLAB, ch. 3): D_kj = (-1)^(k-j) / 2 cot((k - j) pi / N) for even N, csc for
// odd N, 0 on the diagonal.
Eigen::MatrixXd SpectralDerivative(int N) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(N, N);
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < N; ++j) {
      if (k == j) continue;
      const double x = (k - j) * std::numbers::pi / N;
      const double sign = (k - j) % 2 == 0 ? 1.0 : -1.0;
      D(k, j) = 0.5 * sign * (N % 2 == 0 ? 1.0 / std::tan(x) : 1.0 / std::sin(x));
    }
  return D;
}

Reduced ReducedAt(const PreparedRun& run, double t, const std::vector<int>& common,
                  bool stationary_frame) {
  const System& sys = run.system;
  ConstraintWorkspace ws(sys);
  const AccelerationSolution acc = SolveAccelerations(sys, run.q0, run.v0, t, &ws);
  const LinearizedModel lin =
      CalcLinearizedModel(sys, run.q0, run.v0, t, acc.lambda, &ws, acc.vdot);
  const Eigen::MatrixXd T = CommonTransform(lin.Z, common, t);
  Eigen::MatrixXd G = lin.G;
  if (stationary_frame) G -= lin.M * CalcFrameRotationRate(sys, run.q0, run.v0);
  return {T.transpose() * lin.M * T, T.transpose() * G * T, T.transpose() * lin.K * T, T, lin.M, G};
}

}  // namespace

const char* Name(Linearisation l) {
  return l == Linearisation::kFrozen ? "frozen" : "cycle-average";
}

Linearisation ParseLinearisation(const std::string& name) {
  if (name == "frozen") return Linearisation::kFrozen;
  if (name == "cycle-average") return Linearisation::kCycleAverage;
  EMB_THROW(InputError,
            "linearisation: expected 'frozen' or 'cycle-average', got '" << name << "'");
}

CycleAveragedModes CalcCycleAveragedModes(const System& system, AnalysisSettings settings,
                                          const PreparedRun& start, int rotor, int num_angles,
                                          double pool_hz, bool stationary_frame) {
  EMB_THROW_IF(num_angles < 1, "cycle average: expected at least 1 angle, got " << num_angles);
  const System& sys = start.system;
  const double t0 = settings.t_start;
  const double spin = CalcBodyKinematics(sys, start.q0, start.v0)[rotor].omega_W.norm();
  EMB_THROW_IF(!(spin > 0.0), "cycle average: body '" << sys.body(rotor).name << "' does not spin");
  CycleAveragedModes out;
  out.num_angles = num_angles;
  out.period_s = 2 * std::numbers::pi / spin;
  {
    ConstraintWorkspace ws(sys);
    const AccelerationSolution acc = SolveAccelerations(sys, start.q0, start.v0, t0, &ws);
    out.coordinates = SelectCommonRows(
        sys, CalcLinearizedModel(sys, start.q0, start.v0, t0, acc.lambda, &ws, acc.vdot).Z, rotor);
  }
  const std::vector<int>& common = out.coordinates;
  std::vector<int> dependent;
  for (int r = 0; r < sys.layout().nv(); ++r)
    if (std::find(common.begin(), common.end(), r) == common.end()) dependent.push_back(r);
  const Eigen::VectorXd vS = Rows(start.v0, common).col(0);
  const Reduced ref = ReducedAt(start, t0, common, stationary_frame);

  const Eigen::Index n = static_cast<Eigen::Index>(common.size());
  Reduced mean{Eigen::MatrixXd::Zero(n, n),
               Eigen::MatrixXd::Zero(n, n),
               Eigen::MatrixXd::Zero(n, n),
               {},
               {},
               {}};
  std::vector<Reduced> at;
  // March backwards from the start to the negative angles, forwards to the others.
  Eigen::VectorXd q_back = start.q0, q_fwd = start.q0;
  double t_back = t0, t_fwd = t0;
  ConstraintWorkspace ws_back(sys), ws_fwd(sys);
  std::vector<double> times;
  for (int k = 0; k < num_angles; ++k)
    times.push_back(t0 + ((k + 0.5) / num_angles - 0.5) * out.period_s);
  std::vector<Eigen::VectorXd> states(times.size());
  for (int k = num_angles - 1; k >= 0; --k)
    if (times[k] < t0) {
      March(sys, common, dependent, vS, spin, times[k], &q_back, &t_back, &ws_back);
      states[k] = q_back;
    }
  for (int k = 0; k < num_angles; ++k)
    if (times[k] >= t0) {
      March(sys, common, dependent, vS, spin, times[k], &q_fwd, &t_fwd, &ws_fwd);
      states[k] = q_fwd;
    }
  for (int k = 0; k < num_angles; ++k) {
    ConstraintWorkspace ws(sys);
    const ConstraintEval c =
        CalcConstraints(sys, CalcBodyKinematics(sys, states[k], Eigen::VectorXd()), times[k], &ws);
    const Eigen::VectorXd v = Velocities(c, common, dependent, vS, sys.layout().nv());
    AnalysisSettings s = settings;
    s.t_start = times[k];
    s.t_end = std::max(settings.t_end, times[k]);
    const PreparedRun run = PrepareRun(system.WithInitialState(states[k], v), s);
    ThrowIfNotReady(run, "cycle average, angle " + std::to_string(k) + " of " +
                             std::to_string(num_angles));
    at.push_back(ReducedAt(run, times[k], common, stationary_frame));
  }
  // The rate of the coordinate map along the motion, T' = Omega dT/dtheta (spectral), and
  // its terms: with dx = T y, dv = T y' + T' y, the Galerkin projection T^T of
  // M dv' + G dv + K dx = 0 is
  //   T^T M T y'' + T^T (G T + 2 M T') y' + T^T (K T + M T'' + G T') y = 0,
  // whose frozen part (T' = 0) is each angle's model; the T' terms are periodic with a
  // non-zero mean (<T^T M T''> = -<T'^T M T'>: the reciprocating masses' inertia forces).
  const Eigen::MatrixXd D = (2 * std::numbers::pi / out.period_s) * SpectralDerivative(num_angles);
  for (int k = 0; k < num_angles; ++k) {
    Eigen::MatrixXd dT = Eigen::MatrixXd::Zero(at[k].T.rows(), n), ddT = dT;
    for (int j = 0; j < num_angles; ++j) {
      if (D(k, j) != 0.0) dT += D(k, j) * at[j].T;
      const double d2 = D.row(k).dot(D.col(j));
      if (d2 != 0.0) ddT += d2 * at[j].T;
    }
    const Eigen::MatrixXd TtM = at[k].T.transpose() * at[k].M_full;
    mean.M += at[k].M / num_angles;
    mean.G += (at[k].G + 2 * TtM * dT) / num_angles;
    mean.K += (at[k].K + TtM * ddT + at[k].T.transpose() * at[k].G_full * dT) / num_angles;
  }
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  out.modes = CalcReducedRotatingModes(mean.M, mean.G, mean.K, ref.T, ref.M_full, pool_hz);
  // The spread: each averaged mode's partner among the frozen modes of every angle, in y.
  const RotatingModes avg_y = CalcReducedRotatingModes(mean.M, mean.G, mean.K, I, mean.M, pool_hz);
  const Eigen::Index nm = avg_y.frequencies_hz.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.hz_min = Eigen::VectorXd::Constant(nm, nan);
  out.hz_max = Eigen::VectorXd::Constant(nm, nan);
  for (const Reduced& r : at) {
    const RotatingModes frozen = CalcReducedRotatingModes(r.M, r.G, r.K, I, mean.M, 2 * pool_hz);
    if (frozen.frequencies_hz.size() == 0 || nm == 0) continue;
    const std::vector<int> match =
        MatchModes(CalcMac(avg_y.shapes, frozen.shapes, mean.M), kSpreadMinMac);
    for (Eigen::Index j = 0; j < nm; ++j) {
      if (match[j] < 0) continue;
      const double f = frozen.frequencies_hz[match[j]];
      out.hz_min[j] = std::isnan(out.hz_min[j]) ? f : std::min(out.hz_min[j], f);
      out.hz_max[j] = std::isnan(out.hz_max[j]) ? f : std::max(out.hz_max[j], f);
    }
  }
  return out;
}

}  // namespace emb::mbs
