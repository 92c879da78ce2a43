#include "libemb/integrators/matrix_assembler.h"

#include <algorithm>
#include <sstream>

#include "libemb/common/error.h"

namespace emb {

void MatrixAssembler::BeginDense(Eigen::Ref<Eigen::MatrixXd> target) {
  target.setZero();
  dense_ = target.data();
  dense_stride_ = target.outerStride();
  dense_rows_ = static_cast<int>(target.rows());
  dense_cols_ = static_cast<int>(target.cols());
  mode_ = Mode::kDense;
}

void MatrixAssembler::BeginSparse(SparseMatrixd* target, int rows, int cols) {
  EMB_CHECK(target != nullptr && rows >= 0 && cols >= 0);
  target_ = target;
  const bool same = target == recorded_for_ && target->rows() == rows && target->cols() == cols &&
                    !slot_.empty() && target->isCompressed() &&
                    target->nonZeros() == recorded_nnz_;
  if (same) {
    std::fill(target->valuePtr(), target->valuePtr() + target->nonZeros(), 0.0);
    next_ = 0;
    mode_ = Mode::kRefill;
    return;
  }
  rows_count_ = rows;
  cols_count_ = cols;
  rows_.clear();
  cols_.clear();
  values_.clear();
  slot_.clear();
  recorded_for_ = nullptr;
  mode_ = Mode::kRecord;
}

void MatrixAssembler::AddRecord(int row, int col, double value) {
  EMB_CHECK(row >= 0 && row < rows_count_ && col >= 0 && col < cols_count_);
  rows_.push_back(row);
  cols_.push_back(col);
  values_.push_back(value);
}

void MatrixAssembler::StructureChanged(int row, int col) const {
  std::ostringstream o;
  o << "contribution " << next_ << " of " << slot_.size() << " at (" << row << ", " << col
    << ") differs from the recorded structure";
  internal::ThrowInternal("same structure as the recording pass", __FILE__, __LINE__, o.str());
}

void MatrixAssembler::NotStarted() const {
  internal::ThrowInternal("mode_ != Mode::kIdle", __FILE__, __LINE__,
                          "MatrixAssembler used outside BeginDense/BeginSparse ... Finish");
}

void MatrixAssembler::Finish() {
  switch (mode_) {
    case Mode::kIdle:
      NotStarted();
    case Mode::kDense:
      break;
    case Mode::kRefill:
      EMB_CHECK(next_ == slot_.size());
      break;
    case Mode::kRecord: {
      // Structure with explicit zeros kept: build it from unit triplets, then locate every
      // contribution in its column (sorted row indices) once.
      std::vector<Eigen::Triplet<double, int>> triplets;
      triplets.reserve(rows_.size());
      for (std::size_t k = 0; k < rows_.size(); ++k) triplets.emplace_back(rows_[k], cols_[k], 0.0);
      SparseMatrixd& A = *target_;
      A.resize(rows_count_, cols_count_);
      A.setFromTriplets(triplets.begin(), triplets.end());
      A.makeCompressed();
      slot_.resize(rows_.size());
      const int* outer = A.outerIndexPtr();
      const int* inner = A.innerIndexPtr();
      for (std::size_t k = 0; k < rows_.size(); ++k) {
        const int* begin = inner + outer[cols_[k]];
        const int* end = inner + outer[cols_[k] + 1];
        const int* it = std::lower_bound(begin, end, rows_[k]);
        EMB_CHECK(it != end && *it == rows_[k]);
        slot_[k] = static_cast<int>(it - inner);
        A.valuePtr()[slot_[k]] += values_[k];
      }
      values_.clear();
      values_.shrink_to_fit();
      recorded_for_ = target_;
      recorded_nnz_ = A.nonZeros();
      break;
    }
  }
  mode_ = Mode::kIdle;
}

}  // namespace emb
