#include "libemb/sweep/order_tracking.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/results/order_spectrum.h"

namespace emb::sweep {
namespace {
constexpr double kCycleDeg = 720.0;
}  // namespace

std::vector<OperatingPoint> TrackOrders(const std::vector<double>& time,
                                        const std::vector<double>& angle_deg,
                                        const std::vector<std::vector<double>>& values,
                                        const OrderSettings& settings) {
  const std::size_t n = time.size();
  EMB_THROW_IF(angle_deg.size() != n, "order tracking: expected as many angles as times, got "
                                          << angle_deg.size() << " and " << n);
  EMB_THROW_IF(values.size() != settings.channels.size(),
               "order tracking: expected " << settings.channels.size() << " channels, got "
                                           << values.size());
  for (const auto& v : values)
    EMB_THROW_IF(v.size() != n,
                 "order tracking: expected " << n << " values per channel, got " << v.size());
  EMB_THROW_IF(n < 4, "order tracking: expected at least 4 samples, got " << n);
  for (std::size_t i = 1; i < n; ++i)
    EMB_THROW_IF(!(angle_deg[i] > angle_deg[i - 1]) || !(time[i] > time[i - 1]),
                 "order tracking: expected an increasing time and crank angle, got "
                     << angle_deg[i - 1] << " then " << angle_deg[i] << " deg at sample " << i);
  double max_order = 0.0;
  for (double o : settings.orders) {
    EMB_THROW_IF(!(o > 0.0) || std::abs(2 * o - std::round(2 * o)) > 1e-9 ||
                     o >= settings.samples_per_cycle / 4.0,
                 "order tracking: order " << o << ": expected a positive multiple of 0.5 below "
                                          << settings.samples_per_cycle / 4.0);
    max_order = std::max(max_order, o);
  }
  const int windows =
      static_cast<int>(std::floor((angle_deg.back() - angle_deg.front()) / kCycleDeg));
  EMB_THROW_IF(windows < 1, "order tracking: the run covers "
                                << angle_deg.back() - angle_deg.front()
                                << " deg of crank angle, expected at least one 720-degree cycle");
  results::OrderSpectrumSettings os;
  os.cycles = 1;
  os.max_order = max_order;
  os.samples_per_cycle = settings.samples_per_cycle;
  const auto nc = static_cast<Eigen::Index>(values.size());
  const auto no = static_cast<Eigen::Index>(settings.orders.size());
  std::vector<OperatingPoint> out;
  for (int w = 0; w < windows; ++w) {
    const double a0 = angle_deg.front() + w * kCycleDeg, a1 = a0 + kCycleDeg;
    // The samples spanning [a0, a1] (one beyond each end where there is one, for the
    // interpolation stencil), then the angle's end placed at a1 by linear interpolation.
    const auto lo = std::upper_bound(angle_deg.begin(), angle_deg.end(), a0) - angle_deg.begin();
    const auto hi = std::lower_bound(angle_deg.begin(), angle_deg.end(), a1) - angle_deg.begin();
    const std::size_t first = static_cast<std::size_t>(std::max<std::ptrdiff_t>(lo - 1, 0));
    const std::size_t last = std::min(static_cast<std::size_t>(hi), n - 1);
    auto time_at = [&](double a) {
      const auto j = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
          std::upper_bound(angle_deg.begin(), angle_deg.end(), a) - angle_deg.begin(), 1,
          static_cast<std::ptrdiff_t>(n - 1)));
      const double f = (a - angle_deg[j - 1]) / (angle_deg[j] - angle_deg[j - 1]);
      return time[j - 1] + f * (time[j] - time[j - 1]);
    };
    OperatingPoint p;
    p.status = PointStatus::kRunUp;
    p.cycles = w + 1;
    p.change = std::numeric_limits<double>::quiet_NaN();
    p.rpm = 120.0 / (time_at(a1) - time_at(a0));
    p.mean.resize(nc);
    p.amplitude.resize(nc, no);
    p.phase_deg.resize(nc, no);
    // The window ends at a1: the spectrum takes the last whole cycle of the data it is given.
    std::vector<double> a(angle_deg.begin() + static_cast<std::ptrdiff_t>(first),
                          angle_deg.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    for (Eigen::Index c = 0; c < nc; ++c) {
      const auto& v = values[static_cast<std::size_t>(c)];
      std::vector<double> y(v.begin() + static_cast<std::ptrdiff_t>(first),
                            v.begin() + static_cast<std::ptrdiff_t>(last) + 1);
      std::vector<double> ac = a;
      // Trim or extend the end to exactly a1 by linear interpolation of the last interval.
      if (ac.back() > a1 && ac.size() >= 2) {
        const double f = (a1 - ac[ac.size() - 2]) / (ac.back() - ac[ac.size() - 2]);
        y.back() = y[y.size() - 2] + f * (y.back() - y[y.size() - 2]);
        ac.back() = a1;
      }
      const results::OrderSpectrum sp = results::CalcOrderSpectrum(ac, y, os);
      p.mean(c) = sp.mean;
      for (Eigen::Index k = 0; k < no; ++k) {
        const auto line = static_cast<std::size_t>(
            std::lround(2.0 * settings.orders[static_cast<std::size_t>(k)]));
        p.amplitude(c, k) = sp.lines.at(line).amplitude;
        p.phase_deg(c, k) = sp.lines.at(line).phase_deg;
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace emb::sweep
