// MatrixAssembler: the same contributions give the same matrix densely and sparsely; the
// sparse structure keeps explicit zeros and duplicates summed, is built once and refilled;
// a contribution sequence that changes its structure is caught.

#include "libemb/integrators/matrix_assembler.h"

#include <gtest/gtest.h>

#include "libemb/common/error.h"

namespace emb {
namespace {

// A fixed sequence of contributions: a 2x2 block, a duplicate, an entry that is zero now.
void Contribute(MatrixAssembler& a, double scale) {
  Eigen::Matrix2d block;
  block << 1, 2, 3, 4;
  a.AddBlock(0, 1, scale * block);
  a.Add(1, 1, 10.0 * scale);  // lands on an entry of the block: summed
  a.Add(3, 0, 0.0 * scale);   // structurally present, numerically zero
  a.Add(2, 3, -scale);
}

TEST(MatrixAssembler, DenseAndSparsePassesAgree) {
  MatrixAssembler a;
  Eigen::MatrixXd dense(4, 4);
  dense.setConstant(99.0);  // BeginDense zeroes it
  a.BeginDense(dense);
  Contribute(a, 1.0);
  a.Finish();
  SparseMatrixd sparse;
  a.BeginSparse(&sparse, 4, 4);
  Contribute(a, 1.0);
  a.Finish();
  EXPECT_EQ(Eigen::MatrixXd(sparse), dense);
  EXPECT_EQ(dense(1, 1), 13.0);
  // Six distinct positions, one of them an explicit zero, from seven contributions.
  EXPECT_EQ(sparse.nonZeros(), 6);
  EXPECT_EQ(a.num_contributions(), 7u);
}

TEST(MatrixAssembler, RefillKeepsTheStructureAndReplacesValues) {
  MatrixAssembler a;
  SparseMatrixd S;
  a.BeginSparse(&S, 4, 4);
  Contribute(a, 1.0);
  a.Finish();
  const int* inner_before = S.innerIndexPtr();
  a.BeginSparse(&S, 4, 4);
  Contribute(a, 2.0);
  a.Finish();
  EXPECT_EQ(S.innerIndexPtr(), inner_before);  // no reallocation: values only
  EXPECT_EQ(S.coeff(1, 1), 26.0);
  EXPECT_EQ(S.coeff(2, 3), -2.0);
  EXPECT_EQ(S.nonZeros(), 6);
}

TEST(MatrixAssembler, ChangedStructureIsAnInternalError) {
  MatrixAssembler a;
  SparseMatrixd S;
  a.BeginSparse(&S, 4, 4);
  Contribute(a, 1.0);
  a.Finish();
  a.BeginSparse(&S, 4, 4);
  a.Add(0, 1, 1.0);
  EXPECT_THROW(a.Add(3, 3, 1.0), InternalError);  // second contribution was (1, 1)
  // Fewer contributions than recorded.
  a.BeginSparse(&S, 4, 4);
  a.Add(0, 1, 1.0);
  EXPECT_THROW(a.Finish(), InternalError);
  // A new, empty matrix records afresh.
  SparseMatrixd T;
  a.BeginSparse(&T, 4, 4);
  a.Add(3, 3, 5.0);
  a.Finish();
  EXPECT_EQ(T.nonZeros(), 1);
  EXPECT_THROW(a.Add(0, 0, 1.0), InternalError);  // outside a pass
}

}  // namespace
}  // namespace emb
