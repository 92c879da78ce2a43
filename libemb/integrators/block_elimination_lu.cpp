#include "libemb/integrators/block_elimination_lu.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <utility>

#include "libemb/common/error.h"

namespace emb {

struct BlockEliminationLu::Structure {
  // The analysed structure of A (to notice a change).
  std::int64_t n{0};
  std::vector<std::int64_t> col_start, row_index;
  std::vector<int> block_of;  // per unknown: its block, or -1 for R
  std::vector<int> local;     // per unknown: index in its block, or in R
  std::vector<int> rest;      // R: global index of each compact index
  struct Block {
    std::vector<int> unknowns;  // global indices
    std::vector<int> rows;      // compact R indices i with A(i, block) != 0 (sorted)
    std::vector<int> cols;      // compact R indices j with A(block, j) != 0 (sorted)
    Eigen::MatrixXd A, AER, ARE, Y;  // A_i, A_iR, A_Ri, A_i^-1 A_iR
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    std::vector<std::int64_t> schur_slot;  // rows x cols (column-major): index into S values
    Eigen::VectorXd t;                     // scratch: A_i^-1 b_i
  };
  std::vector<Block> blocks;
  // Where entry k of A goes.
  enum class Kind : char { kBlock, kBlockRest, kRestBlock, kRest };
  std::vector<Kind> kind;
  std::vector<int> which, at_i, at_j;  // block; local row / position; local column / position
  std::vector<std::int64_t> rest_slot;  // kRest: index into S values
  // The Schur complement (compressed columns, R x R).
  std::vector<std::int64_t> s_col_start, s_row_index;
  std::vector<double> s_values;
  Eigen::VectorXd xr;  // scratch: the R part of a solution
};

BlockEliminationLu::BlockEliminationLu(std::vector<std::vector<int>> blocks)
    : requested_(std::move(blocks)) {
  std::vector<int> all;
  for (const auto& b : requested_) {
    for (int i : b) EMB_THROW_IF(i < 0, "block elimination: negative unknown index " << i);
    all.insert(all.end(), b.begin(), b.end());
  }
  std::sort(all.begin(), all.end());
  EMB_THROW_IF(std::adjacent_find(all.begin(), all.end()) != all.end(),
               "block elimination: an unknown is in two blocks");
}

BlockEliminationLu::~BlockEliminationLu() = default;

std::vector<int> BlockEliminationLu::block_sizes() const {
  std::vector<int> s;
  if (st_)
    for (const auto& b : st_->blocks) s.push_back(static_cast<int>(b.unknowns.size()));
  return s;
}

void BlockEliminationLu::Analyze(const CscView& a) {
  auto st = std::make_unique<Structure>();
  const std::int64_t n = a.n;
  const std::int64_t nnz = a.col_start[n];
  st->n = n;
  st->col_start.assign(a.col_start, a.col_start + n + 1);
  st->row_index.assign(a.row_index, a.row_index + nnz);

  // Requested blocks, merged where the matrix couples two of them (union-find).
  std::vector<int> block_of(static_cast<std::size_t>(n), -1);
  for (std::size_t b = 0; b < requested_.size(); ++b)
    for (int i : requested_[b]) {
      EMB_THROW_IF(i >= n, "block elimination: unknown " << i << " of a block is beyond the "
                                                         << n << " unknowns of the matrix");
      block_of[i] = static_cast<int>(b);
    }
  std::vector<int> parent(requested_.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t k = a.col_start[j]; k < a.col_start[j + 1]; ++k) {
      const int bi = block_of[a.row_index[k]], bj = block_of[j];
      if (bi >= 0 && bj >= 0 && bi != bj) parent[find(bi)] = find(bj);
    }
  std::vector<int> label(requested_.size(), -1);
  int num_blocks = 0;
  for (std::size_t b = 0; b < requested_.size(); ++b)
    if (!requested_[b].empty() && label[find(static_cast<int>(b))] < 0)
      label[find(static_cast<int>(b))] = num_blocks++;
  st->blocks.resize(num_blocks);
  st->block_of.assign(static_cast<std::size_t>(n), -1);
  st->local.assign(static_cast<std::size_t>(n), -1);
  for (std::int64_t i = 0; i < n; ++i) {
    if (block_of[i] < 0) {
      st->local[i] = static_cast<int>(st->rest.size());
      st->rest.push_back(static_cast<int>(i));
      continue;
    }
    const int b = label[find(block_of[i])];
    st->block_of[i] = b;
    st->local[i] = static_cast<int>(st->blocks[b].unknowns.size());
    st->blocks[b].unknowns.push_back(static_cast<int>(i));
  }
  const int nr = static_cast<int>(st->rest.size());

  // The R rows and columns each block couples to.
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t k = a.col_start[j]; k < a.col_start[j + 1]; ++k) {
      const std::int64_t i = a.row_index[k];
      const int bi = st->block_of[i], bj = st->block_of[j];
      if (bi >= 0 && bj < 0) st->blocks[bi].cols.push_back(st->local[j]);
      if (bi < 0 && bj >= 0) st->blocks[bj].rows.push_back(st->local[i]);
    }
  for (auto& b : st->blocks)
    for (std::vector<int>* v : {&b.rows, &b.cols}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }

  // The structure of S: A_RR and every block's rows x cols, as (column, row) pairs.
  std::vector<std::pair<int, int>> pairs;
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t k = a.col_start[j]; k < a.col_start[j + 1]; ++k) {
      const std::int64_t i = a.row_index[k];
      if (st->block_of[i] < 0 && st->block_of[j] < 0) pairs.emplace_back(st->local[j], st->local[i]);
    }
  for (const auto& b : st->blocks)
    for (int c : b.cols)
      for (int r : b.rows) pairs.emplace_back(c, r);
  // Every diagonal entry, so that S has a structurally full diagonal for KLU's analysis.
  for (int r = 0; r < nr; ++r) pairs.emplace_back(r, r);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  st->s_col_start.assign(static_cast<std::size_t>(nr) + 1, 0);
  st->s_row_index.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ++st->s_col_start[pairs[k].first + 1];
    st->s_row_index[k] = pairs[k].second;
  }
  for (int c = 0; c < nr; ++c) st->s_col_start[c + 1] += st->s_col_start[c];
  st->s_values.assign(pairs.size(), 0.0);
  auto slot = [&](int r, int c) {
    const auto begin = st->s_row_index.begin() + st->s_col_start[c];
    const auto end = st->s_row_index.begin() + st->s_col_start[c + 1];
    const auto it = std::lower_bound(begin, end, r);
    EMB_CHECK(it != end && *it == r);
    return static_cast<std::int64_t>(it - st->s_row_index.begin());
  };

  // Dense storage, the Schur slots of each block and the destination of every entry of A.
  std::vector<int> row_pos(static_cast<std::size_t>(nr), -1), col_pos(static_cast<std::size_t>(nr), -1);
  for (auto& b : st->blocks) {
    const auto nb = static_cast<Eigen::Index>(b.unknowns.size());
    b.A.setZero(nb, nb);
    b.AER.setZero(nb, static_cast<Eigen::Index>(b.cols.size()));
    b.ARE.setZero(static_cast<Eigen::Index>(b.rows.size()), nb);
    b.Y.setZero(nb, static_cast<Eigen::Index>(b.cols.size()));
    b.t.setZero(nb);
    b.schur_slot.resize(b.rows.size() * b.cols.size());
    for (std::size_t c = 0; c < b.cols.size(); ++c)
      for (std::size_t r = 0; r < b.rows.size(); ++r)
        b.schur_slot[c * b.rows.size() + r] = slot(b.rows[r], b.cols[c]);
  }
  st->kind.resize(static_cast<std::size_t>(nnz));
  st->which.assign(static_cast<std::size_t>(nnz), -1);
  st->at_i.assign(static_cast<std::size_t>(nnz), -1);
  st->at_j.assign(static_cast<std::size_t>(nnz), -1);
  st->rest_slot.assign(static_cast<std::size_t>(nnz), -1);
  for (std::size_t b = 0; b < st->blocks.size(); ++b) {
    const auto& blk = st->blocks[b];
    for (std::size_t p = 0; p < blk.rows.size(); ++p) row_pos[blk.rows[p]] = static_cast<int>(p);
    for (std::size_t p = 0; p < blk.cols.size(); ++p) col_pos[blk.cols[p]] = static_cast<int>(p);
    for (std::int64_t j = 0; j < n; ++j)
      for (std::int64_t k = a.col_start[j]; k < a.col_start[j + 1]; ++k) {
        const std::int64_t i = a.row_index[k];
        const int bi = st->block_of[i], bj = st->block_of[j];
        using K = Structure::Kind;
        if (bi == static_cast<int>(b) && bj == static_cast<int>(b)) {
          st->kind[k] = K::kBlock, st->which[k] = bi, st->at_i[k] = st->local[i],
          st->at_j[k] = st->local[j];
        } else if (bi == static_cast<int>(b) && bj < 0) {
          st->kind[k] = K::kBlockRest, st->which[k] = bi, st->at_i[k] = st->local[i],
          st->at_j[k] = col_pos[st->local[j]];
        } else if (bi < 0 && bj == static_cast<int>(b)) {
          st->kind[k] = K::kRestBlock, st->which[k] = bj, st->at_i[k] = row_pos[st->local[i]],
          st->at_j[k] = st->local[j];
        }
      }
  }
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t k = a.col_start[j]; k < a.col_start[j + 1]; ++k) {
      const std::int64_t i = a.row_index[k];
      if (st->block_of[i] < 0 && st->block_of[j] < 0) {
        st->kind[k] = Structure::Kind::kRest;
        st->rest_slot[k] = slot(st->local[i], st->local[j]);
      }
    }
  st->xr.setZero(nr);
  st_ = std::move(st);
}

KluStatus BlockEliminationLu::Factor(const CscView& a) {
  EMB_THROW_IF(a.n < 1 || a.col_start == nullptr || a.row_index == nullptr ||
                   a.values == nullptr || a.col_start[0] != 0,
               "block elimination: expected a square compressed-column matrix");
  message_.clear();
  factored_ = false;
  const std::int64_t nnz = a.col_start[a.n];
  const bool same = st_ && st_->n == a.n &&
                    std::equal(a.col_start, a.col_start + a.n + 1, st_->col_start.begin()) &&
                    static_cast<std::int64_t>(st_->row_index.size()) == nnz &&
                    std::equal(a.row_index, a.row_index + nnz, st_->row_index.begin());
  if (!same) Analyze(a);
  Structure& st = *st_;
  for (auto& b : st.blocks) {
    b.A.setZero();
    b.AER.setZero();
    b.ARE.setZero();
  }
  std::fill(st.s_values.begin(), st.s_values.end(), 0.0);
  using K = Structure::Kind;
  for (std::int64_t k = 0; k < nnz; ++k) {
    const double v = a.values[k];
    switch (st.kind[k]) {
      case K::kBlock:
        st.blocks[st.which[k]].A(st.at_i[k], st.at_j[k]) += v;
        break;
      case K::kBlockRest:
        st.blocks[st.which[k]].AER(st.at_i[k], st.at_j[k]) += v;
        break;
      case K::kRestBlock:
        st.blocks[st.which[k]].ARE(st.at_i[k], st.at_j[k]) += v;
        break;
      case K::kRest:
        st.s_values[st.rest_slot[k]] += v;
        break;
    }
  }
  for (auto& b : st.blocks) {
    b.lu.compute(b.A);
    ++dense_factorizations_;
    // Singular only with an exact zero (or non-finite) pivot after partial pivoting, as
    // KLU decides: the blocks of an iteration matrix are badly scaled by nature (rows of cj
    // next to rows of stiffness), so a condition estimate says nothing about singularity;
    // an inaccurate solve shows as a slow Newton iteration, which the integrator handles.
    const double min_pivot = b.lu.matrixLU().diagonal().cwiseAbs().minCoeff();
    if (!(min_pivot > 0.0) || !std::isfinite(b.lu.matrixLU().diagonal().sum())) {
      std::ostringstream o;
      o << "a dense block of " << b.A.rows() << " unknowns is singular (smallest pivot "
        << min_pivot << ")";
      message_ = o.str();
      return KluStatus::kSingular;
    }
    b.Y.noalias() = b.lu.solve(b.AER);
    // S(rows, cols) -= A_Ri Y_i.
    const Eigen::MatrixXd update = b.ARE * b.Y;
    const std::size_t nrows = b.rows.size();
    for (Eigen::Index c = 0; c < update.cols(); ++c)
      for (Eigen::Index r = 0; r < update.rows(); ++r)
        st.s_values[b.schur_slot[static_cast<std::size_t>(c) * nrows + static_cast<std::size_t>(r)]] -=
            update(r, c);
  }
  const CscView s{static_cast<std::int64_t>(st.rest.size()), st.s_col_start.data(),
                  st.s_row_index.data(), st.s_values.data()};
  const KluStatus status = schur_.Factor(s);
  if (status != KluStatus::kOk) {
    message_ = "Schur complement: " + schur_.message();
    return status;
  }
  factored_ = true;
  return KluStatus::kOk;
}

KluStatus BlockEliminationLu::Solve(double* x) {
  EMB_THROW_IF(!factored_ || !st_, "block elimination: no valid factors to solve with");
  Structure& st = *st_;
  for (std::size_t r = 0; r < st.rest.size(); ++r) st.xr[r] = x[st.rest[r]];
  for (auto& b : st.blocks) {
    for (std::size_t i = 0; i < b.unknowns.size(); ++i) b.t[i] = x[b.unknowns[i]];
    b.t = b.lu.solve(b.t);
    if (!b.rows.empty()) {
      const Eigen::VectorXd u = b.ARE * b.t;
      for (std::size_t p = 0; p < b.rows.size(); ++p) st.xr[b.rows[p]] -= u[p];
    }
  }
  const KluStatus status = schur_.Solve(st.xr.data());
  if (status != KluStatus::kOk) {
    message_ = "Schur complement: " + schur_.message();
    return status;
  }
  for (auto& b : st.blocks) {
    Eigen::VectorXd xc(static_cast<Eigen::Index>(b.cols.size()));
    for (std::size_t p = 0; p < b.cols.size(); ++p) xc[p] = st.xr[b.cols[p]];
    b.t.noalias() -= b.Y * xc;
    for (std::size_t i = 0; i < b.unknowns.size(); ++i) x[b.unknowns[i]] = b.t[i];
  }
  for (std::size_t r = 0; r < st.rest.size(); ++r) x[st.rest[r]] = st.xr[r];
  for (std::int64_t i = 0; i < st.n; ++i)
    if (!std::isfinite(x[i])) return KluStatus::kSingular;
  return KluStatus::kOk;
}

}  // namespace emb
