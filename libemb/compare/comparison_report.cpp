#include "libemb/compare/comparison_report.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/io/atomic_file.h"

namespace emb {
namespace {

std::string Num(double v, int precision = 6) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s << std::setprecision(precision) << v;
  return s.str();
}

std::string Percent(double v) {
  if (!std::isfinite(v)) return "–";
  std::ostringstream s;
  s << std::showpos << std::fixed << std::setprecision(v != 0.0 && std::abs(v) < 0.01 ? 4 : 2)
    << 100.0 * v;
  return s.str();
}

bool Judged(const PartComparison& c, const RouteResult& r, int j) {
  return r.method == "cms" || r.method == "fe" || c.reference[j].beam_like;
}

}  // namespace

RouteSummary SummariseRoute(const PartComparison& c, int route) {
  EMB_THROW_IF(route < 0 || route >= static_cast<int>(c.routes.size()),
               "route index: expected 0.." << c.routes.size() - 1 << ", got " << route);
  const RouteResult& r = c.routes[route];
  RouteSummary s;
  double sum = 0.0;
  for (int j = 0; j < static_cast<int>(c.reference.size()); ++j) {
    if (!Judged(c, r, j)) continue;
    ++s.num_judged;
    const double e = r.Error(c.reference, j);
    if (!std::isfinite(e)) continue;
    ++s.num_paired;
    s.max_abs_error = std::max(s.max_abs_error, std::abs(e));
    sum += std::abs(e);
    if (std::isfinite(r.mac[j])) s.min_mac = std::min(s.min_mac, r.mac[j]);
  }
  s.mean_abs_error = s.num_paired ? sum / s.num_paired : 0.0;
  return s;
}

void WriteComparisonCsv(const PartComparison& c, const std::string& path) {
  std::ostringstream f;
  f << "part,support,route,method,variant,unknowns,seconds,mode,reference_hz,"
       "section_deformation,beam_like,hz,error_pct,mac\n";
  for (const RouteResult& r : c.routes)
    for (int j = 0; j < static_cast<int>(c.reference.size()); ++j) {
      const ReferenceMode& m = c.reference[j];
      const double e = r.Error(c.reference, j);
      f << c.part << ',' << Name(c.support) << ",\"" << r.name << "\"," << r.method << ",\""
        << r.variant << "\"," << r.num_unknowns << ',' << Num(r.seconds, 4) << ',' << j + 1 << ','
        << Num(m.frequency_hz, 8) << ',' << Num(m.section_deformation, 4) << ','
        << (m.beam_like ? 1 : 0) << ',' << Num(r.frequencies_hz[j], 8) << ','
        << Num(100.0 * e, 6) << ',' << Num(r.mac[j], 4) << '\n';
    }
  WriteTextFileAtomic(path, f.str());
}

void WriteComparisonMarkdown(const PartComparison& c, const std::string& path,
                             const std::vector<std::string>& images) {
  std::ostringstream f;
  f << "# Beam vs CMS vs 3-D FE: " << c.part << ", " << Name(c.support) << "\n\n";
  f << "- geometry: `" << c.geometry << "`";
  if (c.beam_geometry != c.geometry) f << " (beams from `" << c.beam_geometry << "`)";
  f << "\n- support: " << c.support_description << "\n";
  f << "- reference: 3-D FE, " << c.mesh_summary << ", " << c.fe_dofs << " DOF, mass "
    << Num(c.fe_mass_kg, 5) << " kg (exact geometry " << Num(c.geometry_mass_kg, 5) << " kg)\n";
  f << "- mesh " << Num(c.mesh_seconds, 3) << " s, assembly " << Num(c.assembly_seconds, 3)
    << " s (both counted in the fe and cms route times)\n";
  f << "- CMS interfaces: ";
  for (size_t i = 0; i < c.interfaces.size(); ++i) f << (i ? ", " : "") << c.interfaces[i];
  f << "\n- MAC stations: ";
  for (size_t i = 0; i < c.stations.size(); ++i) f << (i ? ", " : "") << c.stations[i];
  f << "\n- TMM vs lumped beam FE: max relative difference " << Num(c.tmm_vs_lumped, 3) << "\n\n";

  f << "## Routes\n\n| route | unknowns | wall time [s] | pairing | modes paired | max abs error "
       "[%] | mean abs error [%] | min MAC | note |\n|---|---|---|---|---|---|---|---|---|\n";
  for (int i = 0; i < static_cast<int>(c.routes.size()); ++i) {
    const RouteResult& r = c.routes[i];
    const RouteSummary s = SummariseRoute(c, i);
    f << "| " << r.name << " | " << r.num_unknowns << " | " << Num(r.seconds, 3) << " | "
      << r.pairing << " | " << s.num_paired << "/" << s.num_judged << " | "
      << Num(100 * s.max_abs_error, 3) << " | " << Num(100 * s.mean_abs_error, 3) << " | "
      << (r.method == "beam" ? Num(s.min_mac, 3) : "") << " | " << r.note << " |\n";
  }
  f << "\n## Frequency error per mode [%] (f_route / f_3D − 1)\n\n| mode | 3-D [Hz] | "
       "section def. |";
  for (size_t i = 1; i < c.routes.size(); ++i) f << ' ' << c.routes[i].name << " |";
  f << "\n|---|---|---|";
  for (size_t i = 1; i < c.routes.size(); ++i) f << "---|";
  f << "\n";
  for (int j = 0; j < static_cast<int>(c.reference.size()); ++j) {
    const ReferenceMode& m = c.reference[j];
    f << "| " << j + 1 << " | " << Num(m.frequency_hz, 6) << " | "
      << Num(m.section_deformation, 2) << (m.beam_like ? "" : " (shell)") << " |";
    for (size_t i = 1; i < c.routes.size(); ++i) f << ' ' << Percent(c.routes[i].Error(c.reference, j)) << " |";
    f << "\n";
  }
  f << "\n## 3-D modes a beam cannot represent\n\n";
  bool any = false;
  for (int j = 0; j < static_cast<int>(c.reference.size()); ++j)
    if (!c.reference[j].beam_like) {
      if (!any) f << "| mode | frequency [Hz] | section-deformation ratio |\n|---|---|---|\n";
      any = true;
      f << "| " << j + 1 << " | " << Num(c.reference[j].frequency_hz, 6) << " | "
        << Num(c.reference[j].section_deformation, 3) << " |\n";
    }
  if (!any) f << "None among the modes compared: every cross-section moves (nearly) rigidly.\n";
  if (!c.notes.empty()) {
    f << "\n## Notes\n\n";
    for (const std::string& n : c.notes) f << "- " << n << "\n";
  }
  if (!images.empty()) {
    f << "\n## Plots\n\n";
    for (const std::string& i : images) f << "![" << i << "](" << i << ")\n\n";
  }
  WriteTextFileAtomic(path, f.str());
}

}  // namespace emb
