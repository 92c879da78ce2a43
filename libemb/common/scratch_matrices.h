#pragma once
/// @file
/// Reusable storage for dynamic-size temporaries of a kernel that is evaluated again and
/// again (an iteration matrix per Newton iteration): View(k, rows, cols) maps buffer k as a
/// rows x cols column-major matrix. A buffer grows (allocates) only past the largest size it
/// has held, so after a first evaluation of every size none allocates (ggl_workspace.h).
/// The contents of a view are unspecified until written. Not thread-safe.

#include <Eigen/Core>
#include <vector>

namespace emb {

class ScratchMatrices {
 public:
  /// Buffer `slot` (0, 1, ...) as a rows x cols matrix; a view stays valid until the next
  /// View() of the same slot with a larger size.
  Eigen::Map<Eigen::MatrixXd> View(int slot, Eigen::Index rows, Eigen::Index cols) {
    if (slot >= static_cast<int>(buffers_.size())) buffers_.resize(slot + 1);
    std::vector<double>& b = buffers_[slot];
    if (b.size() < static_cast<std::size_t>(rows * cols)) b.resize(rows * cols);
    return Eigen::Map<Eigen::MatrixXd>(b.data(), rows, cols);
  }

 private:
  std::vector<std::vector<double>> buffers_;
};

}  // namespace emb
