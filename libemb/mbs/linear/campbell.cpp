#include "libemb/mbs/linear/campbell.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/mbs/linear/mode_tracking.h"
#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

using Complex3 = Eigen::Vector3cd;

// Below this fraction of the lateral energy the orbit is taken as a straight line: the
// sense of a whirl that is 10 % circular is still clear, anything flatter is not.
constexpr double kPlanarWhirl = 0.1;

double Norm2(const Complex3& x) { return x.squaredNorm(); }

// Mode j of point p is tracked mode t at speed k: its frequency range over the angles.
void SetAngleRange(const CampbellPoint& p, Eigen::Index j, std::size_t k, TrackedMode* t) {
  if (j >= p.hz_angle_min.size()) return;
  t->hz_angle_min[k] = p.hz_angle_min[j];
  t->hz_angle_max[k] = p.hz_angle_max[j];
}

}  // namespace

const char* Name(ModeClass c) {
  switch (c) {
    case ModeClass::kTorsion: return "torsion";
    case ModeClass::kBending: return "bending";
    case ModeClass::kAxial: return "axial";
  }
  return "?";
}

const char* Name(Whirl w) {
  switch (w) {
    case Whirl::kNone: return "-";
    case Whirl::kForward: return "forward";
    case Whirl::kBackward: return "backward";
    case Whirl::kPlanar: return "planar";
  }
  return "?";
}

ModeSplit ClassifyMode(const System& system, const Eigen::VectorXd& q, int body,
                       const Eigen::Vector3d& axis_W, const Eigen::VectorXcd& phi,
                       const Eigen::MatrixXd& M) {
  const StateLayout& L = system.layout();
  EMB_THROW_IF(body <= 0 || body >= system.num_bodies(),
               "mode classification: expected a moving body, got index " << body);
  EMB_THROW_IF(!(axis_W.norm() > 0.0), "mode classification: expected a non-zero spin axis");
  const Eigen::Vector3d a = axis_W.normalized();
  const Eigen::Vector3d e1 = a.unitOrthogonal(), e2 = a.cross(e1);
  const RigidBody& rb = system.body(body);
  const auto bodies0 = CalcBodyKinematics(system, q, Eigen::VectorXd());
  const Eigen::Matrix3d J_W = bodies0[body].R_WB * rb.inertia_B * bodies0[body].R_WB.transpose();
  const double rg2 = a.dot(J_W * a) / rb.mass;

  // Marker velocities are linear in v: evaluate at Re phi and Im phi.
  const auto re = CalcBodyKinematics(system, q, phi.real());
  const auto im = CalcBodyKinematics(system, q, phi.imag());
  std::vector<int> points;
  for (int m = 0; m < static_cast<int>(system.markers().size()); ++m)
    if (system.marker(m).body == body) points.push_back(m);
  std::vector<std::pair<Complex3, Complex3>> uw;  // (translation, rotation) phasors
  if (points.empty()) {
    uw.emplace_back(re[body].v_WB.cast<std::complex<double>>() +
                        std::complex<double>(0, 1) * im[body].v_WB.cast<std::complex<double>>(),
                    re[body].omega_W.cast<std::complex<double>>() +
                        std::complex<double>(0, 1) * im[body].omega_W.cast<std::complex<double>>());
  } else {
    for (int m : points) {
      const MarkerKinematics kr = CalcMarkerKinematics(system, re, m);
      const MarkerKinematics ki = CalcMarkerKinematics(system, im, m);
      uw.emplace_back(kr.v_WM.cast<std::complex<double>>() +
                          std::complex<double>(0, 1) * ki.v_WM.cast<std::complex<double>>(),
                      kr.omega_W.cast<std::complex<double>>() +
                          std::complex<double>(0, 1) * ki.omega_W.cast<std::complex<double>>());
    }
  }
  double axial = 0.0, bending = 0.0, torsion = 0.0, h = 0.0;
  const Complex3 ac = a.cast<std::complex<double>>();
  // The sense of the orbit of the lateral part of x about a: -Im(conj(x1) x2) > 0 turns
  // from e1 towards e2 (x1 = 1, x2 = -i: (cos, sin)).
  const auto lateral_sense = [&e1, &e2](const Complex3& x) {
    const std::complex<double> x1 = e1.cast<std::complex<double>>().dot(x);
    const std::complex<double> x2 = e2.cast<std::complex<double>>().dot(x);
    return -(std::conj(x1) * x2).imag();
  };
  for (const auto& [u, w] : uw) {
    const std::complex<double> ua = ac.dot(u), wa = ac.dot(w);  // a real: dot = a . u
    axial += std::norm(ua);
    bending += Norm2(u - ac * ua) + rg2 * Norm2(w - ac * wa);
    torsion += rg2 * std::norm(wa);
    h += lateral_sense(u) + rg2 * lateral_sense(w);
  }
  ModeSplit s;
  const double total = axial + bending + torsion;
  if (total > 0.0) s.axial = axial / total, s.bending = bending / total, s.torsion = torsion / total;
  s.kind = s.torsion >= s.bending && s.torsion >= s.axial ? ModeClass::kTorsion
           : s.bending >= s.axial                          ? ModeClass::kBending
                                                           : ModeClass::kAxial;
  if (s.kind == ModeClass::kBending) {
    // |h| <= lateral energy / 2 (a circular orbit); compare against that.
    const double spin = a.dot(bodies0[body].omega_W);
    if (std::abs(h) < kPlanarWhirl * 0.5 * bending)
      s.whirl = Whirl::kPlanar;
    else
      s.whirl = (h > 0.0) == (spin >= 0.0) ? Whirl::kForward : Whirl::kBackward;
  }
  // The body's share of the kinetic energy: its rows of v.
  std::vector<int> rows;
  for (int i = 0; i < StateLayout::kVPerBody; ++i) rows.push_back(L.velocity(body) + i);
  for (int i = 0; i < L.num_elastic(body); ++i) rows.push_back(L.elastic_v(body) + i);
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  Eigen::VectorXcd pb(n);
  Eigen::MatrixXd Mb(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    pb[i] = phi[rows[i]];
    for (Eigen::Index j = 0; j < n; ++j) Mb(i, j) = M(rows[i], rows[j]);
  }
  s.body_energy = (pb.adjoint() * Mb.cast<std::complex<double>>() * pb)(0, 0).real();
  return s;
}

OperatingPointModes CalcOperatingPointModes(const System& system, AnalysisSettings settings,
                                            double rpm, const std::string& rotor, double pool_hz,
                                            bool stationary_frame) {
  OperatingPointOptions options;
  options.stationary_frame = stationary_frame;
  return CalcOperatingPointModes(system, settings, rpm, rotor, pool_hz, options);
}

OperatingPointModes CalcOperatingPointModes(const System& system, AnalysisSettings settings,
                                            double rpm, const std::string& rotor, double pool_hz,
                                            const OperatingPointOptions& options) {
  const bool stationary_frame = options.stationary_frame;
  settings.type = AnalysisType::kDynamic;
  settings.installed_bases.clear();
  settings.truncated_bases.clear();
  const PreparedRun run = PrepareRun(system, settings);
  ThrowIfNotReady(run);
  const System& sys = run.system;
  OperatingPointModes out;
  if (!rotor.empty()) {
    out.rotor_body = sys.FindBody(rotor);
  } else {
    std::vector<int> flexible;
    for (int b = 1; b < sys.num_bodies(); ++b)
      if (sys.layout().num_elastic(b)) flexible.push_back(b);
    EMB_THROW_IF(flexible.size() != 1, "expected a rotor body (--body) naming the crankshaft: "
                                       "the model has "
                                           << flexible.size() << " flexible bodies");
    out.rotor_body = flexible[0];
  }
  const auto bodies = CalcBodyKinematics(sys, run.q0, run.v0);
  const Eigen::Vector3d omega = bodies[out.rotor_body].omega_W;
  EMB_THROW_IF(!(omega.norm() > 0.0), "body '" << sys.body(out.rotor_body).name
                                               << "' does not spin at " << rpm
                                               << " rpm; expected the rotor (--body)");
  out.axis_W = omega.normalized();
  ConstraintWorkspace ws(sys);
  const double t = settings.t_start;
  const AccelerationSolution acc = SolveAccelerations(sys, run.q0, run.v0, t, &ws);
  const LinearizedModel lin = CalcLinearizedModel(sys, run.q0, run.v0, t, acc.lambda, &ws, acc.vdot);
  out.point.rpm = rpm;
  if (options.linearisation == Linearisation::kCycleAverage) {
    CycleAveragedModes avg = CalcCycleAveragedModes(system, settings, run, out.rotor_body,
                                                    options.num_angles, pool_hz, stationary_frame);
    out.point.modes = std::move(avg.modes);
    out.point.hz_angle_min = std::move(avg.hz_min);
    out.point.hz_angle_max = std::move(avg.hz_max);
  } else {
    out.point.modes = CalcRotatingModes(sys, run.q0, run.v0, lin, pool_hz, stationary_frame);
  }
  for (Eigen::Index j = 0; j < out.point.modes.shapes.cols(); ++j)
    out.point.splits.push_back(ClassifyMode(sys, run.q0, out.rotor_body, out.axis_W,
                                            out.point.modes.shapes.col(j), out.point.modes.mass));
  out.q = run.q0;
  out.v = run.v0;
  out.system = sys;
  return out;
}

CampbellDiagram TrackCampbell(const std::vector<CampbellPoint>& points, double fmax_hz,
                              double min_mac) {
  EMB_THROW_IF(points.empty(), "Campbell diagram: expected at least one speed");
  for (std::size_t k = 1; k < points.size(); ++k)
    EMB_THROW_IF(!(points[k].rpm > points[k - 1].rpm),
                 "Campbell diagram: expected increasing speeds, got " << points[k - 1].rpm
                                                                      << " then " << points[k].rpm
                                                                      << " rpm");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CampbellDiagram d;
  const std::size_t ns = points.size();
  for (const auto& p : points) d.rpm.push_back(p.rpm);
  const RotatingModes& first = points[0].modes;
  std::vector<Eigen::VectorXcd> last;  // last shape of each tracked mode
  std::vector<bool> alive;
  for (Eigen::Index j = 0; j < first.frequencies_hz.size(); ++j) {
    if (fmax_hz > 0.0 && first.frequencies_hz[j] > fmax_hz) break;
    TrackedMode t;
    t.index = static_cast<int>(j) + 1;
    t.hz.assign(ns, nan), t.decay.assign(ns, nan), t.mac.assign(ns, nan);
    t.splits.resize(ns);
    t.hz_angle_min.assign(ns, nan), t.hz_angle_max.assign(ns, nan);
    t.hz[0] = first.frequencies_hz[j], t.decay[0] = first.decay[j], t.mac[0] = 1.0;
    SetAngleRange(points[0], j, 0, &t);
    if (j < static_cast<Eigen::Index>(points[0].splits.size())) t.splits[0] = points[0].splits[j];
    d.modes.push_back(t);
    last.push_back(first.shapes.col(j));
    alive.push_back(true);
  }
  for (std::size_t k = 1; k < ns; ++k) {
    const RotatingModes& now = points[k].modes;
    std::vector<int> live;
    for (std::size_t i = 0; i < d.modes.size(); ++i)
      if (alive[i]) live.push_back(static_cast<int>(i));
    Eigen::MatrixXcd prev(now.shapes.rows(), static_cast<Eigen::Index>(live.size()));
    for (std::size_t i = 0; i < live.size(); ++i) prev.col(static_cast<Eigen::Index>(i)) = last[live[i]];
    const Eigen::MatrixXd mac = CalcMac(prev, now.shapes, now.mass);
    const std::vector<int> match = MatchModes(mac, min_mac);
    for (std::size_t i = 0; i < live.size(); ++i) {
      TrackedMode& t = d.modes[live[i]];
      const int j = match[i];
      if (j < 0) {
        alive[live[i]] = false;
        ++d.num_lost;
        continue;
      }
      t.hz[k] = now.frequencies_hz[j], t.decay[k] = now.decay[j];
      t.mac[k] = mac(static_cast<Eigen::Index>(i), j);
      d.min_mac_seen = std::min(d.min_mac_seen, t.mac[k]);
      if (j < static_cast<int>(points[k].splits.size())) t.splits[k] = points[k].splits[j];
      SetAngleRange(points[k], j, k, &t);
      last[live[i]] = now.shapes.col(j);
    }
  }
  for (TrackedMode& t : d.modes) {
    double f[3] = {0, 0, 0};
    for (std::size_t k = 0; k < ns; ++k) {
      if (std::isnan(t.hz[k])) continue;
      f[0] += t.splits[k].torsion, f[1] += t.splits[k].bending, f[2] += t.splits[k].axial;
      t.whirl = t.splits[k].whirl;
    }
    t.kind = f[0] >= f[1] && f[0] >= f[2] ? ModeClass::kTorsion
             : f[1] >= f[2]               ? ModeClass::kBending
                                          : ModeClass::kAxial;
  }
  return d;
}

std::vector<Crossing> FindCrossings(const CampbellDiagram& d, const std::vector<double>& orders) {
  std::vector<Crossing> out;
  for (double k : orders) {
    EMB_THROW_IF(!(k > 0.0), "Campbell diagram: expected engine orders > 0, got " << k);
    for (const TrackedMode& t : d.modes) {
      for (std::size_t i = 0; i + 1 < d.rpm.size(); ++i) {
        if (std::isnan(t.hz[i]) || std::isnan(t.hz[i + 1])) continue;
        const double g0 = t.hz[i] - k * d.rpm[i] / 60.0;
        const double g1 = t.hz[i + 1] - k * d.rpm[i + 1] / 60.0;
        // One crossing per sign change; a zero at a grid speed counts on its left interval.
        if (!((g0 > 0.0 && g1 <= 0.0) || (g0 < 0.0 && g1 >= 0.0) || (i == 0 && g0 == 0.0)))
          continue;
        const double x = g0 == g1 ? 0.0 : g0 / (g0 - g1);
        Crossing c;
        c.order = k;
        c.rpm = d.rpm[i] + x * (d.rpm[i + 1] - d.rpm[i]);
        c.mode_hz = k * c.rpm / 60.0;
        c.mode_index = t.index;
        const ModeSplit& s = t.splits[x < 0.5 ? i : i + 1];
        c.kind = s.kind;
        c.whirl = s.whirl;
        c.torsion = s.torsion;
        c.bending = s.bending;
        c.axial = s.axial;
        out.push_back(c);
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const Crossing& a, const Crossing& b) {
    return a.rpm != b.rpm ? a.rpm < b.rpm : a.order < b.order;
  });
  return out;
}

}  // namespace emb::mbs
