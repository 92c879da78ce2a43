#include "libemb/linalg/metis_ordering.h"

#include <metis.h>

#include <algorithm>
#include <numeric>

#include "libemb/common/error.h"

namespace emb {

std::vector<int> NestedDissectionOrdering(const SparseMatrix& A, int block) {
  EMB_CHECK(A.rows() == A.cols());
  const int n = static_cast<int>(A.rows());
  if (block < 1 || n % block != 0) block = 1;
  const int nv = n / block;
  if (nv <= 1) {
    std::vector<int> id(n);
    std::iota(id.begin(), id.end(), 0);
    return id;
  }
  // Adjacency of the block graph, without self loops (METIS requirement).
  std::vector<idx_t> xadj(nv + 1, 0);
  std::vector<idx_t> adj;
  adj.reserve(static_cast<size_t>(A.nonZeros() / (block * block) + nv));
  std::vector<int> mark(nv, -1);
  for (int v = 0; v < nv; ++v) {
    for (int c = 0; c < block; ++c) {
      const int col = v * block + c;
      for (SparseMatrix::InnerIterator it(A, col); it; ++it) {
        const int w = static_cast<int>(it.row()) / block;
        if (w != v && mark[w] != v) {
          mark[w] = v;
          adj.push_back(w);
        }
      }
    }
    xadj[v + 1] = static_cast<idx_t>(adj.size());
  }
  idx_t nvtxs = nv;
  std::vector<idx_t> perm(nv), iperm(nv);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  const int status =
      METIS_NodeND(&nvtxs, xadj.data(), adj.data(), nullptr, options, perm.data(), iperm.data());
  if (status != METIS_OK)
    EMB_THROW(NumericalError, "METIS_NodeND failed with status " << status << " on a graph of "
                                                                 << nv << " vertices");
  std::vector<int> dof_perm(n);
  for (int k = 0; k < nv; ++k)
    for (int c = 0; c < block; ++c) dof_perm[k * block + c] = static_cast<int>(perm[k]) * block + c;
  return dof_perm;
}

}  // namespace emb
