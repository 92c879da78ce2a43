#include "libemb/mbs/flexible/installed_basis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/mbs/dae/linearization.h"
#include "libemb/mbs/flexible/static_compliance.h"

namespace emb::mbs {
namespace {

// Singular values below this fraction of the largest are dependent directions: far above
// the round-off of the column-normalised vectors (1e-16), far below any physical direction.
constexpr double kRankTolerance = 1e-8;
// An installed mode whose kinetic energy in the body's elastic coordinates is below this
// fraction of its total lives elsewhere (another body, the rigid motion): its eta part is
// numerical noise, not a direction of the body.
constexpr double kEnergyFraction = 1e-6;

// An M-orthonormal basis (V^T M V = I) of the span of the columns of U, each column first
// scaled by `scale` (so that a direction of its own has a singular value of order one: a
// column that is all round-off after an orthogonalisation stays at round-off and is
// dropped), rotated to the Ritz vectors of K (V^T K V diagonal, ascending). M = L L^T.
Eigen::MatrixXd RitzBasis(const Eigen::LLT<Eigen::MatrixXd>& M, const Eigen::MatrixXd& K,
                          const Eigen::MatrixXd& U, const Eigen::VectorXd& scale) {
  if (U.cols() == 0) return Eigen::MatrixXd(U.rows(), 0);
  Eigen::MatrixXd W = M.matrixU() * U;  // L^T U
  W = W * scale.asDiagonal();
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(W, Eigen::ComputeThinU);
  const Eigen::VectorXd& s = svd.singularValues();
  int r = 0;
  while (r < s.size() && s[r] > kRankTolerance * std::max(1.0, s[0])) ++r;
  if (r == 0) return Eigen::MatrixXd(U.rows(), 0);
  Eigen::MatrixXd V = M.matrixU().solve(svd.matrixU().leftCols(r));  // L^-T P
  const Eigen::MatrixXd A = V.transpose() * K * V;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (A + A.transpose()));
  return V * eig.eigenvectors();
}

}  // namespace

InstalledBases CalcInstalledBases(const System& system, const Eigen::VectorXd& q,
                                  const Eigen::VectorXd& v, double t,
                                  const Eigen::VectorXd& lambda, ConstraintWorkspace* workspace,
                                  const std::vector<InstalledBasisRequest>& requests) {
  InstalledBases out;
  if (requests.empty()) return out;
  const StateLayout& L = system.layout();
  for (const auto& r : requests) {
    const int b = system.FindBody(r.body);
    EMB_THROW_IF(L.num_elastic(b) == 0,
                 "installed basis of body '" << r.body << "': expected a flexible body");
    EMB_THROW_IF(!(r.dynamic_band_hz > 0.0), "installed basis of body '"
                                                 << r.body << "': expected a dynamic band > 0 Hz, got "
                                                 << r.dynamic_band_hz);
  }
  const LinearModes modes = CalcLinearModes(system, q, v, t, lambda, workspace, /*undamped=*/true);
  const std::vector<unsigned> loads = MarkerLoadsOf(system);
  for (const auto& r : requests) {
    const int b = system.FindBody(r.body);
    const ElasticModel& model = *system.body(b).elastic;
    const int ne = model.num_modes();
    const Eigen::MatrixXd Mee = 0.5 * (model.Sbar[0] + model.Sbar[4] + model.Sbar[8] +
                                       (model.Sbar[0] + model.Sbar[4] + model.Sbar[8]).transpose());
    const Eigen::LLT<Eigen::MatrixXd> Mllt(Mee);
    EMB_THROW_IF(Mllt.info() != Eigen::Success, "installed basis of body '"
                                                    << r.body
                                                    << "': its modal mass is not positive definite");
    const Eigen::MatrixXd K = 0.5 * (model.K + model.K.transpose());

    // 1. The body's part of the installed modes in the band.
    std::vector<int> in_band;
    double highest = 0.0, first_out = 0.0;
    for (Eigen::Index j = 0; j < modes.frequencies_hz.size(); ++j) {
      const double f = modes.frequencies_hz[j];
      if (f > r.dynamic_band_hz) {
        if (first_out == 0.0 || f < first_out) first_out = f;
        continue;
      }
      const Eigen::VectorXd s = modes.shapes.col(j);
      const Eigen::VectorXd eta = s.segment(L.elastic_v(b), ne);
      const double body_energy = eta.dot(Mee * eta);
      // The mode's total kinetic energy is not needed exactly: the shapes are M-normalised
      // by the linearisation (y^T Z^T M Z y = 1), so the fraction is body_energy itself.
      if (body_energy > kEnergyFraction) {
        in_band.push_back(static_cast<int>(j));
        highest = std::max(highest, f);
      }
    }
    Eigen::MatrixXd U(ne, static_cast<Eigen::Index>(in_band.size()));
    Eigen::VectorXd scale(U.cols());
    for (Eigen::Index k = 0; k < U.cols(); ++k) {
      U.col(k) = modes.shapes.col(in_band[k]).segment(L.elastic_v(b), ne);
      scale[k] = 1.0 / std::sqrt(U.col(k).dot(Mee * U.col(k)));
    }
    const Eigen::MatrixXd Vd = RitzBasis(Mllt, K, U, scale);

    // 2. Static responses to the loads the body can feel: at each loaded marker the forces
    // (shape_t^T) and moments (shape_r^T) it can carry, and the inertia loads (Ibar^T).
    int num_loaded = 0, columns = 9;
    for (std::size_t m = 0; m < loads.size(); ++m)
      if (loads[m] && system.marker(static_cast<int>(m)).body == b) {
        ++num_loaded;
        columns += (loads[m] & kMarkerForce ? 3 : 0) + (loads[m] & kMarkerMoment ? 3 : 0);
      }
    Eigen::MatrixXd F(ne, columns);
    int col = 0;
    for (std::size_t m = 0; m < loads.size(); ++m) {
      const Marker& marker = system.marker(static_cast<int>(m));
      if (!loads[m] || marker.body != b) continue;
      if (loads[m] & kMarkerForce) F.middleCols(col, 3) = marker.shape_t.transpose(), col += 3;
      if (loads[m] & kMarkerMoment) F.middleCols(col, 3) = marker.shape_r.transpose(), col += 3;
    }
    F.rightCols(9) = model.Ibar.transpose();
    const Eigen::LDLT<Eigen::MatrixXd> Kldlt(K);
    EMB_THROW_IF(Kldlt.info() != Eigen::Success || !(Kldlt.vectorD().minCoeff() > 0.0),
                 "installed basis of body '" << r.body
                                             << "': its modal stiffness is not positive definite");
    Eigen::MatrixXd Psi = Kldlt.solve(F);
    Eigen::VectorXd norm0(Psi.cols());
    for (Eigen::Index k = 0; k < Psi.cols(); ++k) norm0[k] = std::sqrt(Psi.col(k).dot(Mee * Psi.col(k)));
    // Twice M-orthogonalised against V_d (classical Gram-Schmidt loses orthogonality once).
    for (int pass = 0; pass < 2; ++pass) Psi -= Vd * (Vd.transpose() * (Mee * Psi));
    Eigen::VectorXd scale_s(Psi.cols());
    for (Eigen::Index k = 0; k < Psi.cols(); ++k) scale_s[k] = norm0[k] > 0.0 ? 1.0 / norm0[k] : 0.0;
    Eigen::MatrixXd Vs = RitzBasis(Mllt, K, Psi, scale_s);
    Vs -= Vd * (Vd.transpose() * (Mee * Vs));

    ElasticBasisChange change;
    change.body = b;
    change.T.resize(ne, Vd.cols() + Vs.cols());
    change.T << Vd, Vs;
    change.quasi_static.assign(static_cast<std::size_t>(change.T.cols()), false);
    change.relaxation_time = r.relaxation / (2.0 * std::numbers::pi * r.dynamic_band_hz);
    for (Eigen::Index k = Vd.cols(); k < change.T.cols(); ++k) change.quasi_static[k] = true;

    InstalledBasisReport rep;
    rep.body = r.body;
    rep.num_available = ne;
    rep.num_dynamic = static_cast<int>(Vd.cols());
    rep.num_quasi_static = static_cast<int>(Vs.cols());
    rep.num_loaded_markers = num_loaded;
    rep.dynamic_band_hz = r.dynamic_band_hz;
    rep.highest_kept_hz = highest;
    rep.first_left_out_hz = first_out;
    // The static compliance at the loaded directions, new basis against the full one.
    rep.static_compliance_error = StaticComplianceError(K, F, change.T);
    std::ostringstream o;
    o << "part '" << r.body << "': installed basis, " << rep.num_dynamic
      << " dynamic coordinates (the model's installed modes up to " << r.dynamic_band_hz
      << " Hz; first left out " << first_out << " Hz) + " << rep.num_quasi_static
      << " quasi-static (static responses at " << rep.num_loaded_markers
      << " loaded markers and to inertia loads) of " << ne << " elastic modes; static "
      << "compliance kept to " << rep.static_compliance_error;
    rep.note = o.str();
    out.changes.push_back(std::move(change));
    out.reports.push_back(std::move(rep));
  }
  return out;
}

Eigen::VectorXd MapElasticCoordinates(const System& from, const System& to,
                                      const std::vector<ElasticBasisChange>& changes,
                                      const Eigen::VectorXd& x, bool positions) {
  const StateLayout& A = from.layout();
  const StateLayout& B = to.layout();
  EMB_CHECK(x.size() == (positions ? A.nq() : A.nv()));
  Eigen::VectorXd y = Eigen::VectorXd::Zero(positions ? B.nq() : B.nv());
  const int rigid = (positions ? StateLayout::kQPerBody : StateLayout::kVPerBody) * A.num_moving();
  y.head(rigid) = x.head(rigid);
  for (int b = 1; b < from.num_bodies(); ++b) {
    const int na = A.num_elastic(b);
    if (na == 0) continue;
    const Eigen::VectorXd eta = x.segment(positions ? A.elastic_q(b) : A.elastic_v(b), na);
    auto out = y.segment(positions ? B.elastic_q(b) : B.elastic_v(b), B.num_elastic(b));
    const auto c = std::find_if(changes.begin(), changes.end(),
                                [b](const ElasticBasisChange& ch) { return ch.body == b; });
    if (c == changes.end())
      out = eta;
    else
      out = c->T.colPivHouseholderQr().solve(eta);
  }
  return y;
}

}  // namespace emb::mbs
