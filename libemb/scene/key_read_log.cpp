#include "libemb/scene/key_read_log.h"

#include <charconv>
#include <limits>

#include "libemb/common/error.h"

namespace emb::scene {
namespace {
thread_local std::vector<KeyRead>* t_log = nullptr;
}  // namespace

KeyReadLog::KeyReadLog() {
  EMB_CHECK(t_log == nullptr);
  t_log = &reads_;
}

KeyReadLog::~KeyReadLog() { t_log = nullptr; }

bool KeyReadLogActive() { return t_log != nullptr; }

void NoteKeyRead(KeyRead read) {
  if (t_log) t_log->push_back(std::move(read));
}

std::string FormatDefault(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, r.ptr);
  // to_chars writes at least two exponent digits and a '+': 1e-06, 5e+08.
  if (const auto e = s.find('e'); e != std::string::npos) {
    std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    if (exponent[0] == '+' || exponent[0] == '-') exponent.erase(0, 1);
    while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
    s = mantissa + "e" + (negative ? "-" : "") + exponent;
  }
  return s;
}

std::string FormatDefault(bool v) { return v ? "true" : "false"; }

// Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "[" + string&&.
std::string FormatDefault(const double (&v)[3]) {
  std::string out("[");
  for (int i = 0; i < 3; ++i) out.append(i ? ", " : "").append(FormatDefault(v[i]));
  return out.append("]");
}

std::string FormatIntegerRange(long long lo, long long hi) {
  if (lo <= std::numeric_limits<int>::min() && hi >= std::numeric_limits<int>::max()) return "";
  std::string out("[");
  return out.append(std::to_string(lo)).append(", ").append(std::to_string(hi)).append("]");
}

}  // namespace emb::scene
