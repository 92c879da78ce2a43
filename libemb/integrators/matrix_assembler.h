#pragma once
/// @file
/// Assembly of an iteration matrix from a fixed sequence of (row, column, value)
/// contributions, into either a dense matrix or a compressed-column sparse one whose
/// structure is built once (DESIGN.md: "assemble once, from triplets or a precomputed
/// sparsity pattern, in O(nnz)").
///
/// A problem writes its Jacobian once, block by block, and the same code fills both targets:
///
///   MatrixAssembler a;
///   a.BeginSparse(&J);            // J empty: this pass records the structure
///   a.AddBlock(r, c, block); ...  // the same calls, in the same order, at every state
///   a.Finish();
///
/// The recording pass keeps every contribution, zero or not, as a structural entry (a
/// block whose value happens to vanish at t0 is still in the pattern) and remembers, per
/// contribution, the slot of the compressed matrix it lands in. Later passes on the same
/// matrix only zero the values and add into those slots: O(number of contributions), no
/// search, no allocation. Every refill contribution is checked against the recorded
/// (row, column), so a structure that changes with the state is caught, not silently
/// mis-assembled.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

namespace emb {

/// Compressed-column sparse matrix used for iteration matrices.
using SparseMatrixd = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class MatrixAssembler {
 public:
  /// Starts a pass that adds into the dense `target` (rows x cols), which is zeroed first.
  /// The target's storage must outlive the pass.
  void BeginDense(Eigen::Ref<Eigen::MatrixXd> target);

  /// Starts a pass into `target` (rows x cols). If `target` is empty (0 x 0) or was not
  /// built by this assembler's last recording pass, the pass records the structure;
  /// otherwise it refills the values of the recorded structure.
  void BeginSparse(SparseMatrixd* target, int rows, int cols);

  /// target(row, col) += value.
  void Add(int row, int col, double value) {
    switch (mode_) {
      case Mode::kDense:
        dense_[static_cast<Eigen::Index>(col) * dense_stride_ + row] += value;
        return;
      case Mode::kRecord:
        AddRecord(row, col, value);
        return;
      case Mode::kRefill:
        // The structure is fixed: the k-th contribution must hit the recorded position.
        if (next_ < slot_.size() && rows_[next_] == row && cols_[next_] == col) {
          target_->valuePtr()[slot_[next_++]] += value;
          return;
        }
        StructureChanged(row, col);
      case Mode::kIdle:
        break;
    }
    NotStarted();
  }

  /// target(row0 + i, col0 + j) += block(i, j), column by column. The expression is
  /// evaluated once (coefficient access to a product expression would re-evaluate it).
  /// A block (a Block, Map or Ref of a matrix) is read in place; an expression is evaluated
  /// once first (on the stack when its size is fixed; pass a dynamic-size product evaluated
  /// into storage of your own, or it is allocated).
  template <typename Derived>
  void AddBlock(int row0, int col0, const Eigen::MatrixBase<Derived>& block) {
    const typename Eigen::internal::nested_eval<Derived, 1>::type b(block.derived());
    for (Eigen::Index j = 0; j < b.cols(); ++j)
      for (Eigen::Index i = 0; i < b.rows(); ++i)
        Add(row0 + static_cast<int>(i), col0 + static_cast<int>(j), b(i, j));
  }

  /// Ends the pass. A recording pass builds the compressed structure of the target (with
  /// duplicates summed) and fills its values. @throws InternalError if a refill pass made a
  /// different number of contributions than the recording pass.
  void Finish();
  /// Ends a pass without using it (an evaluation that failed half-way): the target's values
  /// are unspecified; the next Begin starts afresh (a recording pass records again).
  void Abandon() { mode_ = Mode::kIdle; }

  /// Contributions of the last recording pass (>= the number of structural non-zeros).
  std::size_t num_contributions() const { return rows_.size(); }

 private:
  enum class Mode { kIdle, kDense, kRecord, kRefill };
  void AddRecord(int row, int col, double value);
  [[noreturn]] void StructureChanged(int row, int col) const;
  [[noreturn]] void NotStarted() const;

  Mode mode_{Mode::kIdle};
  // Dense pass.
  double* dense_{nullptr};
  Eigen::Index dense_stride_{0};
  int dense_rows_{0}, dense_cols_{0};
  // Sparse passes.
  SparseMatrixd* target_{nullptr};
  const SparseMatrixd* recorded_for_{nullptr};  // the matrix the structure was built in
  Eigen::Index recorded_nnz_{0};
  int rows_count_{0}, cols_count_{0};
  std::vector<int> rows_, cols_;  // recorded contribution positions
  std::vector<double> values_;    // recording pass values
  std::vector<int> slot_;         // contribution -> index into the target's values
  std::size_t next_{0};           // refill: next contribution
};

}  // namespace emb
