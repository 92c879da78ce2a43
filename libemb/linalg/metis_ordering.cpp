#include "libemb/linalg/metis_ordering.h"

#include <metis.h>

#include <algorithm>
#include <mutex>
#include <numeric>

#include "libemb/common/error.h"
#include "libemb/common/signal_cleanup.h"

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
  std::vector<int> xadj(nv + 1, 0);
  std::vector<int> adj;
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
    xadj[v + 1] = static_cast<int>(adj.size());
  }
  return NestedDissectionOrdering(std::move(xadj), std::move(adj), block);
}

std::vector<int> NestedDissectionOrdering(std::vector<int> offset, std::vector<int> adj,
                                          int block) {
  static_assert(sizeof(idx_t) == sizeof(int), "METIS built with 32-bit indices expected");
  EMB_CHECK(block >= 1 && !offset.empty() && offset.back() == static_cast<int>(adj.size()));
  idx_t nvtxs = static_cast<idx_t>(offset.size() - 1);
  if (nvtxs <= 1) {
    std::vector<int> id(static_cast<size_t>(nvtxs) * block);
    std::iota(id.begin(), id.end(), 0);
    return id;
  }
  std::vector<idx_t> perm(nvtxs), iperm(nvtxs);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  // METIS swaps the process's SIGTERM handler while it runs (signal_cleanup.h): one call at
  // a time, never beside a termination.
  const int status = [&] {
    const std::lock_guard<std::mutex> lock(SignalSwappingLibraryMutex());
    return METIS_NodeND(&nvtxs, offset.data(), adj.data(), nullptr, options, perm.data(),
                        iperm.data());
  }();
  if (status != METIS_OK)
    EMB_THROW(NumericalError, "METIS_NodeND failed with status " << status << " on a graph of "
                                                                 << nvtxs << " vertices");
  std::vector<int> dof_perm(static_cast<size_t>(nvtxs) * block);
  for (idx_t k = 0; k < nvtxs; ++k)
    for (int c = 0; c < block; ++c) dof_perm[k * block + c] = static_cast<int>(perm[k]) * block + c;
  return dof_perm;
}

}  // namespace emb
