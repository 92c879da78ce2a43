#include "libemb/tribology/film_loads.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace emb::tribology {
namespace {

// Boundary friction changes sign with the sliding speed R (omega_j - omega_s); tanh over
// 1 mm/s keeps it smooth (and its Jacobian finite) without changing it at running speeds.
constexpr double kSlidingRegularisation = 1e-3;  // [m/s]

}  // namespace

void CalcBearingLoads(const FilmFields& film, const FilmUnknowns& x, const FilmBalance& balance,
                      BearingLoads* out, LoadPartials* d) {
  using KL = KinematicsLayout;
  using LL = LoadLayout;
  const ReynoldsBearing& bearing = film.bearing();
  const ReynoldsBearingParameters& par = bearing.parameters();
  const BearingGrid& g = bearing.grid();
  const Lubricant& oil = bearing.lubricant();
  const JournalKinematics& kin = film.kinematics();
  const int N = g.num_circumferential(), m = g.num_rows(), nz = g.num_axial_intervals();
  const int n = g.num_unknowns();
  const double R = g.radius(), dphi = g.dphi();
  const double dw = kin.shell_speed - kin.journal_speed;  // omega_s - omega_j
  const bool half = par.cavitation == CavitationModel::kHalfSommerfeld;
  const Eigen::Vector2d tilt = kin.tilt - par.bore_tilt;
  const Eigen::VectorXd* dh = kin.film_offset;
  const double floor = bearing.contact() ? par.film_floor * bearing.contact()->roughness() : 0.0;

  BearingLoads L;
  if (d) {
    d->d_unknowns.setZero(LL::kNumLoads, n);
    d->d_position.setZero();
    d->d_velocity.setZero();
  }
  double pressure_torque = 0.0, couette = 0.0;  // T_p, sum w theta mu / h
  double Fx = 0.0, Fy = 0.0, Mx = 0.0, My = 0.0;
  // d(T_p)/dx = 1/2 sum A p (s, -c, z s, -z c); d(sum w theta mu / h)/dx (h: FilmGradient).
  double tp_dx[4] = {}, cou_dx[4] = {};
  double p_max = -std::numeric_limits<double>::infinity();
  int p_max_k = 0, cavitated = 0, free_nodes = 0;
  const bool piezo = oil.piezoviscous();
  const double mu0 = oil.ambient_viscosity();
  const Eigen::Vector2d e = kin.eccentricity;
  double* du = d ? d->d_unknowns.data() : nullptr;  // 6 x n, column-major
  // Interior nodes: pressure loads, pressure torque, Couette shear.
  for (int k = 0; k < n; ++k) {
    const int i = g.column_of(k), j = g.row_of(k);
    const double c = g.cos_node(i), s = g.sin_node(i), z = g.axial(j);
    const double A = g.quadrature_area(j);
    const double p_raw = x.pressure[k];
    const double p = half ? std::max(p_raw, 0.0) : p_raw;
    const double dp_du = (half && p_raw < 0.0) ? 0.0 : x.dp_dpsi[k] * x.dpsi_du[k];
    // dh/dphi at the node (T1): e(z) . (sin, -cos) plus the offset's central difference.
    double dh_dphi = (e.x() + z * tilt.x()) * s - (e.y() + z * tilt.y()) * c;
    if (dh)
      dh_dphi += ((*dh)[g.Node(g.next(i), j)] - (*dh)[g.Node(g.previous(i), j)]) / (2.0 * dphi);
    const double Ap = A * p;
    Fx -= Ap * c;
    Fy -= Ap * s;
    Mx += Ap * z * s;
    My -= Ap * z * c;
    pressure_torque += 0.5 * Ap * dh_dphi;
    if (p_raw > p_max) {
      p_max = p_raw;
      p_max_k = k;
    }
    if (!bearing.is_supply(k)) {
      ++free_nodes;
      if (p_raw <= 0.0 && (x.theta[k] < 1.0 || x.slack[k] < 0.0)) ++cavitated;
    }
    double dmu_dp = 0.0;
    const double mu = piezo ? oil.Viscosity(p_raw, &dmu_dp) : mu0;
    const double h = film.film(k);
    const double shear = A * x.theta[k] * mu / h;
    couette += shear;
    if (!d) continue;
    double* col = du + static_cast<std::size_t>(k) * LL::kNumLoads;
    col[LL::kFx] = -A * c * dp_du;
    col[LL::kFy] = -A * s * dp_du;
    col[LL::kMx] = A * z * s * dp_du;
    col[LL::kMy] = -A * z * c * dp_du;
    const double dTp = 0.5 * A * dh_dphi * dp_du;
    const double dTc = R * R * dw * A / h *
                       (x.dtheta_du[k] * mu + x.theta[k] * dmu_dp * x.dp_dpsi[k] * x.dpsi_du[k]);
    col[LL::kJournalTorque] = dTp + dTc;
    col[LL::kShellTorque] = dTp - dTc;
    const double half_ap = 0.5 * Ap;
    tp_dx[0] += half_ap * s;
    tp_dx[1] -= half_ap * c;
    tp_dx[2] += half_ap * z * s;
    tp_dx[3] -= half_ap * z * c;
    if (!film.film_floored(k)) {  // d(1/h)/dx = -dh/dx / h^2 = (c, s, z c, z s) / h^2
      const double q = shear / h;
      cou_dx[0] += q * c;
      cou_dx[1] += q * s;
      cou_dx[2] += q * z * c;
      cou_dx[3] += q * z * s;
    }
  }
  L.force = Eigen::Vector2d(Fx, Fy);
  L.moment = Eigen::Vector2d(Mx, My);
  if (d)
    for (int q = 0; q < 4; ++q) {
      const double dTc_dx = R * R * dw * cou_dx[q];
      d->d_position(LL::kJournalTorque, q) += tp_dx[q] + dTc_dx;
      d->d_position(LL::kShellTorque, q) += tp_dx[q] - dTc_dx;
    }
  // Edge rows: Couette shear with the neighbour's fill fraction; asperity contact everywhere.
  const std::vector<double>& h_node = film.node_film();
  const std::optional<AsperityContact>& contact = bearing.contact();
  double contact_load = 0.0, dcontact_dv = 0.0;  // sum w p_c, for boundary friction
  Eigen::Vector4d dcontact_load_dx = Eigen::Vector4d::Zero();
  for (int i = 0; i < N; ++i) {
    const double c = g.cos_node(i), s = g.sin_node(i);
    for (int j = 0; j <= nz; ++j) {
      const bool edge = j == 0 || j == nz;
      const double w = g.quadrature_area(j);
      const double z = g.axial(j);
      const double h = h_node[g.Node(i, j)];
      const Eigen::Vector4d dh_dx = FilmFields::FilmGradient(c, s, z);
      if (edge) {
        const int k = g.Unknown(i, j == 0 ? 1 : m);
        const double hf = std::max(h, floor);
        const double mu0 = oil.ambient_viscosity();
        couette += w * x.theta[k] * mu0 / hf;
        if (d) {
          d->d_unknowns(LL::kJournalTorque, k) += R * R * dw * w * x.dtheta_du[k] * mu0 / hf;
          d->d_unknowns(LL::kShellTorque, k) -= R * R * dw * w * x.dtheta_du[k] * mu0 / hf;
          if (h >= floor) {
            const Eigen::Vector4d dTc = -R * R * dw * w * x.theta[k] * mu0 / (hf * hf) * dh_dx;
            d->d_position.row(LL::kJournalTorque).head<4>() += dTc.transpose();
            d->d_position.row(LL::kShellTorque).head<4>() -= dTc.transpose();
          }
        }
      }
      if (!contact) continue;
      double dpc_dh = 0.0;
      const double pc = contact->Pressure(h, &dpc_dh);
      if (pc == 0.0) continue;
      L.contact_force -= w * pc * Eigen::Vector2d(c, s);
      L.moment += w * pc * z * Eigen::Vector2d(s, -c);
      L.max_contact_pressure = std::max(L.max_contact_pressure, pc);
      contact_load += w * pc;
      if (d) {
        const Eigen::Matrix<double, 4, 1> dpc_dx = dpc_dh * dh_dx;
        d->d_position.row(LL::kFx).head<4>() -= w * c * dpc_dx.transpose();
        d->d_position.row(LL::kFy).head<4>() -= w * s * dpc_dx.transpose();
        d->d_position.row(LL::kMx).head<4>() += w * z * s * dpc_dx.transpose();
        d->d_position.row(LL::kMy).head<4>() -= w * z * c * dpc_dx.transpose();
        dcontact_load_dx += w * dpc_dx;
      }
    }
  }
  L.force += L.contact_force;
  // Torques: pressure part on both surfaces, Couette part opposite, boundary friction.
  const double Tc = R * R * dw * couette;
  double friction = 0.0;  // boundary friction torque on the journal
  if (contact && contact_load > 0.0) {
    const double fb = contact->boundary_friction();
    const double t = std::tanh(-dw * R / kSlidingRegularisation);  // sign(omega_j - omega_s)
    friction = -fb * R * contact_load * t;
    dcontact_dv = -fb * R * contact_load * (1.0 - t * t) * R / kSlidingRegularisation;
    if (d) {
      d->d_position.row(LL::kJournalTorque).head<4>() +=
          (-fb * R * t) * dcontact_load_dx.transpose();
      d->d_position.row(LL::kShellTorque).head<4>() -=
          (-fb * R * t) * dcontact_load_dx.transpose();
    }
  }
  L.journal_torque = pressure_torque + Tc + friction;
  L.shell_torque = pressure_torque - Tc - friction;
  if (d) {
    const double dTc_domega = R * R * couette;  // dTc/domega_s; -dTc/domega_j
    d->d_velocity(LL::kJournalTorque, KL::kOmegaJournal) += -dTc_domega + dcontact_dv;
    d->d_velocity(LL::kJournalTorque, KL::kOmegaShell) += dTc_domega - dcontact_dv;
    d->d_velocity(LL::kShellTorque, KL::kOmegaJournal) += dTc_domega - dcontact_dv;
    d->d_velocity(LL::kShellTorque, KL::kOmegaShell) += -dTc_domega + dcontact_dv;
  }
  // Flows.
  L.side_flow = balance.side_flow;
  L.supply_flow = balance.supply_flow;
  L.storage_rate = balance.storage_rate;
  L.content = balance.content;
  L.cavitated_fraction = free_nodes > 0 ? static_cast<double>(cavitated) / free_nodes : 0.0;
  // Peak pressure.
  L.max_pressure = p_max;
  L.max_pressure_angle = g.angle(g.column_of(p_max_k));
  L.max_pressure_axial = g.axial(g.row_of(p_max_k));
  // Minimum film.
  if (!dh) {
    const Eigen::Vector2d e_lo = kin.eccentricity - 0.5 * g.length() * tilt;
    const Eigen::Vector2d e_hi = kin.eccentricity + 0.5 * g.length() * tilt;
    const bool aligned = tilt.squaredNorm() == 0.0;
    const Eigen::Vector2d& e = aligned ? kin.eccentricity : (e_hi.norm() >= e_lo.norm() ? e_hi : e_lo);
    L.min_film = par.clearance - e.norm();
    L.min_film_angle = std::atan2(e.y(), e.x());
    L.min_film_axial = aligned ? 0.0 : (e_hi.norm() >= e_lo.norm() ? 0.5 : -0.5) * g.length();
  } else {
    const int node = film.min_film_node();
    const int i = node / (nz + 1), j = node % (nz + 1);
    const double h0 = h_node[g.Node(g.previous(i), j)], h1 = h_node[node],
                 h2 = h_node[g.Node(g.next(i), j)];
    const double curvature = h0 - 2.0 * h1 + h2;
    double shift = 0.0, hmin = h1;
    if (curvature > 0.0) {
      shift = 0.5 * (h0 - h2) / curvature;  // in units of dphi, within [-1/2, 1/2]
      hmin = h1 - 0.25 * (h0 - h2) * shift;
    }
    L.min_film = hmin;
    L.min_film_angle = g.angle(i) + shift * dphi;
    L.min_film_axial = g.axial(j);
  }
  L.power_loss = -(L.force.dot(kin.eccentricity_rate) + L.moment.y() * kin.tilt_rate.x() -
                   L.moment.x() * kin.tilt_rate.y() + L.journal_torque * kin.journal_speed +
                   L.shell_torque * kin.shell_speed);
  *out = L;
}

}  // namespace emb::tribology
