#include "libemb/mbs/time_function.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libemb/common/error.h"

namespace emb::mbs {

TimeFunction TimeFunction::Constant(double value) { return Polynomial({value}); }

TimeFunction TimeFunction::Polynomial(std::vector<double> coefficients) {
  EMB_THROW_IF(coefficients.empty(), "polynomial function: expected at least one coefficient");
  TimeFunction f;
  f.kind_ = Kind::kPolynomial;
  f.c_ = std::move(coefficients);
  return f;
}

TimeFunction TimeFunction::Harmonic(double amplitude, double omega, double phase, double offset) {
  TimeFunction f;
  f.kind_ = Kind::kHarmonic;
  f.c_ = {amplitude, omega, phase, offset};
  return f;
}

TimeFunction TimeFunction::Table(std::vector<double> x, std::vector<double> y, bool periodic) {
  EMB_THROW_IF(x.size() != y.size(), "table function: expected as many x as y values, got "
                                         << x.size() << " and " << y.size());
  EMB_THROW_IF(x.size() < 2, "table function: expected at least 2 points, got " << x.size());
  for (std::size_t i = 1; i < x.size(); ++i)
    EMB_THROW_IF(!(x[i] > x[i - 1]), "table function: expected strictly increasing x, got x["
                                         << i - 1 << "] = " << x[i - 1] << " and x[" << i
                                         << "] = " << x[i]);
  TimeFunction f;
  f.kind_ = Kind::kTable;
  f.x_ = std::move(x);
  f.y_ = std::move(y);
  f.periodic_ = periodic;
  return f;
}

FunctionValue TimeFunction::Eval(double x) const {
  FunctionValue v;
  switch (kind_) {
    case Kind::kPolynomial: {
      // Horner for f, f', f''.
      for (std::size_t k = c_.size(); k-- > 0;) {
        v.d2f = v.d2f * x + 2.0 * v.df;
        v.df = v.df * x + v.f;
        v.f = v.f * x + c_[k];
      }
      return v;
    }
    case Kind::kHarmonic: {
      const double a = c_[0], w = c_[1], ph = c_[2], off = c_[3];
      v.f = off + a * std::sin(w * x + ph);
      v.df = a * w * std::cos(w * x + ph);
      v.d2f = -a * w * w * std::sin(w * x + ph);
      return v;
    }
    case Kind::kTable: {
      double xx = x;
      if (periodic_) {
        const double period = x_.back() - x_.front();
        xx = x_.front() + std::fmod(std::fmod(x - x_.front(), period) + period, period);
      }
      if (xx <= x_.front()) return {y_.front(), 0.0, 0.0};
      if (xx >= x_.back()) return {y_.back(), 0.0, 0.0};
      const auto it = std::upper_bound(x_.begin(), x_.end(), xx);
      const std::size_t i = static_cast<std::size_t>(it - x_.begin()) - 1;
      const double slope = (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]);
      v.f = y_[i] + slope * (xx - x_[i]);
      v.df = slope;
      return v;
    }
  }
  return v;
}

std::string TimeFunction::Describe() const {
  std::ostringstream o;
  o.precision(10);
  if (kind_ == Kind::kTable) {
    o << "table[" << x_.size() << " points" << (periodic_ ? ", periodic" : "") << "]";
    return o.str();
  }
  o << (kind_ == Kind::kPolynomial ? "polynomial[" : "harmonic[");
  for (std::size_t k = 0; k < c_.size(); ++k) o << (k ? ", " : "") << c_[k];
  o << "]";
  return o.str();
}

}  // namespace emb::mbs
