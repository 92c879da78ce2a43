#include "libemb/mbs/flexible/basis_truncation.h"

#include <algorithm>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/mbs/flexible/static_compliance.h"

namespace emb::mbs {

std::vector<TruncationReport> CalcTruncationReports(const System& system,
                                                    const std::vector<TruncatedBasis>& bases) {
  std::vector<TruncationReport> out;
  if (bases.empty()) return out;
  const std::vector<unsigned> loads = MarkerLoadsOf(system);
  for (const TruncatedBasis& tb : bases) {
    const int b = system.FindBody(tb.body);
    const int ne = static_cast<int>(tb.full_eigenvalues.size());
    TruncationReport rep;
    rep.body = tb.body;
    rep.num_kept = static_cast<int>(tb.kept.size());
    rep.num_available = ne;
    std::vector<Eigen::MatrixXd> columns;  // ne x 3 blocks of F
    for (std::size_t m = 0; m < loads.size(); ++m) {
      const Marker& marker = system.marker(static_cast<int>(m));
      if (!loads[m] || marker.body != b) continue;
      const auto it = std::find_if(tb.markers.begin(), tb.markers.end(),
                                   [&](const auto& e) { return e.first == marker.name; });
      EMB_CHECK(it != tb.markers.end() && it->second.rows() == 6 && it->second.cols() == ne);
      rep.loaded_markers.push_back(marker.name);
      if (loads[m] & kMarkerForce) columns.push_back(it->second.topRows(3).transpose());
      if (loads[m] & kMarkerMoment) columns.push_back(it->second.bottomRows(3).transpose());
    }
    Eigen::MatrixXd F(ne, 3 * static_cast<Eigen::Index>(columns.size()));
    for (std::size_t k = 0; k < columns.size(); ++k) F.middleCols(3 * k, 3) = columns[k];
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(ne, rep.num_kept);
    for (int j = 0; j < rep.num_kept; ++j) T(tb.kept[j], j) = 1.0;
    rep.static_compliance_error =
        StaticComplianceError(Eigen::MatrixXd(tb.full_eigenvalues.asDiagonal()), F, T);
    std::ostringstream o;
    o << "part '" << tb.body << "': " << rep.num_kept << " of " << ne << " elastic modes of "
      << tb.source << " kept; static compliance error " << rep.static_compliance_error
      << " at " << rep.loaded_markers.size() << " loaded marker(s)";
    for (std::size_t k = 0; k < rep.loaded_markers.size(); ++k)
      o << (k ? ", " : " (") << rep.loaded_markers[k] << (k + 1 == rep.loaded_markers.size() ? ")" : "");
    rep.note = o.str();
    out.push_back(std::move(rep));
  }
  return out;
}

std::string TruncationWarning(const TruncationReport& r, double threshold) {
  if (!(r.static_compliance_error > threshold)) return {};
  std::ostringstream o;
  o << "part '" << r.body << "': the " << r.num_kept << " kept of " << r.num_available
    << " elastic modes miss " << 100.0 * r.static_compliance_error
    << " % of the full basis's static compliance at its loaded markers (more than "
    << 100.0 * threshold << " %): its response to the joint and force loads is too stiff. "
    << "Keep more modes (modes:, fmax_hz:), or use `basis: installed` with dynamic_band_hz "
       "(static completeness at every loaded marker)";
  return o.str();
}

}  // namespace emb::mbs
