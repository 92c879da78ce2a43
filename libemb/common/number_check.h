#pragma once
/// @file
/// One check for every number a user gives (command-line options, scene keys): finite, in
/// its range, and a message that names the number, the range and the unit:
///   "--rtol: expected a finite number in (0, 1), got nan"
///   "scene.yaml:12: analysis 'output_step': expected a finite number > 0 s, got -0.001 s".

#include <limits>
#include <string>

namespace emb {

/// The values a number may take: [lo, hi] with either end open, and its unit for messages.
struct NumberRange {
  double lo{-std::numeric_limits<double>::infinity()};
  double hi{std::numeric_limits<double>::infinity()};
  bool lo_open{false};
  bool hi_open{false};
  std::string unit;  ///< e.g. "m", "Hz", "s"; empty for pure numbers

  /// (0, ∞)
  static NumberRange Positive(std::string unit = "");
  /// [0, ∞)
  static NumberRange NonNegative(std::string unit = "");
  /// [lo, hi]
  static NumberRange Closed(double lo, double hi, std::string unit = "");
  /// (lo, hi)
  static NumberRange Open(double lo, double hi, std::string unit = "");
  /// Any finite number.
  static NumberRange Finite(std::string unit = "");

  bool Contains(double v) const;
  /// "> 0 m", ">= 0", "in (0, 1)", "in [1, 2] Hz", "" for any finite number.
  std::string Describe() const;
};

/// @returns `value`. @throws InputError "<what>: expected a finite number <range>, got <v>"
///          if it is not finite or outside `range`.
double CheckNumber(const std::string& what, double value, const NumberRange& range);

/// @returns `value`. @throws InputError "<what>: expected an integer in [lo, hi], got <v>".
long long CheckInteger(const std::string& what, long long value, long long lo, long long hi);

}  // namespace emb
