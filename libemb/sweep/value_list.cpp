#include "libemb/sweep/value_list.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "libemb/common/error.h"

namespace emb::sweep {
namespace {

double Number(const std::string& token, const std::string& what, const std::string& text) {
  const char* begin = token.c_str();
  char* end = nullptr;
  const double x = token.empty() ? NAN : std::strtod(begin, &end);
  EMB_THROW_IF(token.empty() || end != begin + token.size() || !std::isfinite(x),
               what << ": expected a number in '" << text << "', got '" << token
                    << "' (a list 1000,2000 or a range first:last:step)");
  return x;
}

std::vector<std::string> Split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(sep, start);
    parts.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

}  // namespace

std::vector<double> ParseValueList(const std::string& text, const std::string& what) {
  EMB_THROW_IF(text.empty(), what << ": expected a list 1000,2000 or a range first:last:step, "
                                     "got nothing");
  std::vector<double> values;
  if (text.find(':') != std::string::npos) {
    const std::vector<std::string> p = Split(text, ':');
    EMB_THROW_IF(p.size() != 3, what << ": expected a range first:last:step, got '" << text << "'");
    const double first = Number(p[0], what, text), last = Number(p[1], what, text),
                 step = Number(p[2], what, text);
    EMB_THROW_IF(!(step > 0.0), what << ": expected a positive step in '" << text << "', got "
                                     << step);
    EMB_THROW_IF(last < first, what << ": expected last >= first in '" << text << "', got "
                                    << last << " < " << first);
    const double n = std::floor((last - first) / step + 1e-9);
    EMB_THROW_IF(n + 1 > kMaxValues, what << ": '" << text << "' makes " << n + 1
                                          << " values; the limit is " << kMaxValues);
    for (int k = 0; k <= static_cast<int>(n); ++k) values.push_back(first + k * step);
  } else {
    for (const std::string& token : Split(text, ',')) values.push_back(Number(token, what, text));
    EMB_THROW_IF(static_cast<int>(values.size()) > kMaxValues,
                 what << ": " << values.size() << " values; the limit is " << kMaxValues);
  }
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
  EMB_THROW_IF(dup != sorted.end(), what << ": " << *dup << " appears twice in '" << text << "'");
  return values;
}

}  // namespace emb::sweep
