#include "tools/emb/sweep_report.h"

#include <cmath>
#include <iostream>

#include "libemb/common/error.h"
#include "tools/emb/table.h"

namespace emb::cli {

void Report(const sweep::SweepData& d, const std::string& output, std::size_t reused,
            const OutputOptions& out) {
  using sweep::PointStatus;
  const auto& ch = d.settings.channels;
  const auto& orders = d.settings.orders;
  std::vector<std::string> keys = {"rpm", "status", "cycles", "change", "cpu_seconds"};
  std::vector<std::string> headers = {"rpm", "status", "cycles", "change", "CPU [s]"};
  for (const auto& c : ch) {
    keys.push_back(c + ":top_order");
    keys.push_back(c + ":top_amplitude");
    headers.push_back(c + " top order");
    headers.push_back("amplitude");
  }
  Table t("Operating points (per channel the order of largest amplitude)", keys, headers);
  t.set_precision(5);
  nlohmann::json amplitude = nlohmann::json::array(), phase = nlohmann::json::array();
  int failed = 0, unsettled = 0;
  std::string bad;
  for (const sweep::OperatingPoint& p : d.points) {
    std::vector<Table::Cell> row = {p.rpm, std::string(Name(p.status)),
                                    static_cast<long long>(p.cycles), p.change, p.cpu_seconds};
    nlohmann::json a = nlohmann::json::object(), ph = nlohmann::json::object();
    for (Eigen::Index c = 0; c < p.amplitude.rows(); ++c) {
      Eigen::Index top = 0;
      const bool any = p.amplitude.row(c).allFinite();
      if (any) p.amplitude.row(c).maxCoeff(&top);
      row.push_back(any ? orders[static_cast<std::size_t>(top)] : NAN);
      row.push_back(any ? p.amplitude(c, top) : NAN);
      std::vector<double> ar(p.amplitude.row(c).begin(), p.amplitude.row(c).end());
      std::vector<double> pr(p.phase_deg.row(c).begin(), p.phase_deg.row(c).end());
      a[ch[static_cast<std::size_t>(c)]] = ar;
      ph[ch[static_cast<std::size_t>(c)]] = pr;
    }
    amplitude.push_back(a);
    phase.push_back(ph);
    t.AddRow(row);
    if (p.status == PointStatus::kFailed || p.status == PointStatus::kNotConverged) {
      (p.status == PointStatus::kFailed ? failed : unsettled)++;
      bad += (bad.empty() ? "" : "; ") + std::to_string(std::lround(p.rpm)) + " rpm " +
             Name(p.status) + (p.message.empty() ? "" : " (" + p.message + ")");
    }
  }
  Summary s("Sweep of " + d.scene);
  s.Add("scene", "scene", d.scene);
  s.Add("digest", "sweep digest", d.digest);
  s.Add("points", "operating points in this file", static_cast<long long>(d.points.size()));
  s.Add("sweep_points", "operating points of the sweep", static_cast<long long>(d.sweep_rpm.size()));
  if (d.shard_count > 1)
    s.Add("shard", "shard", std::to_string(d.shard_index) + " of " + std::to_string(d.shard_count));
  s.Add("reused", "points reused from an earlier run", static_cast<long long>(reused));
  s.Add("failed", "points failed", static_cast<long long>(failed));
  s.Add("not_converged", "points without a steady state", static_cast<long long>(unsettled));
  s.Add("channels", "channels", ch);
  s.Add("orders", "orders", orders);
  double cpu = 0.0;
  for (const auto& p : d.points) cpu += p.cpu_seconds;
  s.Add("cpu_seconds", "CPU time of the points [s]", cpu);
  s.Add("output", "written", output);
  if (out.json) {
    PrintJson({{"summary", s.ToJson()},
               {"points", t.ToJson()},
               {"amplitude", amplitude},
               {"phase_deg", phase}});
  } else if (!out.quiet) {  // -q: the file is the result, no report
    s.Print(std::cout);
    std::cout << "\n";
    t.Print(std::cout);
  }
  if (failed + unsettled > 0)
    EMB_THROW(NumericalError, failed + unsettled << " of " << d.points.size()
                                                 << " operating points failed or did not "
                                                    "settle (all are in "
                                                 << output << "): " << bad);
}

}  // namespace emb::cli
