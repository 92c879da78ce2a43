#include "libemb/tribology/film_fields.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "libemb/common/error.h"

namespace emb::tribology {

void FilmUnknowns::Resize(int n) {
  for (auto* v : {&psi, &theta, &pressure, &dp_dpsi, &dpsi_du, &dtheta_du, &dslack_du, &slack,
                  &slack_scale, &d2psi_du2, &d2theta_du2})
    v->assign(n, 0.0);
}

FilmFields::FilmFields(const ReynoldsBearing& bearing) : bearing_(&bearing) {
  const BearingGrid& g = bearing.grid();
  const int n = g.num_unknowns();
  h_node_.assign(g.num_nodes(), 0.0);
  h_unknown_.assign(n, 0.0);
  hdot_unknown_.assign(n, 0.0);
  h_face_c_.assign(n, 0.0);
  g_c_.assign(n, 0.0);
  const int nz_faces = g.num_circumferential() * (g.num_rows() + 1);
  h_face_z_.assign(nz_faces, 0.0);
  g_z_.assign(nz_faces, 0.0);
  floored_unknown_.assign(n, 0);
  floored_c_.assign(n, 0);
  floored_z_.assign(nz_faces, 0);
  if (bearing.contact()) floor_ = bearing.parameters().film_floor * bearing.contact()->roughness();
}

double FilmFields::Rigid(double c, double s, double z) const {
  const ReynoldsBearingParameters& p = bearing_->parameters();
  const Eigen::Vector2d ez = kin_.eccentricity + z * (kin_.tilt - p.bore_tilt);
  return p.clearance - ez.x() * c - ez.y() * s;
}

bool FilmFields::Set(const JournalKinematics& kin, std::string* message) {
  const BearingGrid& g = bearing_->grid();
  const int N = g.num_circumferential(), m = g.num_rows(), nz = g.num_axial_intervals();
  kin_ = kin;
  kin_.film_offset = kin.film_offset;
  surface_speed_ = 0.5 * g.radius() * (kin.journal_speed + kin.shell_speed);
  const Eigen::VectorXd* dh = kin.film_offset;
  const Eigen::VectorXd* dh_rate = kin.film_offset_rate;
  EMB_THROW_IF(dh && dh->size() != g.num_nodes(),
               bearing_->who() << ": expected a film offset over " << g.num_nodes()
                               << " nodes, got " << dh->size());
  EMB_THROW_IF(dh_rate && dh_rate->size() != g.num_nodes(),
               bearing_->who() << ": expected a film offset rate over " << g.num_nodes()
                               << " nodes, got " << dh_rate->size());
  const double mu0 = bearing_->lubricant().ambient_viscosity();
  const double R = g.radius(), dphi = g.dphi(), dz = g.dz();
  const double kc = dz / (12.0 * mu0 * R * dphi);
  const double kz = R * dphi / (12.0 * mu0 * dz);
  const bool contact = bearing_->contact().has_value();
  min_film_ = std::numeric_limits<double>::infinity();
  for (int i = 0; i < N; ++i) {
    const double c = g.cos_node(i), s = g.sin_node(i);
    for (int j = 0; j <= nz; ++j) {
      const int node = g.Node(i, j);
      const double h = Rigid(c, s, g.axial(j)) + (dh ? (*dh)[node] : 0.0);
      h_node_[node] = h;
      if (h < min_film_) {
        min_film_ = h;
        min_film_node_ = node;
      }
    }
  }
  if (!(min_film_ > 0.0) && !contact) {
    if (message) {
      const int i = min_film_node_ / (nz + 1), j = min_film_node_ % (nz + 1);
      std::ostringstream os;
      os << bearing_->who() << ": the journal touches the shell: film thickness " << min_film_
         << " m <= 0 at phi = " << g.angle(i) << " rad, z = " << g.axial(j)
         << " m (clearance " << bearing_->parameters().clearance
         << " m; no asperity contact model)";
      *message = os.str();
    }
    return false;
  }
  auto floored = [&](double h, char* flag) {
    *flag = h < floor_;
    return *flag ? floor_ : h;
  };
  for (int i = 0; i < N; ++i) {
    const double c = g.cos_node(i), s = g.sin_node(i);
    const double cf = g.cos_face(i), sf = g.sin_face(i);
    const int inext = g.next(i);
    for (int j = 1; j <= m; ++j) {
      const int k = g.Unknown(i, j);
      const double z = g.axial(j);
      h_unknown_[k] = floored(h_node_[g.Node(i, j)], &floored_unknown_[k]);
      const Eigen::Vector2d ez_dot = kin.eccentricity_rate + z * kin.tilt_rate;
      hdot_unknown_[k] = -(ez_dot.x() * c + ez_dot.y() * s) +
                         (dh_rate ? (*dh_rate)[g.Node(i, j)] : 0.0);
      double hf = Rigid(cf, sf, z);
      if (dh) hf += 0.5 * ((*dh)[g.Node(i, j)] + (*dh)[g.Node(inext, j)]);
      hf = floored(hf, &floored_c_[k]);
      h_face_c_[k] = hf;
      g_c_[k] = kc * hf * hf * hf;
    }
    for (int jf = 0; jf <= m; ++jf) {
      const int f = i * (m + 1) + jf;
      const double z = g.axial(jf) + 0.5 * dz;
      double hf = Rigid(c, s, z);
      if (dh) hf += 0.5 * ((*dh)[g.Node(i, jf)] + (*dh)[g.Node(i, jf + 1)]);
      hf = floored(hf, &floored_z_[f]);
      h_face_z_[f] = hf;
      g_z_[f] = kz * hf * hf * hf;
    }
  }
  if (bearing_->has_journal_holes())
    CalcJournalFeed(g, bearing_->parameters().journal_oil_holes,
                    bearing_->journal_hole_conductance(), bearing_->journal_supply_psi(),
                    kin.journal_angle, &feed_);
  return true;
}

namespace {

// Psi -> pressure for every unknown; false if Psi reaches the law's limit.
bool SetPressures(const Lubricant& oil, FilmUnknowns* x) {
  bool ok = true;
  const double psi_max = oil.reduced_pressure_limit();
  for (size_t k = 0; k < x->psi.size(); ++k) {
    if (!oil.piezoviscous()) {
      x->pressure[k] = x->psi[k];
      x->dp_dpsi[k] = 1.0;
    } else if (!(x->psi[k] < psi_max)) {
      ok = false;
      x->pressure[k] = std::numeric_limits<double>::infinity();
      x->dp_dpsi[k] = 0.0;
    } else {
      x->pressure[k] = oil.Pressure(x->psi[k], &x->dp_dpsi[k]);
    }
  }
  return ok;
}

// sigma_k of kReynolds: any positive value gives the same solution; the node's Poiseuille
// diagonal (sum of its face conductances times p_ref) keeps the column comparable with the
// pressure columns.
double SlackScale(const FilmFields& film, int k, double pref) {
  const BearingGrid& g = film.bearing().grid();
  const int i = g.column_of(k), j = g.row_of(k), m = g.num_rows();
  return pref * (film.conductance_c(k) + film.conductance_c(g.Unknown(g.previous(i), j)) +
                 film.conductance_z(i * (m + 1) + j - 1) + film.conductance_z(i * (m + 1) + j));
}

}  // namespace

bool SetUnknownsFromPairs(const ReynoldsBearing& bearing, const FilmFields& film,
                          const Eigen::VectorXd& a, const Eigen::VectorXd& b, FilmUnknowns* x) {
  const double pref = bearing.parameters().pressure_scale;
  const bool jfo = bearing.parameters().cavitation == CavitationModel::kMassConserving;
  for (int k = 0; k < bearing.num_unknowns(); ++k) {
    const bool pressurised = a[k] - b[k] >= 0.0;
    x->d2psi_du2[k] = x->d2theta_du2[k] = 0.0;
    x->psi[k] = pref * a[k];
    x->dpsi_du[k] = pressurised ? pref : 0.0;
    if (jfo) {
      x->theta[k] = 1.0 - b[k];
      x->dtheta_du[k] = pressurised ? 0.0 : 1.0;
      x->slack[k] = x->dslack_du[k] = 0.0;
    } else {
      x->theta[k] = 1.0;
      x->dtheta_du[k] = 0.0;
      x->slack_scale[k] = SlackScale(film, k, pref);
      x->slack[k] = -x->slack_scale[k] * b[k];
      x->dslack_du[k] = pressurised ? 0.0 : x->slack_scale[k];
    }
  }
  return SetPressures(bearing.lubricant(), x);
}

bool SetUnknownsFromUniversal(const ReynoldsBearing& bearing, const FilmFields& film,
                              const Eigen::VectorXd& u, FilmUnknowns* x) {
  const double pref = bearing.parameters().pressure_scale;
  const CavitationModel model = bearing.parameters().cavitation;
  const bool full_film =
      model == CavitationModel::kFullSommerfeld || model == CavitationModel::kHalfSommerfeld;
  const double w = model == CavitationModel::kMassConserving ? bearing.parameters().switch_width : 0.0;
  for (int k = 0; k < bearing.num_unknowns(); ++k) {
    const double uk = u[k];
    x->d2psi_du2[k] = x->d2theta_du2[k] = 0.0;
    if (std::abs(uk) < w) {
      // The smoothed switch: P = (u + w)^2 / (4 w) with P' = (u + w) / (2 w), matching
      // max(u, 0) in value and slope at u = -w and u = w; theta = 1 + u - P.
      const double P = (uk + w) * (uk + w) / (4.0 * w), dP = (uk + w) / (2.0 * w);
      x->psi[k] = pref * P;
      x->dpsi_du[k] = pref * dP;
      x->theta[k] = 1.0 + uk - P;
      x->dtheta_du[k] = 1.0 - dP;
      x->slack[k] = x->dslack_du[k] = 0.0;
      x->d2psi_du2[k] = pref / (2.0 * w);
      x->d2theta_du2[k] = -1.0 / (2.0 * w);
      continue;
    }
    const bool pressurised = full_film || uk >= 0.0;
    x->psi[k] = pressurised ? pref * uk : 0.0;
    x->dpsi_du[k] = pressurised ? pref : 0.0;
    const double cav = pressurised ? 0.0 : uk;  // min(u, 0)
    if (model == CavitationModel::kMassConserving) {
      x->theta[k] = 1.0 + cav;
      x->dtheta_du[k] = pressurised ? 0.0 : 1.0;
      x->slack[k] = x->dslack_du[k] = 0.0;
    } else {
      x->theta[k] = 1.0;
      x->dtheta_du[k] = 0.0;
      x->slack_scale[k] = model == CavitationModel::kReynolds ? SlackScale(film, k, pref) : 0.0;
      x->slack[k] = x->slack_scale[k] * cav;
      x->dslack_du[k] = pressurised ? 0.0 : x->slack_scale[k];
    }
  }
  return SetPressures(bearing.lubricant(), x);
}

}  // namespace emb::tribology
