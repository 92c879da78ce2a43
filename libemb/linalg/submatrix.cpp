#include "libemb/linalg/submatrix.h"

#include "libemb/common/error.h"

namespace emb {

SparseMatrix ExtractSubmatrix(const SparseMatrix& A, const std::vector<int>& rows,
                              const std::vector<int>& cols) {
  std::vector<int> new_row(A.rows(), -1);
  for (size_t k = 0; k < rows.size(); ++k) {
    EMB_CHECK(rows[k] >= 0 && rows[k] < A.rows() && (k == 0 || rows[k] > rows[k - 1]));
    new_row[rows[k]] = static_cast<int>(k);
  }
  long long nnz = 0;
  for (int c : cols) {
    EMB_CHECK(c >= 0 && c < A.cols());
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) nnz += new_row[it.row()] >= 0;
  }
  SparseMatrix S(static_cast<int>(rows.size()), static_cast<int>(cols.size()));
  S.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = S.outerIndexPtr();
  int* inner = S.innerIndexPtr();
  double* val = S.valuePtr();
  long long pos = 0;
  for (size_t j = 0; j < cols.size(); ++j) {
    outer[j] = static_cast<int>(pos);
    for (SparseMatrix::InnerIterator it(A, cols[j]); it; ++it) {
      const int r = new_row[it.row()];
      if (r < 0) continue;
      inner[pos] = r;
      val[pos++] = it.value();
    }
  }
  outer[cols.size()] = static_cast<int>(pos);
  return S;
}

std::vector<int> Complement(const std::vector<int>& indices, int n) {
  std::vector<char> in(n, 0);
  for (int i : indices) {
    EMB_CHECK(i >= 0 && i < n);
    in[i] = 1;
  }
  std::vector<int> out;
  out.reserve(n - indices.size());
  for (int i = 0; i < n; ++i)
    if (!in[i]) out.push_back(i);
  return out;
}

}  // namespace emb
