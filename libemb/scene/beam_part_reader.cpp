#include "libemb/scene/beam_part_reader.h"

#include <filesystem>

#include "libemb/common/error.h"
#include "libemb/scene/scene_parts.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {

bool IsBeamPart(const YAML::Node& body) {
  return body.IsMap() && body["model"] && body["model"].IsScalar() &&
         body["model"].as<std::string>() == "beam";
}

BeamPartSpec ReadBeamPart(const YAML::Node& node, const std::string& file) {
  MapReader r0(node, file, "body", "bodies");
  BeamPartSpec s;
  s.name = r0.GetString("name");
  const std::string what = "body '" + s.name + "'";
  MapReader r(node, file, what, "bodies");
  r.GetString("name");
  r.GetString("model");
  r.set_section("bodies: beam");
  s.geometry = r.GetString("geometry");
  if (std::filesystem::path(s.geometry).is_relative())
    s.geometry = (std::filesystem::path(file).parent_path() / s.geometry).string();
  BeamGenerationOptions& g = s.generation;
  if (const YAML::Node p = r.Optional("parameters")) {
    EMB_THROW_IF(!p.IsMap(), Where(file, p) << ": " << what << " parameters: expected a map");
    for (const auto& kv : p) {
      EMB_THROW_IF(!kv.first.IsScalar(),
                   Where(file, kv.first) << ": " << what << " parameters: expected NAME: VALUE");
      g.parameters.emplace_back(
          kv.first.Scalar(),
          AsDouble(kv.second, file, what + " parameter '" + kv.first.Scalar() + "'"));
    }
  }
  const std::string webs = r.GetString("webs", "rigid");
  EMB_THROW_IF(webs != "rigid" && webs != "elastic",
               Where(file, node) << ": " << what << " webs: expected rigid or elastic, got '"
                                 << webs << "'");
  g.webs = webs == "rigid" ? WebModel::kRigid : WebModel::kElastic;
  g.web_width = r.GetDouble("web_width", 0.0, NumberRange::NonNegative("m"));
  if (r.Has("beam_nodes")) {
    const YAML::Node n = r.Optional("beam_nodes");
    try {
      s.nodes = mbs::ParseBeamPartNodes(r.GetString("beam_nodes"));
    } catch (const InputError& e) {
      EMB_THROW(InputError, Where(file, n) << ": " << what << " " << e.what());
    }
  }
  // The element count is the part's length over this: bounded below.
  g.max_element_length = r.GetDouble("element_length", g.max_element_length,
                                     NumberRange::Closed(1e-4, 100.0, "m"));
  g.stiffness_damping =
      r.GetDouble("stiffness_damping", g.stiffness_damping, NumberRange::NonNegative("s"));
  if (const YAML::Node m = r.Optional("material")) {
    MapReader rm(m, file, what + " material", "bodies: beam material");
    g.material.youngs_modulus = rm.GetDouble("E", g.material.youngs_modulus);
    g.material.poisson_ratio = rm.GetDouble("nu", g.material.poisson_ratio);
    g.material.density = rm.GetDouble("rho", g.material.density);
    rm.Finish();
  }
  s.placement.p_WP = r.GetVector3("position", Eigen::Vector3d::Zero());
  if (const YAML::Node o = r.Optional("orientation"))
    s.placement.R_WP = ReadOrientation(o, file, what + " orientation");
  s.placement.omega_W = r.GetVector3("angular_velocity", Eigen::Vector3d::Zero());
  // The keys of `model: rigid|cms` parts from a body file may stay in the entry, so that a
  // scene switches models with the one word `model:` (they are not used here).
  for (const char* key : {"modes", "fmax_hz", "dynamic_band_hz", "basis",
                          "quasi_static_relaxation", "geometric_stiffening",
                          "expect_mesh_hash", "modal_coordinates", "modal_velocities"})
    r.Ignore(key);
  if (r.Has("body_file")) {
    s.body_file = r.GetString("body_file");
    if (std::filesystem::path(s.body_file).is_relative())
      s.body_file = (std::filesystem::path(file).parent_path() / s.body_file).string();
  } else {
    r.Optional("body_file");
  }
  r.Finish();
  return s;
}

}  // namespace emb::scene
