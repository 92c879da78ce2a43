#include "libemb/scene/scene_at_speed.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {
namespace {

// Round-trip text of a double (17 significant digits).
std::string Text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// Multiplies a number or a list of numbers in place by `factor`.
void Scale(YAML::Node node, double factor, const std::string& source, const std::string& what) {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      node[i] = Text(AsDouble(node[i], source, what) * factor);
    return;
  }
  node = Text(AsDouble(node, source, what) * factor);
}

// The single key of a function map ({rpm: 3000} -> "rpm"), or "" if it is not a map.
std::string FunctionKind(const YAML::Node& f) {
  if (!f.IsMap()) return "";
  for (const auto& kv : f) {
    const std::string key = kv.first.Scalar();
    if (key != "constants" && key != "scale") return key;
  }
  return "";
}

std::string NameOf(const YAML::Node& entry) {
  return entry.IsMap() && entry["name"] ? entry["name"].Scalar() : std::string("?");
}

}  // namespace

SceneAtSpeed SceneTextAtSpeed(const std::string& yaml_text, const std::string& source,
                              double rpm) {
  EMB_THROW_IF(!(rpm >= kMinSpeedRpm && rpm <= kMaxSpeedRpm),
               source << ": speed: expected " << kMinSpeedRpm << " to " << kMaxSpeedRpm
                      << " rpm, got " << rpm);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    EMB_THROW(InputError, source << ":" << e.mark.line + 1 << ": YAML syntax error: " << e.msg);
  }
  EMB_THROW_IF(!root.IsMap(), source << ": expected a scene (a YAML map)");
  SceneAtSpeed out;
  out.rpm = rpm;
  // The speed: every motion with {rpm: n0}; they must agree on n0.
  std::vector<YAML::Node> rpm_functions;
  std::string first_motion;
  if (const YAML::Node motions = root["motions"]; motions && motions.IsSequence()) {
    for (const auto& m : motions) {
      const YAML::Node f = m["function"];
      const std::string kind = FunctionKind(f);
      if (kind == "rpm") {
        const double n0 = AsDouble(f["rpm"], source, "motion '" + NameOf(m) + "' rpm");
        EMB_THROW_IF(!(n0 > 0.0), Where(source, f) << ": motion '" << NameOf(m)
                                                   << "' rpm: expected > 0 to scale the speed, got "
                                                   << n0);
        EMB_THROW_IF(!rpm_functions.empty() && std::abs(n0 - out.reference_rpm) >
                                                   1e-12 * out.reference_rpm,
                     Where(source, f) << ": motion '" << NameOf(m) << "' runs at " << n0
                                      << " rpm, motion '" << first_motion << "' at "
                                      << out.reference_rpm << " rpm: expected one speed to scale");
        if (rpm_functions.empty()) first_motion = NameOf(m);
        out.reference_rpm = n0;
        rpm_functions.push_back(f);
        out.changes.push_back("motion '" + NameOf(m) + "'");
      } else if (kind != "constant") {
        EMB_THROW(InputError, Where(source, m)
                                  << ": motion '" << NameOf(m) << "' has a '" << kind
                                  << "' function of time, which cannot be scaled to another "
                                     "speed; expected {rpm: N} (or {constant: x})");
      }
    }
  }
  EMB_THROW_IF(rpm_functions.empty(),
               source << ": no motion with function {rpm: N}: expected one that drives the "
                         "engine at constant speed (e.g. {name: crank_speed, joint: "
                         "dyno_bearing, coordinate: rotation, function: {rpm: 3000}})");
  out.ratio = rpm / out.reference_rpm;
  const double s = out.ratio;
  for (YAML::Node f : rpm_functions) f["rpm"] = Text(rpm);
  for (std::string& c : out.changes)
    c += ": rpm " + Text(out.reference_rpm) + " -> " + Text(rpm);
  // Loads driven by time (not by a crank angle `argument`) have their own time scale.
  if (const YAML::Node forces = root["forces"]; forces && forces.IsSequence()) {
    for (const auto& f : forces) {
      const YAML::Node fn = f["function"];
      if (!fn || f["argument"]) continue;
      const std::string kind = FunctionKind(fn);
      EMB_THROW_IF(kind != "constant",
                   Where(source, f) << ": force '" << NameOf(f) << "' has a '" << kind
                                    << "' function of time, which cannot be scaled to another "
                                       "speed; expected a crank-angle argument or {constant: x}");
    }
  }
  // Initial velocities scale with the speed (the kinematics is linear in it).
  if (const YAML::Node bodies = root["bodies"]; bodies && bodies.IsSequence()) {
    for (YAML::Node b : bodies) {
      for (const char* key : {"velocity", "angular_velocity", "modal_velocities"}) {
        if (!b.IsMap() || !b[key]) continue;
        Scale(b[key], s, source, "body '" + NameOf(b) + "' " + key);
        out.changes.push_back("body '" + NameOf(b) + "' " + key + " x " + Text(s));
      }
    }
  }
  // Times scale with the period.
  if (YAML::Node analysis = root["analysis"]; analysis && analysis.IsMap()) {
    for (const char* key : {"t_start", "t_end", "output_step", "max_step"}) {
      if (!analysis[key]) continue;
      Scale(analysis[key], 1.0 / s, source, std::string("analysis ") + key);
      out.changes.push_back(std::string("analysis ") + key + " / " + Text(s));
    }
    if (YAML::Node ss = analysis["steady_state"]; ss && ss.IsMap() && ss["period"]) {
      Scale(ss["period"], 1.0 / s, source, "analysis steady_state period");
      out.changes.push_back("analysis steady_state period / " + Text(s));
    }
  }
  YAML::Emitter emit;
  emit << root;
  EMB_THROW_IF(!emit.good(), source << ": cannot write the scene at " << rpm
                                    << " rpm: " << emit.GetLastError());
  out.yaml = emit.c_str();
  return out;
}

Scene LoadSceneAtSpeed(const std::string& path, double rpm, const SceneOptions& options,
                       SceneAtSpeed* at_speed) {
  SceneAtSpeed s = SceneTextAtSpeed(ReadSceneText(path), path, rpm);
  Scene scene = ParseScene(s.yaml, path, options);
  scene.output = OutputSpec{};
  if (at_speed) *at_speed = std::move(s);
  return scene;
}

}  // namespace emb::scene
