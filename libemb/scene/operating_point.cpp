#include "libemb/scene/operating_point.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <sstream>

#include "libemb/common/error.h"

namespace emb::scene {
namespace {

void ScaleVector(YAML::Node node, double factor) {
  if (!node || !node.IsSequence()) return;
  for (std::size_t i = 0; i < node.size(); ++i) node[i] = node[i].as<double>() * factor;
}

}  // namespace

std::string SceneTextAtSpeed(const std::string& yaml_text, const std::string& source, double rpm,
                             SpeedChange* change) {
  EMB_THROW_IF(!std::isfinite(rpm) || !(rpm > 0.0),
               source << ": speed: expected rpm > 0, got " << rpm);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    EMB_THROW(InputError, source << ":" << e.mark.line + 1 << ": YAML syntax error: " << e.msg);
  }
  SpeedChange c;
  c.rpm = rpm;
  YAML::Node found;
  int count = 0;
  if (const YAML::Node motions = root["motions"]; motions && motions.IsSequence()) {
    for (std::size_t i = 0; i < motions.size(); ++i) {
      const YAML::Node f = motions[i]["function"];
      if (f && f.IsMap() && f["rpm"]) {
        ++count;
        found = motions[i];
      }
    }
  }
  EMB_THROW_IF(count == 0, source << ": expected a motion with function {rpm: ...} that sets "
                                     "the speed; the scene has none");
  EMB_THROW_IF(count > 1, source << ": expected one motion with function {rpm: ...} that sets "
                                    "the speed; the scene has "
                                 << count);
  c.motion = found["name"] ? found["name"].as<std::string>() : std::string("?");
  try {
    c.nominal_rpm = found["function"]["rpm"].as<double>();
  } catch (const YAML::Exception&) {
    EMB_THROW(InputError, source << ": motion '" << c.motion << "' rpm: expected a number");
  }
  EMB_THROW_IF(!(std::abs(c.nominal_rpm) > 0.0),
               source << ": motion '" << c.motion
                      << "' rpm: expected a non-zero speed to scale the initial velocities from");
  c.factor = rpm / c.nominal_rpm;
  found["function"]["rpm"] = rpm;
  try {
    if (const YAML::Node bodies = root["bodies"]; bodies && bodies.IsSequence())
      for (std::size_t i = 0; i < bodies.size(); ++i) {
        ScaleVector(bodies[i]["velocity"], c.factor);
        ScaleVector(bodies[i]["angular_velocity"], c.factor);
      }
    // The cycle keeps its number of output samples (the period must be a whole number of
    // output steps).
    if (YAML::Node ss = root["analysis"]["steady_state"]; ss && ss["period"]) {
      ss["period"] = ss["period"].as<double>() / c.factor;
      if (YAML::Node a = root["analysis"]; a["output_step"])
        a["output_step"] = a["output_step"].as<double>() / c.factor;
    }
  } catch (const YAML::Exception& e) {
    // The nominal scene would fail to load with a precise message; say which speed failed.
    EMB_THROW(InputError, source << ": cannot set the speed to " << rpm << " rpm: " << e.msg);
  }
  if (change) *change = c;
  YAML::Emitter out;
  out << root;
  return out.c_str();
}

Scene LoadSceneAtSpeed(const std::string& path, double rpm, const SceneOptions& options,
                       SpeedChange* change) {
  return LoadSceneText(SceneTextAtSpeed(ReadSceneText(path), path, rpm, change), path, options);
}

}  // namespace emb::scene
