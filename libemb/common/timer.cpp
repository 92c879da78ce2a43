#include "libemb/common/timer.h"

#include <sys/resource.h>

namespace emb {

double PhaseTimes::Get(const std::string& name) const {
  double sum = 0.0;
  for (const auto& [n, s] : phases)
    if (n == name) sum += s;
  return sum;
}

double PhaseTimes::Total() const {
  double sum = 0.0;
  for (const auto& p : phases) sum += p.second;
  return sum;
}

long long PeakResidentBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<long long>(usage.ru_maxrss) * 1024;  // Linux reports KiB.
}

}  // namespace emb
