// emb compare PART: the beam-vs-CMS benchmark of one part (issue 6). Natural frequencies of
// the same geometry by the transfer-matrix method, the beam FE model (lumped and consistent
// mass; rigid and elastic webs), Craig–Bampton bodies with several mode counts and the full
// 3-D FE model (the reference): % error per mode, MAC pairing of the beam shapes at the
// journal centres / along the tube axis, wall time per route, and the 3-D modes no beam can
// represent (cross-sections that deform: shell/ovalling modes).
//
//   emb compare meshes/crankshaft_i4.geo --size 0.012 --support installed --report-dir out
//   /usr/bin/python3 benchmarks/compare_plots.py out/crankshaft_i4_installed_compare.csv
//
// Input: a .geo with beam parts (beam_parts = 1: meshes/crankshaft_i4.geo, meshes/tube.geo).
// Output: tables (or --json); with --report-dir a Markdown report and a CSV.

#include <filesystem>
#include <iostream>
#include <memory>

#include "libemb/common/error.h"
#include "libemb/compare/comparison_report.h"
#include "libemb/common/number_check.h"
#include "libemb/compare/part_comparison.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/progress_display.h"

namespace emb::cli {
namespace {

struct CompareCommand {
  PartOptions part;
  OutputOptions out;
  std::string support{"free-free"};
  int num_modes{10};
  std::vector<int> cms_modes{5, 10, 20, 40};
  std::vector<std::string> webs{"rigid", "elastic"};
  double web_width{0.0};
  std::string beam_geometry;
  double element_length{0.02};
  bool euler_bernoulli{false};
  std::vector<double> tmm_band;
  int scan_intervals{400};
  int stations{16};
  double shell_threshold{0.5};
  std::string report_dir;

  ComparisonOptions Options() const {
    ComparisonOptions o;
    o.geometry = part.file;
    o.beam_geometry = beam_geometry;
    o.meshing = part.Meshing();
    o.material = part.material;
    o.support = support == "installed" ? SupportCase::kInstalled : SupportCase::kFreeFree;
    o.num_modes = num_modes;
    o.cms_modes = cms_modes;
    o.webs.clear();
    for (const std::string& w : webs)
      o.webs.push_back(w == "rigid" ? WebModel::kRigid : WebModel::kElastic);
    o.web_width = web_width;
    o.beam_element_length = element_length;
    o.shear_deformable = !euler_bernoulli;
    CheckNumber("--web-width", web_width, NumberRange::NonNegative("m"));
    CheckNumber("--element-length", element_length, NumberRange::Positive("m"));
    CheckInteger("--scan-intervals", scan_intervals, 1, 100000000);
    CheckInteger("--stations", stations, 2, 100000);
    CheckNumber("--shell-threshold", shell_threshold, NumberRange::Open(0.0, 1.0));
    CheckInteger("--modes", num_modes, 1, 100000);
    for (int n : cms_modes) CheckInteger("--cms", n, 0, 100000);
    if (!tmm_band.empty()) {
      EMB_THROW_IF(tmm_band.size() != 2,
                   "--tmm-band: expected LO,HI [Hz], got " << tmm_band.size() << " values");
      for (double f : tmm_band) CheckNumber("--tmm-band", f, NumberRange::NonNegative("Hz"));
      o.tmm_min_hz = tmm_band[0];
      o.tmm_max_hz = tmm_band[1];
      EMB_THROW_IF(!(o.tmm_max_hz > o.tmm_min_hz && o.tmm_min_hz >= 0.0),
                   "--tmm-band: expected 0 <= LO < HI, got " << o.tmm_min_hz << ","
                                                             << o.tmm_max_hz);
    }
    o.tmm_scan_intervals = scan_intervals;
    o.axis_stations = stations;
    o.shell_threshold = shell_threshold;
    return o;
  }

  void Run() const {
    const ComparisonOptions o = Options();
    if (!report_dir.empty()) {
      std::error_code ec;
      EMB_THROW_IF(!std::filesystem::is_directory(report_dir, ec),
                   "--report-dir '" << report_dir << "': directory does not exist");
    }
    // The report's names are known now: check and lock them before any work.
    const std::string base =
        report_dir.empty()
            ? ""
            : (std::filesystem::path(report_dir) /
               (std::filesystem::path(part.file).stem().string() + "_" + Name(o.support) +
                "_compare"))
                  .string();
    const PreparedOutputs outputs({{base.empty() ? "" : base + ".csv", "--report-dir"},
                                   {base.empty() ? "" : base + ".md", "--report-dir"},
                                   {part.save_mesh, "--save-mesh"}},
                                  {part.file, beam_geometry});
    const PartComparison c = RunPartComparison(o, MakeProgressDisplay(out.quiet));
    FinishProgressLine();

    Summary s("Beam vs CMS vs 3-D FE: " + c.part + ", " + Name(c.support));
    s.Add("part", "part", c.part);
    s.Add("geometry", "geometry", c.geometry);
    if (c.beam_geometry != c.geometry) s.Add("beam_geometry", "beam geometry", c.beam_geometry);
    s.Add("support", "support", c.support_description);
    s.Add("mesh", "reference mesh", c.mesh_summary);
    s.Add("fe_dofs", "reference DOF", c.fe_dofs);
    s.Add("fe_mass_kg", "mesh mass [kg]", c.fe_mass_kg);
    s.Add("geometry_mass_kg", "exact geometry mass [kg]", c.geometry_mass_kg);
    s.Add("seconds_mesh", "time mesh [s]", c.mesh_seconds);
    s.Add("seconds_assembly", "time assembly [s]", c.assembly_seconds);
    s.Add("stations", "MAC stations", c.stations);
    s.Add("interfaces", "CMS interfaces", c.interfaces);
    s.Add("tmm_vs_lumped", "max |TMM - lumped beam FE| / f", c.tmm_vs_lumped);
    for (size_t i = 0; i < c.notes.size(); ++i) s.Add("note_" + std::to_string(i + 1), "note", c.notes[i]);

    Table routes("Routes (errors over the modes each is judged on: beams on beam-like modes)",
                 {"route", "method", "unknowns", "seconds", "pairing", "paired", "judged",
                  "max_abs_error_pct", "mean_abs_error_pct", "min_mac", "note"},
                 {"route", "method", "unknowns", "time [s]", "pairing", "paired", "judged",
                  "max |err| [%]", "mean |err| [%]", "min MAC", "note"});
    routes.set_precision(4);
    for (int i = 0; i < static_cast<int>(c.routes.size()); ++i) {
      const RouteResult& r = c.routes[i];
      const RouteSummary rs = SummariseRoute(c, i);
      routes.AddRow({r.name, r.method, static_cast<long long>(r.num_unknowns), r.seconds,
                     r.pairing, static_cast<long long>(rs.num_paired),
                     static_cast<long long>(rs.num_judged), 100 * rs.max_abs_error,
                     100 * rs.mean_abs_error, r.method == "beam" ? rs.min_mac : 1.0, r.note});
    }
    std::vector<std::string> keys{"mode", "reference_hz", "section_deformation", "beam_like"};
    std::vector<std::string> headers{"mode", "3-D [Hz]", "sect. def.", "beam-like"};
    for (size_t i = 1; i < c.routes.size(); ++i) {
      keys.push_back(c.routes[i].name);
      headers.push_back(c.routes[i].name + " [%]");
    }
    Table modes("Frequency error per mode [%]: f_route / f_3D - 1 (NaN: unpaired)", keys, headers);
    modes.set_precision(4);
    for (int j = 0; j < static_cast<int>(c.reference.size()); ++j) {
      std::vector<Table::Cell> row{static_cast<long long>(j + 1), c.reference[j].frequency_hz,
                                   c.reference[j].section_deformation,
                                   std::string(c.reference[j].beam_like ? "yes" : "no")};
      for (size_t i = 1; i < c.routes.size(); ++i) row.push_back(100 * c.routes[i].Error(c.reference, j));
      modes.AddRow(row);
    }
    Table shells("3-D modes a beam cannot represent (cross-section deforms)",
                 {"mode", "frequency_hz", "section_deformation"},
                 {"mode", "frequency [Hz]", "section deformation"});
    for (int j = 0; j < static_cast<int>(c.reference.size()); ++j)
      if (!c.reference[j].beam_like)
        shells.AddRow({static_cast<long long>(j + 1), c.reference[j].frequency_hz,
                       c.reference[j].section_deformation});

    if (!report_dir.empty()) {
      const std::string name = std::filesystem::path(base).filename().string();
      WriteComparisonCsv(c, base + ".csv");
      WriteComparisonMarkdown(c, base + ".md",
                              {name + "_error_vs_mode.png", name + "_error_vs_time.png"});
      s.Add("report", "written", base + ".md and " + base + ".csv");
    }
    if (out.json) {
      nlohmann::json routes_json = routes.ToJson();
      for (size_t i = 0; i < c.routes.size(); ++i) {
        std::vector<double> hz, err, mac;
        for (int j = 0; j < static_cast<int>(c.reference.size()); ++j) {
          hz.push_back(c.routes[i].frequencies_hz[j]);
          err.push_back(c.routes[i].Error(c.reference, j));
          mac.push_back(c.routes[i].mac[j]);
        }
        routes_json[i]["frequencies_hz"] = hz;
        routes_json[i]["relative_errors"] = err;
        routes_json[i]["mac"] = mac;
      }
      PrintJson({{"summary", s.ToJson()},
                 {"routes", routes_json},
                 {"modes", modes.ToJson()},
                 {"not_beam_like", shells.ToJson()}});
    } else if (!out.quiet) {  // -q: the file is the result, no report
      s.Print(std::cout);
      std::cout << "\n";
      routes.Print(std::cout);
      std::cout << "\n";
      modes.Print(std::cout);
      std::cout << "\n";
      shells.Print(std::cout);
    }
  }
};

}  // namespace

void RegisterCompareCommand(CLI::App& app) {
  auto st = std::make_shared<CompareCommand>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Beam vs CMS vs 3-D FE for one part: natural frequencies by TMM, beam FE (lumped and "
      "consistent mass, rigid and elastic webs), Craig-Bampton bodies and the full 3-D model "
      "(reference); % error per mode, MAC pairing, wall time per route, shell modes no beam "
      "represents");
  st->part.Register(*cmd);
  cmd->add_option("--support", st->support,
                  "free-free, or installed: journal centres held radially (journal 1 also "
                  "axially), spin free (parts with main journals)")
      ->capture_default_str()
      ->check(CLI::IsMember({"free-free", "installed"}));
  cmd->add_option("-n,--modes", st->num_modes, "Elastic 3-D modes to compare")
      ->capture_default_str();
  cmd->add_option("--cms", st->cms_modes,
                  "Fixed-interface mode counts of the CMS routes (comma separated)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--webs", st->webs,
                  "Web models of the beam crankshaft: rigid (dummy parts), elastic (web arms)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"rigid", "elastic"}));
  cmd->add_option("--web-width", st->web_width,
                  "Elastic web arm width [m]; 0 = web_r_main + web_r_pin of the .geo")
      ->capture_default_str();
  cmd->add_option("--beam-geometry", st->beam_geometry,
                  "Build the beam model from this .geo instead of PART (must be the same part: "
                  "mass and length are checked)");
  cmd->add_option("--element-length", st->element_length, "Largest beam element length [m]")
      ->capture_default_str();
  cmd->add_flag("--euler-bernoulli", st->euler_bernoulli,
                "Beams without shear deformation (default: Timoshenko)");
  cmd->add_option("--tmm-band", st->tmm_band,
                  "TMM band LO,HI [Hz] (default 0 to 1.25 x the highest 3-D frequency); a band "
                  "without roots is an error")
      ->delimiter(',');
  cmd->add_option("--scan-intervals", st->scan_intervals, "TMM scan grid intervals")
      ->capture_default_str();
  cmd->add_option("--stations", st->stations,
                  "MAC stations along a one-segment part (tube)")
      ->capture_default_str();
  cmd->add_option("--shell-threshold", st->shell_threshold,
                  "Section-deformation ratio above which a 3-D mode is not beam-like")
      ->capture_default_str();
  cmd->add_option("--report-dir", st->report_dir,
                  "Write <part>_<support>_compare.md and .csv there (plots: "
                  "benchmarks/compare_plots.py on the .csv)")
      ->check(NonEmptyPath());
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
