#include "libemb/results/order_spectrum.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::results {
namespace {

constexpr double kCycleDeg = 720.0;

// 4-point Lagrange interpolation of (x, y) at t (x strictly increasing, x[0] <= t <= x.back()).
double Interpolate(const std::vector<double>& x, const std::vector<double>& y, double t) {
  const std::size_t n = x.size();
  std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin());
  i = std::clamp<std::size_t>(i, 2, n - 2) - 2;  // stencil i .. i+3 around t
  if (n < 4) i = 0;
  const std::size_t m = std::min<std::size_t>(4, n);
  double sum = 0.0;
  for (std::size_t a = i; a < i + m; ++a) {
    double w = 1.0;
    for (std::size_t b = i; b < i + m; ++b)
      if (b != a) w *= (t - x[b]) / (x[a] - x[b]);
    sum += w * y[a];
  }
  return sum;
}

}  // namespace

OrderSpectrum CalcOrderSpectrum(const std::vector<double>& angle_deg,
                                const std::vector<double>& values, const OrderSpectrumSettings& s) {
  EMB_THROW_IF(angle_deg.size() != values.size(),
               "order spectrum: expected as many angles as values, got "
                   << angle_deg.size() << " and " << values.size());
  EMB_THROW_IF(angle_deg.size() < 4,
               "order spectrum: expected at least 4 samples, got " << angle_deg.size());
  for (std::size_t i = 1; i < angle_deg.size(); ++i)
    EMB_THROW_IF(!(angle_deg[i] > angle_deg[i - 1]),
                 "order spectrum: expected a strictly increasing crank angle, got "
                     << angle_deg[i - 1] << " then " << angle_deg[i] << " deg at sample " << i);
  EMB_THROW_IF(
      s.samples_per_cycle < 8,
      "order spectrum: expected at least 8 samples per cycle, got " << s.samples_per_cycle);
  const double twice = 2.0 * s.max_order;
  EMB_THROW_IF(
      !(s.max_order >= 0.0) || std::abs(twice - std::round(twice)) > 1e-12,
      "order spectrum: expected a maximum order that is a multiple of 1/2, got " << s.max_order);
  EMB_THROW_IF(s.max_order >= s.samples_per_cycle / 4.0,
               "order spectrum: expected a maximum order below the resampling Nyquist order "
                   << s.samples_per_cycle / 4.0 << ", got " << s.max_order);
  const double span = angle_deg.back() - angle_deg.front();
  // A run of whole cycles may end a little short of them (output times in floating point,
  // the angle from the integrated motion): half a mean sample spacing counts as complete;
  // the window then starts that little before the first sample (held constant there).
  const double slack = 0.5 * span / static_cast<double>(angle_deg.size() - 1);
  const int available = static_cast<int>(std::floor((span + slack) / kCycleDeg));
  EMB_THROW_IF(available < 1,
               "order spectrum: expected at least one whole 720-degree cycle, the "
               "data cover "
                   << span << " deg");
  EMB_THROW_IF(s.cycles < 0 || s.cycles > available,
               "order spectrum: asked for " << s.cycles << " cycles, the data cover " << available
                                            << " whole cycles (" << span << " deg)");
  OrderSpectrum out;
  out.cycles = s.cycles > 0 ? s.cycles : available;
  out.angle_end_deg = angle_deg.back();
  out.angle_start_deg = out.angle_end_deg - kCycleDeg * out.cycles;
  const int m = out.cycles * s.samples_per_cycle;
  const double step = kCycleDeg * out.cycles / m;
  std::vector<double> y(static_cast<std::size_t>(m));
  for (int k = 0; k < m; ++k)
    y[static_cast<std::size_t>(k)] =
        Interpolate(angle_deg, values, std::max(angle_deg.front(), out.angle_start_deg + k * step));
  // Order o = j / (2 K) for bin j; engine orders k/2 are the bins j = k K.
  const int top = static_cast<int>(std::lround(twice));
  for (int k = 0; k <= top; ++k) {
    const int j = k * out.cycles;
    std::complex<double> c = 0.0;
    for (int i = 0; i < m; ++i)
      c += y[static_cast<std::size_t>(i)] *
           std::polar(1.0, -2.0 * std::numbers::pi * static_cast<double>(j) * i / m);
    c /= static_cast<double>(m);
    OrderLine line;
    line.order = 0.5 * k;
    line.amplitude = (k == 0 ? 1.0 : 2.0) * std::abs(c);
    // The window starts at theta_0: arg c = order theta_0 + phase.
    const double phase = std::arg(c) * 180.0 / std::numbers::pi - line.order * out.angle_start_deg;
    line.phase_deg = k == 0 ? 0.0 : std::remainder(phase, 360.0);
    if (k == 0) out.mean = c.real();
    out.lines.push_back(line);
  }
  return out;
}

}  // namespace emb::results
