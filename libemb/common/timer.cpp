#include "libemb/common/timer.h"

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>

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

void PhaseTimes::Merge(const PhaseTimes& other) {
  for (const auto& phase : other.phases) {  // (clang 14 cannot capture structured bindings)
    auto it = std::find_if(phases.begin(), phases.end(),
                           [&](const auto& p) { return p.first == phase.first; });
    if (it == phases.end())
      phases.push_back(phase);
    else
      it->second += phase.second;
  }
}

void ReturnFreedMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

long long PeakResidentBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return static_cast<long long>(usage.ru_maxrss) * 1024;  // Linux reports KiB.
}

}  // namespace emb
