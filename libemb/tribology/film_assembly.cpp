#include "libemb/tribology/film_assembly.h"

#include <vector>

#include "libemb/common/error.h"

namespace emb::tribology {
namespace {

// d(storage_k)/d(theta_k) / A: the storage term's theta coefficient per unit area.
double StorageThetaSlope(const FilmFields& film, const StorageInputs& st, int k) {
  switch (st.term) {
    case StorageTerm::kQuasiStatic:
    case StorageTerm::kDae:
      return film.film_rate(k);
    case StorageTerm::kBackwardEuler:
      return film.film(k) / st.dt;
  }
  return 0.0;
}

// The storage's (and slack's) entry on the diagonal of column k: theta's share of the
// storage, and for kDae with the smoothed switch the slope's own change A h s'(u) u_dot.
double StorageDiagonal(const FilmFields& film, const FilmUnknowns& x, const StorageInputs& st,
                       const ColumnWeights& w, int k) {
  const double A = film.bearing().grid().node_area();
  double d = A * StorageThetaSlope(film, st, k) * w.beta[k] + w.slack[k];
  if (st.term == StorageTerm::kDae) d += A * film.film(k) * DaeStorageCurvature(x, st, k) * (*st.u_dot)[k];
  return d;
}

// Calls add(row, col, value) for every entry of dr/du with the column weights; supply rows
// get their identity entry only.
template <class Add>
void FillGeneric(const FilmFields& film, const FilmUnknowns& x, const StorageInputs& st,
                 const ColumnWeights& w, Add add) {
  const ReynoldsBearing& bearing = film.bearing();
  const BearingGrid& g = bearing.grid();
  const int N = g.num_circumferential(), m = g.num_rows();
  const double U = film.surface_speed(), dz = g.dz();
  auto put = [&](int row, int col, double v) {
    if (!bearing.is_supply(row)) add(row, col, v);
  };
  for (int i = 0; i < N; ++i) {
    const int inext = g.next(i);
    for (int j = 1; j <= m; ++j) {
      const int k = g.Unknown(i, j), b = g.Unknown(inext, j);
      const double gc = film.conductance_c(k);
      put(k, k, gc * w.alpha[k]);
      put(k, b, -gc * w.alpha[b]);
      put(b, k, -gc * w.alpha[k]);
      put(b, b, gc * w.alpha[b]);
      const int up = U >= 0.0 ? k : b;
      const double cc = U * film.face_film_c(k) * dz * w.beta[up];
      put(k, up, cc);
      put(b, up, -cc);
    }
    for (int jf = 0; jf <= m; ++jf) {
      const double gz = film.conductance_z(i * (m + 1) + jf);
      const int a = jf >= 1 ? g.Unknown(i, jf) : -1;
      const int b = jf + 1 <= m ? g.Unknown(i, jf + 1) : -1;
      if (a >= 0) {
        put(a, a, gz * w.alpha[a]);
        if (b >= 0) put(a, b, -gz * w.alpha[b]);
      }
      if (b >= 0) {
        put(b, b, gz * w.alpha[b]);
        if (a >= 0) put(b, a, -gz * w.alpha[a]);
      }
    }
  }
  const JournalFeed& feed = film.feed();
  for (int e = 0; e < feed.size(); ++e) {
    const int k = feed.unknown[e];
    put(k, k, feed.conductance[e] * w.alpha[k]);
  }
  for (int k = 0; k < g.num_unknowns(); ++k) {
    if (bearing.is_supply(k)) {
      add(k, k, 1.0);
      continue;
    }
    add(k, k, StorageDiagonal(film, x, st, w, k));
  }
}

}  // namespace

void CalcFilmResidual(const FilmFields& film, const FilmUnknowns& x, const Eigen::VectorXd& u,
                      const StorageInputs& st, Eigen::VectorXd* r, FilmBalance* balance) {
  const ReynoldsBearing& bearing = film.bearing();
  const BearingGrid& g = bearing.grid();
  const int N = g.num_circumferential(), m = g.num_rows(), n = g.num_unknowns();
  const double U = film.surface_speed(), dz = g.dz(), A = g.node_area();
  r->setZero();
  double side = 0.0;
  for (int i = 0; i < N; ++i) {
    const int inext = g.next(i);
    for (int j = 1; j <= m; ++j) {
      const int k = g.Unknown(i, j), b = g.Unknown(inext, j);
      const double theta_up = U >= 0.0 ? x.theta[k] : x.theta[b];
      const double Q = U * film.face_film_c(k) * dz * theta_up +
                       film.conductance_c(k) * (x.psi[k] - x.psi[b]);
      (*r)[k] += Q;
      (*r)[b] -= Q;
    }
    for (int jf = 0; jf <= m; ++jf) {
      const int a = jf >= 1 ? g.Unknown(i, jf) : -1;
      const int b = jf + 1 <= m ? g.Unknown(i, jf + 1) : -1;
      const double Q = film.conductance_z(i * (m + 1) + jf) *
                       ((a >= 0 ? x.psi[a] : 0.0) - (b >= 0 ? x.psi[b] : 0.0));
      if (a >= 0) (*r)[a] += Q; else side -= Q;
      if (b >= 0) (*r)[b] -= Q; else side += Q;
    }
  }
  double supply = 0.0, storage_rate = 0.0, content = 0.0;
  const JournalFeed& feed = film.feed();
  for (int e = 0; e < feed.size(); ++e) {
    const int k = feed.unknown[e];
    if (bearing.is_supply(k)) continue;
    const double q = feed.conductance[e] * (feed.supply_psi[e] - x.psi[k]);
    (*r)[k] -= q;
    supply += q;
  }
  for (int k = 0; k < n; ++k) {
    if (bearing.is_supply(k)) {
      supply += (*r)[k];
      (*r)[k] = u[k] - bearing.SupplyUnknown(k);
      continue;
    }
    const double h = film.film(k), theta = x.theta[k];
    double s = 0.0;
    switch (st.term) {
      case StorageTerm::kQuasiStatic:
        s = A * theta * film.film_rate(k);
        break;
      case StorageTerm::kBackwardEuler:
        s = A * (theta * h - (*st.previous_content)[k]) / st.dt;
        break;
      case StorageTerm::kDae:
        s = A * (h * DaeStorageSlope(x, st, k) * (*st.u_dot)[k] + theta * film.film_rate(k));
        break;
    }
    (*r)[k] += s + x.slack[k];
    storage_rate += s;
    content += A * theta * h;
  }
  if (balance) {
    balance->side_flow = side;
    balance->supply_flow = supply;
    balance->storage_rate = storage_rate;
    balance->content = content;
  }
}

void FillFilmJacobian(const FilmFields& film, const FilmUnknowns& x, const StorageInputs& st,
                      const ColumnWeights& w, CyclicBlockLu* lu) {
  // FillGeneric's entries written straight into the blocks (no index arithmetic per entry):
  // row/column k = i m + r sits in block i at r; the east neighbour couples through
  // upper(i) (row i) and lower(i + 1) (row i + 1). Supply columns are identity columns too
  // (the solver holds u = u_supply there, so r_supply = 0 and their coupling never acts; the
  // adjoint's supply components multiply dr_supply/dx = 0): a supply node then couples
  // nothing, and a column that is cavitated except at its supply nodes decouples.
  const ReynoldsBearing& bearing = film.bearing();
  const BearingGrid& g = bearing.grid();
  const int N = g.num_circumferential(), m = g.num_rows();
  const double U = film.surface_speed(), dz = g.dz();
  const std::vector<int>& feature = bearing.supply().feature;
  auto alpha = [&](int k) { return feature[k] < 0 ? w.alpha[k] : 0.0; };
  auto beta = [&](int k) { return feature[k] < 0 ? w.beta[k] : 0.0; };
  for (int i = 0; i < N; ++i) {
    const int inext = g.next(i);
    double* D = lu->diagonal_block(i);
    double* Dn = lu->diagonal_block(inext);
    double* up = lu->upper(i);
    double* lo = lu->lower(inext);
    for (int r = 0; r < m; ++r) {
      const int k = i * m + r, b = inext * m + r;
      const bool row_k = feature[k] < 0, row_b = feature[b] < 0;
      const double gc = film.conductance_c(k);
      const double ck = U >= 0.0 ? U * film.face_film_c(k) * dz * beta(k) : 0.0;
      const double cb = U < 0.0 ? U * film.face_film_c(k) * dz * beta(b) : 0.0;
      if (row_k) {
        D[r + r * m] += gc * alpha(k) + ck;
        up[r] += -gc * alpha(b) + cb;
      }
      if (row_b) {
        lo[r] += -gc * alpha(k) - ck;
        Dn[r + r * m] += gc * alpha(b) - cb;
      }
    }
    for (int jf = 0; jf <= m; ++jf) {
      const double gz = film.conductance_z(i * (m + 1) + jf);
      const int ra = jf - 1, rb = jf;  // rows below and above the face (valid if 0..m-1)
      const bool a_ok = ra >= 0, b_ok = rb < m;
      const int ka = i * m + ra, kb = i * m + rb;
      if (a_ok && feature[ka] < 0) {
        D[ra + ra * m] += gz * alpha(ka);
        if (b_ok) D[ra + rb * m] -= gz * alpha(kb);
      }
      if (b_ok && feature[kb] < 0) {
        D[rb + rb * m] += gz * alpha(kb);
        if (a_ok) D[rb + ra * m] -= gz * alpha(ka);
      }
    }
  }
  for (int i = 0; i < N; ++i) {
    double* D = lu->diagonal_block(i);
    for (int r = 0; r < m; ++r) {
      const int k = i * m + r;
      D[r + r * m] += feature[k] >= 0 ? 1.0 : StorageDiagonal(film, x, st, w, k);
    }
  }
  const JournalFeed& feed = film.feed();
  for (int e = 0; e < feed.size(); ++e) {
    const int k = feed.unknown[e];
    if (feature[k] >= 0) continue;
    const int r = k % m;
    lu->diagonal_block(k / m)[r + r * m] += feed.conductance[e] * w.alpha[k];
  }
}

void FillFilmJacobian(const FilmFields& film, const FilmUnknowns& x, const StorageInputs& st,
                      const ColumnWeights& w, Eigen::SparseMatrix<double>* J) {
  const int n = film.bearing().num_unknowns();
  if (J->rows() != n || J->nonZeros() == 0) {
    // The pattern: every entry the fill can touch, with all weights set.
    std::vector<Eigen::Triplet<double>> t;
    std::vector<double> ones(n, 1.0);
    const ColumnWeights all{ones.data(), ones.data(), ones.data()};
    FillGeneric(film, x, st, all, [&](int row, int col, double) { t.emplace_back(row, col, 0.0); });
    // Entries a supply row skips are still in the pattern (other columns may use them).
    const BearingGrid& g = film.bearing().grid();
    for (int k = 0; k < n; ++k) {
      const int i = g.column_of(k), j = g.row_of(k);
      for (int other : {g.Unknown(g.next(i), j), g.Unknown(g.previous(i), j)}) t.emplace_back(k, other, 0.0);
      if (j > 1) t.emplace_back(k, k - 1, 0.0);
      if (j < g.num_rows()) t.emplace_back(k, k + 1, 0.0);
    }
    J->resize(n, n);
    J->setFromTriplets(t.begin(), t.end());
    J->makeCompressed();
  }
  std::fill(J->valuePtr(), J->valuePtr() + J->nonZeros(), 0.0);
  FillGeneric(film, x, st, w, [&](int row, int col, double v) { J->coeffRef(row, col) += v; });
}

void AddFilmJacobianRowSums(const FilmFields& film, const FilmUnknowns& x,
                            const StorageInputs& st, const ColumnWeights& w,
                            Eigen::VectorXd* out) {
  FillGeneric(film, x, st, w, [&](int row, int, double v) { (*out)[row] += v; });
}

void AddAdjointKinematicTerms(const FilmFields& film, const FilmUnknowns& x,
                              const StorageInputs& st, const Eigen::MatrixXd& lambda,
                              std::vector<double>* scratch,
                              Eigen::Matrix<double, 6, KinematicsLayout::kNumPositions>* d_position,
                              Eigen::Matrix<double, 6, 6>* d_velocity) {
  using L = KinematicsLayout;
  constexpr int kLoads = 6;
  const ReynoldsBearing& bearing = film.bearing();
  const BearingGrid& g = bearing.grid();
  const int N = g.num_circumferential(), m = g.num_rows(), n = g.num_unknowns();
  const double U = film.surface_speed(), dz = g.dz(), A = g.node_area(), R = g.radius();
  const std::vector<int>& feature = bearing.supply().feature;
  // lambda^T dr/dx = sum over fluxes Q (a -> b) of (lambda_a - lambda_b) dQ/dx, plus the
  // storage terms; supply rows (dr/dx = 0) get lambda = 0, and so does the ambient "node" n
  // beyond the edges. Rows of six loads, contiguous: the per-face work vectorises.
  scratch->resize(static_cast<std::size_t>(n + 1) * kLoads);
  double* lam = scratch->data();
  for (int k = 0; k < n; ++k)
    for (int l = 0; l < kLoads; ++l) lam[k * kLoads + l] = feature[k] < 0 ? lambda(k, l) : 0.0;
  for (int l = 0; l < kLoads; ++l) lam[n * kLoads + l] = 0.0;
  // dh/dx = -(c, s, z c, z s) (FilmGradient): accumulate sum w (c, s, z c, z s) per load.
  double pc[kLoads] = {}, ps[kLoads] = {}, pzc[kLoads] = {}, pzs[kLoads] = {};
  double omega[kLoads] = {};
  double rc[kLoads] = {}, rs[kLoads] = {}, rzc[kLoads] = {}, rzs[kLoads] = {};
  auto face = [&](int a, int b, double dQ_dh, double c, double s, double z) {
    const double* la = lam + a * kLoads;
    const double* lb = lam + b * kLoads;
    const double wc = dQ_dh * c, ws = dQ_dh * s, wzc = wc * z, wzs = ws * z;
    for (int l = 0; l < kLoads; ++l) {
      const double d = la[l] - lb[l];
      pc[l] += d * wc;
      ps[l] += d * ws;
      pzc[l] += d * wzc;
      pzs[l] += d * wzs;
    }
  };
  for (int i = 0; i < N; ++i) {
    const int inext = g.next(i);
    const double cf = g.cos_face(i), sf = g.sin_face(i);
    for (int j = 1; j <= m; ++j) {
      const int k = g.Unknown(i, j), b = g.Unknown(inext, j);
      const double theta_up = U >= 0.0 ? x.theta[k] : x.theta[b];
      const double h = film.face_film_c(k);
      const double dQ_domega = 0.5 * R * h * dz * theta_up;
      const double* la = lam + k * kLoads;
      const double* lb = lam + b * kLoads;
      for (int l = 0; l < kLoads; ++l) omega[l] += (la[l] - lb[l]) * dQ_domega;
      if (film.face_floored_c(k)) continue;
      const double dQ_dh =
          U * dz * theta_up + 3.0 * film.conductance_c(k) / h * (x.psi[k] - x.psi[b]);
      face(k, b, dQ_dh, cf, sf, g.axial(j));
    }
    const double c = g.cos_node(i), s = g.sin_node(i);
    for (int jf = 0; jf <= m; ++jf) {
      const int f = i * (m + 1) + jf;
      if (film.face_floored_z(f)) continue;
      const int a = jf >= 1 ? g.Unknown(i, jf) : n;
      const int b = jf + 1 <= m ? g.Unknown(i, jf + 1) : n;
      const double dQ_dh = 3.0 * film.conductance_z(f) / film.face_film_z(f) *
                           ((a < n ? x.psi[a] : 0.0) - (b < n ? x.psi[b] : 0.0));
      face(a, b, dQ_dh, c, s, g.axial(jf) + 0.5 * dz);
    }
  }
  for (int k = 0; k < n; ++k) {
    if (feature[k] >= 0) continue;
    const int i = g.column_of(k);
    const double c = g.cos_node(i), s = g.sin_node(i), z = g.axial(g.row_of(k));
    double position_scale = 0.0, rate_scale = 0.0;
    switch (st.term) {
      case StorageTerm::kQuasiStatic:
        rate_scale = A * x.theta[k];
        break;
      case StorageTerm::kBackwardEuler:
        if (!film.film_floored(k)) position_scale = A * x.theta[k] / st.dt;
        break;
      case StorageTerm::kDae:
        if (!film.film_floored(k)) position_scale = A * DaeStorageSlope(x, st, k) * (*st.u_dot)[k];
        rate_scale = A * x.theta[k];
        break;
    }
    if (position_scale != 0.0) face(k, n, position_scale, c, s, z);
    if (rate_scale != 0.0) {
      const double* lk = lam + k * kLoads;
      const double wc = rate_scale * c, ws = rate_scale * s;
      for (int l = 0; l < kLoads; ++l) {
        rc[l] += lk[l] * wc;
        rs[l] += lk[l] * ws;
        rzc[l] += lk[l] * wc * z;
        rzs[l] += lk[l] * ws * z;
      }
    }
  }
  // The journal holes' feed: dr_k/dpsi = dG_k/dpsi (Psi_k - Psi_s).
  double angle[kLoads] = {};
  const JournalFeed& feed = film.feed();
  for (int e = 0; e < feed.size(); ++e) {
    const int k = feed.unknown[e];
    const double dr = feed.conductance_slope[e] * (x.psi[k] - feed.supply_psi[e]);
    for (int l = 0; l < kLoads; ++l) angle[l] += lam[k * kLoads + l] * dr;
  }
  // d_position -= lambda^T dr/dx with dr/dx = -sum w (c, s, z c, z s); likewise the rates.
  for (int l = 0; l < kLoads; ++l) {
    (*d_position)(l, L::kJournalAngle) -= angle[l];
    (*d_position)(l, L::kEx) += pc[l];
    (*d_position)(l, L::kEy) += ps[l];
    (*d_position)(l, L::kTiltX) += pzc[l];
    (*d_position)(l, L::kTiltY) += pzs[l];
    (*d_velocity)(l, L::kEdotX) += rc[l];
    (*d_velocity)(l, L::kEdotY) += rs[l];
    (*d_velocity)(l, L::kTiltDotX) += rzc[l];
    (*d_velocity)(l, L::kTiltDotY) += rzs[l];
    (*d_velocity)(l, L::kOmegaJournal) -= omega[l];
    (*d_velocity)(l, L::kOmegaShell) -= omega[l];
  }
}

void CalcFilmKinematicJacobian(const FilmFields& film, const FilmUnknowns& x,
                               const StorageInputs& st,
                               Eigen::MatrixXd* dr_dx, Eigen::MatrixXd* dr_dv) {
  using L = KinematicsLayout;
  const ReynoldsBearing& bearing = film.bearing();
  const BearingGrid& g = bearing.grid();
  const int N = g.num_circumferential(), m = g.num_rows(), n = g.num_unknowns();
  const double U = film.surface_speed(), dz = g.dz(), A = g.node_area(), R = g.radius();
  dr_dx->setZero(n, L::kNumPositions);
  dr_dv->setZero(n, L::kNumVelocities);
  // Adds dQ/dh dh/dx (and dQ/domega) of a flux from a to b.
  auto scatter = [&](int a, int b, double dQ_dh, const Eigen::Vector4d& dh_dx, double dQ_domega) {
    if (a >= 0 && !bearing.is_supply(a)) {
      dr_dx->row(a).head<4>() += dQ_dh * dh_dx.transpose();
      (*dr_dv)(a, L::kOmegaJournal) += dQ_domega;
      (*dr_dv)(a, L::kOmegaShell) += dQ_domega;
    }
    if (b >= 0 && !bearing.is_supply(b)) {
      dr_dx->row(b).head<4>() -= dQ_dh * dh_dx.transpose();
      (*dr_dv)(b, L::kOmegaJournal) -= dQ_domega;
      (*dr_dv)(b, L::kOmegaShell) -= dQ_domega;
    }
  };
  for (int i = 0; i < N; ++i) {
    const int inext = g.next(i);
    for (int j = 1; j <= m; ++j) {
      const int k = g.Unknown(i, j), b = g.Unknown(inext, j);
      const double theta_up = U >= 0.0 ? x.theta[k] : x.theta[b];
      const double h = film.face_film_c(k);
      const Eigen::Vector4d dh_dx = film.face_floored_c(k)
                                        ? Eigen::Vector4d::Zero()
                                        : FilmFields::FilmGradient(g.cos_face(i), g.sin_face(i),
                                                                   g.axial(j));
      const double dQ_dh =
          U * dz * theta_up + 3.0 * film.conductance_c(k) / h * (x.psi[k] - x.psi[b]);
      scatter(k, b, dQ_dh, dh_dx, 0.5 * R * h * dz * theta_up);
    }
    for (int jf = 0; jf <= m; ++jf) {
      const int f = i * (m + 1) + jf;
      const int a = jf >= 1 ? g.Unknown(i, jf) : -1;
      const int b = jf + 1 <= m ? g.Unknown(i, jf + 1) : -1;
      const double h = film.face_film_z(f);
      const Eigen::Vector4d dh_dx =
          film.face_floored_z(f) ? Eigen::Vector4d::Zero()
                                 : FilmFields::FilmGradient(g.cos_node(i), g.sin_node(i),
                                                            g.axial(jf) + 0.5 * dz);
      const double dQ_dh = 3.0 * film.conductance_z(f) / h *
                           ((a >= 0 ? x.psi[a] : 0.0) - (b >= 0 ? x.psi[b] : 0.0));
      scatter(a, b, dQ_dh, dh_dx, 0.0);
    }
  }
  for (int k = 0; k < n; ++k) {
    if (bearing.is_supply(k)) continue;
    const int i = g.column_of(k);
    const double z = g.axial(g.row_of(k));
    const double c = g.cos_node(i), s = g.sin_node(i);
    const Eigen::Vector4d dh_dx =
        film.film_floored(k) ? Eigen::Vector4d::Zero() : FilmFields::FilmGradient(c, s, z);
    // dh_dot/d(e_dot, gamma_dot) has the same form as dh/dx (T1 differentiated in time).
    const Eigen::Vector4d dhdot_dv = FilmFields::FilmGradient(c, s, z);
    switch (st.term) {
      case StorageTerm::kQuasiStatic:
        dr_dv->row(k).head<4>() += A * x.theta[k] * dhdot_dv.transpose();
        break;
      case StorageTerm::kBackwardEuler:
        dr_dx->row(k).head<4>() += A * x.theta[k] / st.dt * dh_dx.transpose();
        break;
      case StorageTerm::kDae:
        dr_dx->row(k).head<4>() +=
            A * DaeStorageSlope(x, st, k) * (*st.u_dot)[k] * dh_dx.transpose();
        dr_dv->row(k).head<4>() += A * x.theta[k] * dhdot_dv.transpose();
        break;
    }
  }
  const JournalFeed& feed = film.feed();
  for (int e = 0; e < feed.size(); ++e) {
    const int k = feed.unknown[e];
    if (bearing.is_supply(k)) continue;
    (*dr_dx)(k, L::kJournalAngle) +=
        feed.conductance_slope[e] * (x.psi[k] - feed.supply_psi[e]);
  }
}

}  // namespace emb::tribology
