#pragma once
/// @file
/// Rainflow cycle counting (ASTM E1049-85 (2017), section 5.4.4), for fatigue of a stress
/// history.
///
/// The history is first reduced to its reversals (peaks and valleys; repeated values and
/// points on a monotonic run dropped). Then, with a stack of reversals not yet counted and
/// X the range of the last two, Y the range of the two before:
///   while X >= Y: if Y holds the first point of the stack (the start S), count Y as a half
///   cycle and drop the first point; else count Y as one cycle and drop both its points.
/// What remains at the end counts as half cycles (range after range).
/// A *periodic* history (one period of a steady state repeating) is first rotated to start
/// at its largest absolute value and closed there: its residue then comes in pairs of half
/// cycles of equal range (one whole cycle each), and the counts are those of one period of
/// the repeated history.

#include <vector>

namespace emb::results {

/// One counted range.
struct RainflowCycle {
  double range{0.0};  ///< max − min of the cycle (> 0)
  double mean{0.0};   ///< (max + min) / 2
  double count{0.0};  ///< 1 or 0.5
};

/// The reversals of `history` (first and last points kept).
std::vector<double> Reversals(const std::vector<double>& history);

/// Rainflow cycles of `history` (file comment), in the order counted.
std::vector<RainflowCycle> CountRainflow(const std::vector<double>& history);

/// Rainflow cycles of one period of a periodically repeated `history` (file comment).
std::vector<RainflowCycle> CountRainflowPeriodic(const std::vector<double>& history);

}  // namespace emb::results
