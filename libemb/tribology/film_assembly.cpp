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

// Calls add(row, col, value) for every entry of dr/du with the column weights; supply rows
// get their identity entry only.
template <class Add>
void FillGeneric(const FilmFields& film, const FilmUnknowns& x, const StorageInputs& st,
                 const ColumnWeights& w, Add add) {
  const ReynoldsBearing& bearing = film.bearing();
  const BearingGrid& g = bearing.grid();
  const int N = g.num_circumferential(), m = g.num_rows();
  const double U = film.surface_speed(), dz = g.dz(), A = g.node_area();
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
  for (int k = 0; k < g.num_unknowns(); ++k) {
    if (bearing.is_supply(k)) {
      add(k, k, 1.0);
      continue;
    }
    add(k, k, A * StorageThetaSlope(film, st, k) * w.beta[k] + w.slack[k]);
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
        s = A * (h * x.dtheta_du[k] * (*st.u_dot)[k] + theta * film.film_rate(k));
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
  const BearingGrid& g = film.bearing().grid();
  const int m = g.num_rows();
  FillGeneric(film, x, st, w, [&](int row, int col, double v) {
    const int ir = row / m, rr = row % m, ic = col / m, rc = col % m;
    if (ir == ic)
      lu->diagonal_block(ir)[rr + rc * m] += v;
    else if (ic == g.previous(ir))
      lu->lower(ir)[rr] += v;
    else
      lu->upper(ir)[rr] += v;
  });
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
      dr_dx->row(a) += dQ_dh * dh_dx.transpose();
      (*dr_dv)(a, L::kOmegaJournal) += dQ_domega;
      (*dr_dv)(a, L::kOmegaShell) += dQ_domega;
    }
    if (b >= 0 && !bearing.is_supply(b)) {
      dr_dx->row(b) -= dQ_dh * dh_dx.transpose();
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
        dr_dx->row(k) += A * x.theta[k] / st.dt * dh_dx.transpose();
        break;
      case StorageTerm::kDae:
        dr_dx->row(k) += A * x.dtheta_du[k] * (*st.u_dot)[k] * dh_dx.transpose();
        dr_dv->row(k).head<4>() += A * x.theta[k] * dhdot_dv.transpose();
        break;
    }
  }
}

}  // namespace emb::tribology
