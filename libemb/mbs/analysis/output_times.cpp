// Output times and the model's size (analysis_internal.h).
#include <algorithm>
#include <cmath>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis_internal.h"

namespace emb::mbs::internal {

double ModelSize(const System& system, const Eigen::VectorXd& q) {
  const StateLayout& L = system.layout();
  double size = 0.0;
  for (int b = 1; b < system.num_bodies(); ++b)
    size = std::max(size, q.segment<3>(L.position(b)).norm());
  for (const Marker& m : system.markers()) size = std::max(size, m.p_BM.norm());
  return size;
}

OutputTimes::OutputTimes(const AnalysisSettings& s, bool single)
    : t_start_(s.t_start), t_end_(single ? s.t_start : s.t_end), step_(s.output_step) {
  EMB_THROW_IF(!(step_ > 0.0) || !std::isfinite(t_start_) || !(t_end_ >= t_start_),
               "analysis: expected finite times t_end >= t_start and output_step > 0, got "
                   << t_start_ << ", " << t_end_ << " and " << step_ << " s");
  // Number of whole output steps; a remainder below 1e-9 steps is round-off of t_end / dt.
  const double n = std::floor((t_end_ - t_start_) / step_ + 1e-9);
  constexpr double kMaxTimes = 9007199254740992.0;  // 2^53: k dt exact for every k below
  EMB_THROW_IF(!(n < kMaxTimes), "analysis: (t_end - t_start) / output_step = "
                                     << n << " output times; expected at most 2^53");
  EMB_THROW_IF(n > 0 && !(t_end_ - step_ < t_end_ && t_start_ + step_ > t_start_),
               "analysis: output_step " << step_ << " s is below the resolution of the "
                                        << "times around t = " << t_end_ << " s");
  whole_ = static_cast<long long>(n) + 1;
  const double last = t_start_ + static_cast<double>(whole_ - 1) * step_;
  size_ = last < t_end_ - 1e-9 * step_ ? whole_ + 1 : whole_;
}

double OutputTimes::operator[](long long k) const {
  if (k >= whole_) return t_end_;
  return std::min(t_start_ + static_cast<double>(k) * step_, t_end_);
}


}  // namespace emb::mbs::internal
