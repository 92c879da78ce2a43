#pragma once
/// @file
/// Fill-reducing nested-dissection ordering (METIS_NodeND) of a symmetric sparse matrix.

#include <vector>

#include "libemb/linalg/sparse_types.h"

namespace emb {

/// Returns perm with A(perm, perm) the matrix to factor (row k of the permuted matrix is row
/// perm[k] of A). If `block` > 1 and divides n, the graph of `block`×`block` node blocks is
/// ordered (9× fewer edges for 3-D solids) and expanded, keeping each block's unknowns
/// together. @throws NumericalError if METIS fails.
std::vector<int> NestedDissectionOrdering(const SparseMatrix& A, int block);

/// The same for a graph in CSR form — the neighbours of vertex v are adj[offset[v] …
/// offset[v+1]), without v itself — whose vertex v stands for the `block` unknowns
/// block·v … block·v + block − 1 (e.g. a mesh's node graph and 3 unknowns per node).
/// @throws NumericalError if METIS fails.
std::vector<int> NestedDissectionOrdering(std::vector<int> offset, std::vector<int> adj,
                                          int block);

}  // namespace emb
