#include "libemb/common/number_check.h"

#include <cmath>
#include <sstream>

#include "libemb/common/error.h"

namespace emb {
namespace {
std::string Num(double v) {
  std::ostringstream o;
  o.precision(12);
  o << v;
  return o.str();
}
std::string WithUnit(const std::string& v, const std::string& unit) {
  return unit.empty() ? v : v + " " + unit;
}
}  // namespace

NumberRange NumberRange::Positive(std::string unit) {
  NumberRange r;
  r.lo = 0.0;
  r.lo_open = true;
  r.unit = std::move(unit);
  return r;
}
NumberRange NumberRange::NonNegative(std::string unit) {
  NumberRange r;
  r.lo = 0.0;
  r.unit = std::move(unit);
  return r;
}
NumberRange NumberRange::Closed(double lo, double hi, std::string unit) {
  NumberRange r;
  r.lo = lo;
  r.hi = hi;
  r.unit = std::move(unit);
  return r;
}
NumberRange NumberRange::Open(double lo, double hi, std::string unit) {
  NumberRange r = Closed(lo, hi, std::move(unit));
  r.lo_open = r.hi_open = true;
  return r;
}
NumberRange NumberRange::Finite(std::string unit) {
  NumberRange r;
  r.unit = std::move(unit);
  return r;
}

bool NumberRange::Contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string NumberRange::Describe() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return std::string("in ") + (lo_open ? "(" : "[") + Num(lo) + ", " + Num(hi) +
           (hi_open ? ")" : "]") + (unit.empty() ? "" : " " + unit);
  if (has_lo) return WithUnit((lo_open ? "> " : ">= ") + Num(lo), unit);
  if (has_hi) return WithUnit((hi_open ? "< " : "<= ") + Num(hi), unit);
  return unit.empty() ? "" : "in " + unit;
}

double CheckNumber(const std::string& what, double value, const NumberRange& range) {
  if (!range.Contains(value)) {
    const std::string d = range.Describe();
    EMB_THROW(InputError, what << ": expected a finite number" << (d.empty() ? "" : " " + d)
                               << ", got " << WithUnit(Num(value), range.unit));
  }
  return value;
}

long long CheckInteger(const std::string& what, long long value, long long lo, long long hi) {
  EMB_THROW_IF(value < lo || value > hi,
               what << ": expected an integer in [" << lo << ", " << hi << "], got " << value);
  return value;
}

}  // namespace emb
