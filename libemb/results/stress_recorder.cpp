#include "libemb/results/stress_recorder.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/fe/stress_measures.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/io/mesh_io.h"
#include "libemb/mesh/boundary_surface.h"
#include "libemb/results/rainflow.h"
#include "libemb/results/stress_field_file.h"

namespace emb::results {
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

// Whether the sample at `t` takes the next of the sorted `times` (advancing `next` past every
// time it reaches).
bool Due(const std::vector<double>& times, std::size_t& next, double t) {
  if (next >= times.size() || t < times[next] - kFieldTimeSlack) return false;
  while (next < times.size() && t >= times[next] - kFieldTimeSlack) ++next;
  return true;
}

// The group's field (coordinates and faces from the body file's mesh).
NodalStressField GroupField(const StressOutput& out, const mbs::StressRows& group, const Mesh& mesh,
                            const BoundarySurface& boundary) {
  NodalStressField f;
  f.path = "/" + out.name + "/" + group.name;
  f.title = out.name + "." + group.name;
  f.nodes = group.nodes;
  f.coordinates.resize(static_cast<Eigen::Index>(group.nodes.size()), 3);
  std::vector<int> local(static_cast<std::size_t>(mesh.num_nodes()), -1);
  for (std::size_t i = 0; i < group.nodes.size(); ++i) {
    const int node = group.nodes[i];
    EMB_THROW_IF(node < 0 || node >= mesh.num_nodes(),
                 "stress output '" << out.name << "': node " << node << " is not in the mesh of '"
                                   << out.body_file << "'");
    f.coordinates.row(static_cast<Eigen::Index>(i)) = mesh.nodes.col(node).transpose();
    local[static_cast<std::size_t>(node)] = static_cast<int>(i);
  }
  std::vector<int> sorted = group.nodes;
  std::sort(sorted.begin(), sorted.end());
  for (CellBlock b : SelectFaces(boundary, sorted).faces) {
    for (int& n : b.connectivity) n = local[static_cast<std::size_t>(n)];
    f.faces.push_back(std::move(b));
  }
  return f;
}

}  // namespace

StressRecorder::StressRecorder(const mbs::System& system, std::vector<StressOutput> outputs)
    : system_(system), outputs_(std::move(outputs)) {
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    StressOutput& out = outputs_[o];
    std::sort(out.field_times.begin(), out.field_times.end());
    std::sort(out.surface_field_times.begin(), out.surface_field_times.end());
    std::shared_ptr<const mbs::StressProbe> probe;
    for (const auto& p : system.probes())
      if (p->name() == out.name) probe = std::dynamic_pointer_cast<const mbs::StressProbe>(p);
    EMB_THROW_IF(!probe, "stress output '" << out.name
                                           << "': no stress probe of that name in "
                                              "the system");
    probes_.push_back(probe);
    EMB_CHECK(out.surface_field_times.empty() || probe->has_surface());
    next_field_.push_back(0);
    next_surface_.push_back(0);
    surfaces_.emplace_back();
    snapshots_.emplace_back();
    for (std::size_t g = 0; g < probe->groups().size(); ++g)
      groups_.push_back({static_cast<int>(o), static_cast<int>(g), {}, {}, {}, {}});
  }
}

bool StressRecorder::has_fatigue() const {
  return std::any_of(outputs_.begin(), outputs_.end(), [](const auto& o) { return o.fatigue; });
}

bool StressRecorder::has_fields() const {
  return std::any_of(outputs_.begin(), outputs_.end(), [](const auto& o) {
    return !o.field_times.empty() || !o.surface_field_times.empty();
  });
}

void StressRecorder::Add(const mbs::Sample& s) {
  const mbs::StateLayout& L = system_.layout();
  std::vector<char> take_field(outputs_.size(), 0);
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    take_field[o] = Due(outputs_[o].field_times, next_field_[o], s.t);
    if (!Due(outputs_[o].surface_field_times, next_surface_[o], s.t)) continue;
    const mbs::StressProbe& probe = *probes_[o];
    const int b = probe.body();
    surfaces_[o].t.push_back(s.t);
    surfaces_[o].field.push_back(
        probe.SurfaceStresses(s.q.segment(L.elastic_q(b), L.num_elastic(b))));
  }
  // Each output's probe evaluated once per sample, for all of its groups.
  std::vector<char> evaluated(outputs_.size(), 0);
  for (Group& g : groups_) {
    const auto o = static_cast<std::size_t>(g.output);
    const StressOutput& out = outputs_[o];
    if (!out.fatigue && !take_field[o]) continue;
    mbs::StressSnapshot& snap = snapshots_[o];
    if (!evaluated[o]) {
      const mbs::StressProbe& probe = *probes_[o];
      const int b = probe.body();
      probe.Evaluate(s.q.segment(L.elastic_q(b), L.num_elastic(b)), &snap);
      evaluated[o] = 1;
    }
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
        if (g.t[k] >= t0 && g.t[k] <= t1)
          history.push_back(g.measure[k][static_cast<Eigen::Index>(i)]);
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
  for (std::size_t o = 0; o < outputs_.size(); ++o)
    for (std::size_t k = next_surface_[o]; k < outputs_[o].surface_field_times.size(); ++k)
      missed.push_back(outputs_[o].surface_field_times[k]);
  return missed;
}

void StressRecorder::WriteFields(const std::string& h5_path, const std::string& xdmf_path) const {
  std::vector<NodalStressField> fields;
  // Per output, the body file's mesh and its boundary faces (for the groups' faces).
  std::vector<Mesh> meshes(outputs_.size());
  std::vector<BoundarySurface> boundaries(outputs_.size());
  for (const Group& g : groups_) {
    if (g.field.empty()) continue;
    const auto o = static_cast<std::size_t>(g.output);
    const StressOutput& out = outputs_[o];
    if (meshes[o].num_nodes() == 0) {
      const H5File body(out.body_file, H5File::Mode::kRead);
      EMB_THROW_IF(!body.Exists("/mesh/nodes"),
                   "stress output '" << out.name << "': body file '" << out.body_file
                                     << "' has no mesh (reduced with --no-mesh-shapes), which "
                                        "field_times need");
      meshes[o] = ReadMeshSection(body);
      boundaries[o] = ExtractBoundarySurface(meshes[o]);
    }
    NodalStressField f = GroupField(out, probes_[o]->groups()[static_cast<std::size_t>(g.index)],
                                    meshes[o], boundaries[o]);
    f.times = g.field_t;
    f.stress = g.field;
    fields.push_back(std::move(f));
  }
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    if (surfaces_[o].t.empty()) continue;
    const StressOutput& out = outputs_[o];
    NodalStressField f;
    f.path = "/" + out.name + "/surface";
    f.title = out.name + ".surface";
    f.nodes = probes_[o]->surface().nodes;
    f.coordinates = out.surface_coordinates;
    f.faces = out.surface_faces;
    f.times = surfaces_[o].t;
    f.stress = surfaces_[o].field;
    fields.push_back(std::move(f));
  }
  WriteStressFields(h5_path, xdmf_path, fields);
}

}  // namespace emb::results
