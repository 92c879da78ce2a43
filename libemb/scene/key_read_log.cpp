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

std::string FormatDefault(const double (&v)[3]) {
  return "[" + FormatDefault(v[0]) + ", " + FormatDefault(v[1]) + ", " + FormatDefault(v[2]) + "]";
}

std::string FormatIntegerRange(long long lo, long long hi) {
  if (lo <= std::numeric_limits<int>::min() && hi >= std::numeric_limits<int>::max()) return "";
  return "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

}  // namespace emb::scene
