#include "libemb/scene/stress_recorder.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <tuple>

#include "libemb/common/error.h"
#include "libemb/fe/stress_measures.h"
#include "libemb/io/atomic_file.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/io/mesh_io.h"
#include "libemb/results/rainflow.h"

namespace emb::scene {
namespace {

// A sample within this of a field time takes it (output times are sums of steps).
constexpr double kFieldTimeSlack = 1e-9;  // [s]

// The fatigue measure of every node of group g (fe/stress_measures.h, SignedVonMises).
Eigen::VectorXd Measure(const std::string& measure, const mbs::StressSnapshot& snap,
                        std::size_t g) {
  if (measure != "signed_von_mises") return snap.max_principal[g];
  const Eigen::VectorXd& p1 = snap.max_principal[g];
  const Eigen::VectorXd& p3 = snap.min_principal[g];
  Eigen::VectorXd m = snap.von_mises[g];
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (std::abs(p1[i]) < std::abs(p3[i])) m[i] = -m[i];
  return m;
}

}  // namespace

StressRecorder::StressRecorder(const mbs::System& system, std::vector<StressOutput> outputs)
    : system_(system), outputs_(std::move(outputs)) {
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    StressOutput& out = outputs_[o];
    std::sort(out.field_times.begin(), out.field_times.end());
    std::shared_ptr<const mbs::StressProbe> probe;
    for (const auto& p : system.probes())
      if (p->name() == out.name) probe = std::dynamic_pointer_cast<const mbs::StressProbe>(p);
    EMB_THROW_IF(!probe, "stress output '" << out.name << "': no stress probe of that name in "
                                                          "the system");
    probes_.push_back(probe);
    next_field_.push_back(0);
    for (std::size_t g = 0; g < probe->groups().size(); ++g)
      groups_.push_back({static_cast<int>(o), static_cast<int>(g), {}, {}, {}, {}});
  }
}

bool StressRecorder::has_fatigue() const {
  return std::any_of(outputs_.begin(), outputs_.end(), [](const auto& o) { return o.fatigue; });
}

bool StressRecorder::has_fields() const {
  return std::any_of(outputs_.begin(), outputs_.end(),
                     [](const auto& o) { return !o.field_times.empty(); });
}

void StressRecorder::Add(const mbs::Sample& s) {
  const mbs::StateLayout& L = system_.layout();
  std::vector<char> take_field(outputs_.size(), 0);
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    const auto& times = outputs_[o].field_times;
    std::size_t& next = next_field_[o];
    if (next < times.size() && s.t >= times[next] - kFieldTimeSlack) {
      take_field[o] = 1;
      while (next < times.size() && s.t >= times[next] - kFieldTimeSlack) ++next;
    }
  }
  for (Group& g : groups_) {
    const StressOutput& out = outputs_[static_cast<std::size_t>(g.output)];
    if (!out.fatigue && !take_field[static_cast<std::size_t>(g.output)]) continue;
    const mbs::StressProbe& probe = *probes_[static_cast<std::size_t>(g.output)];
    const int b = probe.body();
    const mbs::StressSnapshot& snap =
        probe.Evaluate(s.q.segment(L.elastic_q(b), L.num_elastic(b)));
    const auto gi = static_cast<std::size_t>(g.index);
    if (out.fatigue) {
      g.t.push_back(s.t);
      g.measure.push_back(Measure(out.measure, snap, gi));
    }
    if (take_field[static_cast<std::size_t>(g.output)]) {
      g.field_t.push_back(s.t);
      g.field.push_back(snap.sigma[gi]);
    }
  }
}

std::vector<FatigueRow> StressRecorder::Fatigue(double t0, double t1, bool periodic) const {
  std::vector<FatigueRow> rows;
  for (const Group& g : groups_) {
    const StressOutput& out = outputs_[static_cast<std::size_t>(g.output)];
    if (!out.fatigue) continue;
    const mbs::StressRows& group = probes_[static_cast<std::size_t>(g.output)]->groups()[g.index];
    FatigueRow row;
    row.output = out.name;
    row.group = group.name;
    row.measure = out.measure;
    row.damage = -1.0;
    std::vector<double> history;
    for (std::size_t i = 0; i < group.nodes.size(); ++i) {
      history.clear();
      for (std::size_t k = 0; k < g.t.size(); ++k)
        if (g.t[k] >= t0 && g.t[k] <= t1) history.push_back(g.measure[k][static_cast<Eigen::Index>(i)]);
      const auto cycles = periodic ? CountRainflowPeriodic(history) : CountRainflow(history);
      const FatigueDamage d = CalcMinerDamage(cycles, out.sn);
      if (d.damage > row.damage) {
        row.damage = d.damage;
        row.node = group.nodes[i];
        row.cycles = d.cycles;
        row.max_range = d.max_range;
        row.max_equivalent = d.max_equivalent;
      }
    }
    row.damage = std::max(row.damage, 0.0);
    row.life = row.damage > 0.0 ? 1.0 / row.damage : std::numeric_limits<double>::infinity();
    rows.push_back(row);
  }
  return rows;
}

std::vector<double> StressRecorder::MissedFieldTimes() const {
  std::vector<double> missed;
  for (std::size_t o = 0; o < outputs_.size(); ++o)
    for (std::size_t k = next_field_[o]; k < outputs_[o].field_times.size(); ++k)
      missed.push_back(outputs_[o].field_times[k]);
  return missed;
}

void StressRecorder::WriteFields(const std::string& h5_path, const std::string& xdmf_path) const {
  AtomicFile h5_out(h5_path);
  std::ostringstream x;
  x.precision(12);
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n";
  const std::string h5_name = std::filesystem::path(h5_path).filename().string();
  {
    H5File h5(h5_out.temp_path(), H5File::Mode::kCreate);
    h5.SetAttribute("/", "format", std::string("emb.stress_fields"));
    h5.SetAttribute("/", "units", std::string("SI: m, s, Pa; stress in Voigt order xx, yy, zz, "
                                              "xy, yz, zx, mesh axes"));
    std::vector<Mesh> meshes(outputs_.size());
    for (const Group& g : groups_) {
      if (g.field.empty()) continue;
      const StressOutput& out = outputs_[static_cast<std::size_t>(g.output)];
      Mesh& mesh = meshes[static_cast<std::size_t>(g.output)];
      if (mesh.num_nodes() == 0) {
        const H5File body(out.body_file, H5File::Mode::kRead);
        EMB_THROW_IF(!body.Exists("/mesh/nodes"),
                     "stress output '" << out.name << "': body file '" << out.body_file
                                       << "' has no mesh (reduced with --no-mesh-shapes), which "
                                          "field_times need");
        mesh = ReadMeshSection(body);
      }
      const mbs::StressRows& group = probes_[static_cast<std::size_t>(g.output)]->groups()[g.index];
      const std::uint64_t m = group.nodes.size(), k = g.field.size();
      const std::string base = "/" + out.name + "/" + group.name;
      std::vector<double> xyz, stress, vm, p1;
      for (int node : group.nodes) {
        EMB_THROW_IF(node < 0 || node >= mesh.num_nodes(),
                     "stress output '" << out.name << "': node " << node
                                       << " is not in the mesh of '" << out.body_file << "'");
        for (int c = 0; c < 3; ++c) xyz.push_back(mesh.nodes(c, node));
      }
      for (const Eigen::MatrixXd& s : g.field)
        for (Eigen::Index i = 0; i < s.cols(); ++i) {
          const Voigt6 v = s.col(i);
          for (int c = 0; c < 6; ++c) stress.push_back(v[c]);
          vm.push_back(VonMises(v));
          p1.push_back(PrincipalStresses(v)[0]);
        }
      h5.Write(base + "/nodes", group.nodes.data(), {m});
      h5.Write(base + "/coordinates", xyz.data(), {m, 3});
      h5.Write(base + "/times", g.field_t.data(), {k});
      h5.Write(base + "/stress", stress.data(), {k, m, 6});
      h5.Write(base + "/von_mises", vm.data(), {k, m});
      h5.Write(base + "/max_principal", p1.data(), {k, m});
      x << "  <Grid Name=\"" << out.name << "." << group.name
        << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (std::uint64_t s = 0; s < k; ++s) {
        x << "   <Grid Name=\"t = " << g.field_t[s] << " s\" GridType=\"Uniform\">\n"
          << "    <Time Value=\"" << g.field_t[s] << "\"/>\n"
          << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << m << "\"/>\n"
          << "    <Geometry GeometryType=\"XYZ\">\n     <DataItem Dimensions=\"" << m
          << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5_name << ":"
          << base << "/coordinates</DataItem>\n    </Geometry>\n";
        for (const auto& [field, width, type] :
             {std::tuple{"von_mises", 1, "Scalar"}, std::tuple{"max_principal", 1, "Scalar"},
              std::tuple{"stress", 6, "Tensor6"}}) {
          const bool scalar = width == 1;
          x << "    <Attribute Name=\"" << field << "\" AttributeType=\"" << type
            << "\" Center=\"Node\">\n     <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << m
            << (scalar ? "" : " 6") << "\">\n      <DataItem Dimensions=\"3 " << (scalar ? 2 : 3)
            << "\" Format=\"XML\">" << s << " 0" << (scalar ? "" : " 0") << " 1 1"
            << (scalar ? "" : " 1") << " 1 " << m << (scalar ? "" : " 6")
            << "</DataItem>\n      <DataItem Dimensions=\"" << k << " " << m
            << (scalar ? "" : " 6") << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
            << h5_name << ":" << base << "/" << field << "</DataItem>\n     </DataItem>\n"
            << "    </Attribute>\n";
        }
        x << "   </Grid>\n";
      }
      x << "  </Grid>\n";
    }
    h5.Close();
  }
  x << " </Domain>\n</Xdmf>\n";
  AtomicFile xdmf(xdmf_path);
  xdmf.WriteText(x.str());
  h5_out.Commit();
  xdmf.Commit();
}

}  // namespace emb::scene
