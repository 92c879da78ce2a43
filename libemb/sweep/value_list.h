#pragma once
/// @file
/// Lists of operating values on the command line: a range "first:last:step" (last included
/// when it is a whole number of steps from first, to 1e-9 of a step) or a comma-separated
/// list "1000,2500,4000". Used for engine speeds (`emb sweep --rpm`) and orders (`--orders`).

#include <string>
#include <vector>

namespace emb::sweep {

/// Parses `text` (see the file comment). `what` names the option in messages (e.g. "--rpm").
/// @returns the values in the order given (a range ascending), none repeated.
/// @throws InputError for a malformed number, a range whose step is not positive or whose
/// last is below its first, a repeated value, or more than kMaxValues values.
std::vector<double> ParseValueList(const std::string& text, const std::string& what);

/// The most values one list may hold (a typo such as 1000:6500:0.25 must not start 22 001 runs).
inline constexpr int kMaxValues = 10000;

}  // namespace emb::sweep
