#include "libemb/common/did_you_mean.h"

#include <algorithm>

namespace emb {

int EditDistance(const std::string& a, const std::string& b) {
  std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string DidYouMean(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  int best_d = 1 << 30;
  for (const auto& c : candidates) {
    const int d = EditDistance(name, c);
    if (d < best_d) best_d = d, best = c;
  }
  // Suggest only near misses: at most a third of the name wrong (and at least 2 edits).
  if (best.empty() || best_d > std::max<int>(2, static_cast<int>(name.size()) / 3)) return "";
  return "; did you mean '" + best + "'?";
}

}  // namespace emb
