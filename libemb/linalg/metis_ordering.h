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

}  // namespace emb
