#include "libemb/scene/stress_output_reader.h"

#include <cmath>

#include "libemb/common/error.h"
#include "libemb/mbs/parts/stress_probe.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {
namespace {

// A list given must hold something, once each: an empty list or a repeated entry is a slip
// (leave the key out for its default).
template <typename T>
void CheckListed(const std::vector<T>& list, const std::string& file, const YAML::Node& n,
                 const std::string& what, const char* absent_means) {
  EMB_THROW_IF(list.empty(), Where(file, n) << ": " << what << ": expected at least one entry, "
                                            << "got an empty list (leave the key out for "
                                            << absent_means << ")");
  for (std::size_t i = 0; i < list.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      EMB_THROW_IF(list[i] == list[j], Where(file, n) << ": " << what << ": " << list[i]
                                                      << " is listed twice; expected each once");
}

std::vector<std::string> Strings(const YAML::Node& n, const std::string& file,
                                 const std::string& what) {
  EMB_THROW_IF(!n.IsSequence(), Where(file, n) << ": " << what << ": expected a list of names");
  std::vector<std::string> out;
  for (const auto& e : n) {
    EMB_THROW_IF(!e.IsScalar(), Where(file, e) << ": " << what << ": expected a name");
    out.push_back(e.Scalar());
  }
  CheckListed(out, file, n, what, "every group of the body file");
  return out;
}

std::vector<int> Nodes(const YAML::Node& n, const std::string& file, const std::string& what) {
  std::vector<int> out;
  for (double x : AsDoubles(n, file, what)) {
    EMB_THROW_IF(!(x >= 0.0 && x == std::floor(x) && x < 2147483647.0),
                 Where(file, n) << ": " << what << ": expected 0-based mesh node indices (the "
                                << "body file's node order, not gmsh's node tags), got " << x);
    out.push_back(static_cast<int>(x));
  }
  CheckListed(out, file, n, what, "no node channels");
  return out;
}

std::vector<long long> NodeTags(const YAML::Node& n, const std::string& file,
                                const std::string& what) {
  std::vector<long long> out;
  for (double x : AsDoubles(n, file, what)) {
    EMB_THROW_IF(!(x >= 1.0 && x == std::floor(x) && x < 2147483648.0),
                 Where(file, n) << ": " << what << ": expected the mesh file's node tags "
                                << "(integers from 1, as gmsh numbers nodes), got " << x);
    out.push_back(static_cast<long long>(x));
  }
  CheckListed(out, file, n, what, "no node channels");
  return out;
}

results::SnCurve ReadSn(MapReader& f, results::StressOutput* out) {
  out->measure = f.GetString("measure", out->measure);
  EMB_THROW_IF(out->measure != "max_principal" && out->measure != "signed_von_mises",
               f.what() << " measure: expected max_principal or signed_von_mises, got '"
                        << out->measure << "'");
  results::SnCurve sn;
  if (const YAML::Node pts = f.Optional("sn_points")) {
    EMB_THROW_IF(f.Has("fatigue_strength_coefficient") || f.Has("exponent"),
                 f.what() << ": expected either sn_points or fatigue_strength_coefficient and "
                             "exponent (Basquin), not both");
    EMB_THROW_IF(!pts.IsSequence(), f.what() << " sn_points: expected a list of [cycles, "
                                                "amplitude Pa] pairs");
    for (const YAML::Node& p : pts) {
      const std::vector<double> v = AsDoubles(p, f.file(), f.what() + " sn_points");
      EMB_THROW_IF(v.size() != 2, f.what() << " sn_points: expected [cycles, amplitude Pa] "
                                              "pairs, got a list of "
                                           << v.size());
      sn.points.push_back({v[0], v[1]});
    }
  } else {
    sn.fatigue_strength_coefficient = f.GetDouble("fatigue_strength_coefficient");
    sn.exponent = f.GetDouble("exponent");
  }
  sn.ultimate_strength = f.GetDouble("ultimate_strength");
  sn.endurance_limit = f.GetDouble("endurance_limit", 0.0);
  sn.Validate(f.what());
  return sn;
}

}  // namespace

void CheckStressOutputTimes(const std::vector<results::StressOutput>& outputs, double t_start,
                            double t_end) {
  for (const results::StressOutput& o : outputs)
    for (auto [key, times] : {std::pair{"field_times", &o.field_times},
                              std::pair{"surface_field_times", &o.surface_field_times}})
      for (double t : *times)
        EMB_THROW_IF(t < t_start || t > t_end,
                     "stress output '" << o.name << "' " << key << ": " << t << " s is "
                                       << (t < t_start ? "before the run's start" : "after the run's end")
                                       << "; expected times in [t_start, t_end] = [" << t_start
                                       << ", " << t_end << "] s");
}

std::vector<results::StressOutput> ReadStressOutputs(
    const YAML::Node& list, const std::string& file, mbs::System* sys,
    const std::map<std::string, mbs::FlexiblePart>& body_file_parts,
    const std::map<std::string, PartStresses>& stresses) {
  std::vector<results::StressOutput> outputs;
  ReadNamedList(
      list, file, "stress_outputs", "stress output",
      [&](MapReader& r, const std::string& name, const YAML::Node&) {
        results::StressOutput out;
        out.name = name;
        out.body = r.GetString("body");
        mbs::StressProbeSpec spec;
        spec.name = name;
        if (const YAML::Node g = r.Optional("groups"))
          spec.groups = Strings(g, file, r.what() + " groups");
        if (const YAML::Node n = r.Optional("nodes")) spec.nodes = Nodes(n, file, r.what() + " nodes");
        if (const YAML::Node n = r.Optional("node_tags"))
          spec.node_tags = NodeTags(n, file, r.what() + " node_tags");
        for (auto [key, times] : {std::pair{"field_times", &out.field_times},
                                  std::pair{"surface_field_times", &out.surface_field_times}}) {
          if (!r.Has(key)) {
            r.Optional(key);
            continue;
          }
          *times = r.GetDoubles(key);
          for (double t : *times)
            EMB_THROW_IF(!std::isfinite(t),
                         r.what() << " " << key << ": expected finite times [s], got " << t);
          CheckListed(*times, file, r.node(), r.what() + " " + key, "no fields");
        }
        spec.surface = !out.surface_field_times.empty();
        if (const YAML::Node f = r.Optional("fatigue")) {
          MapReader fr(f, file, r.what() + " fatigue", "stress_outputs: fatigue");
          out.fatigue = true;
          out.sn = ReadSn(fr, &out);
          fr.Finish();
        }
        r.Finish();
        const auto part = body_file_parts.find(out.body);
        if (part == body_file_parts.end()) {
          sys->FindBody(out.body);  // an unknown body: did-you-mean
          EMB_THROW(InputError, "stress output '" << name << "': body '" << out.body
                                                  << "' is not a part from a body file; "
                                                     "expected a cms part");
        }
        out.body_file = part->second.source;
        const auto stored = stresses.find(out.body);
        EMB_CHECK(stored != stresses.end());
        sys->AddProbe(mbs::MakeStressProbe(part->second, stored->second.groups, spec,
                                           &stored->second.surface));
        if (spec.surface) {
          out.surface_coordinates = stored->second.surface.coordinates;
          out.surface_faces = stored->second.surface.faces;
        }
        outputs.push_back(std::move(out));
      });
  return outputs;
}

}  // namespace emb::scene
