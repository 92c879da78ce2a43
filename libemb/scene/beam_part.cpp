#include "libemb/scene/beam_part.h"

#include <filesystem>
#include <memory>

#include "libemb/common/error.h"
#include "libemb/linalg/cross_matrix.h"
#include "libemb/mbs/flexible/beam_force.h"
#include "libemb/scene/scene_parts.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Mass points of one node in the part frame: mass, centre, inertia about the centre.
struct Lump {
  double m{0.0};
  Vector3d first{Vector3d::Zero()};     // Σ m c
  Matrix3d second{Matrix3d::Zero()};    // Σ (I_c + m (|c|² 1 − c cᵀ)) about P's origin
  void Add(double mi, const Vector3d& c, const Matrix3d& I_c) {
    m += mi;
    first += mi * c;
    second += I_c + mi * (c.squaredNorm() * Matrix3d::Identity() - c * c.transpose());
  }
};

// Beam node of interface `name` (see the header), or −1.
int InterfaceNode(const GeneratedBeamModel& g, const std::string& name) {
  const BeamModel& m = g.model;
  auto find = [&](const std::string& n) {
    for (int i = 0; i < m.num_nodes(); ++i)
      if (m.nodes()[i].name == n) return i;
    return -1;
  };
  if (name == "flange") return find("flange:end");
  if ((name == "end_a" || name == "end_b") && g.parts.size() == 1)
    return find(g.parts[0].name + (name == "end_a" ? ":start" : ":end"));
  return find(name);
}

}  // namespace

BeamPartInfo AddBeamPart(const BeamPartSpec& spec, mbs::System* sys) {
  const GeneratedBeamModel g = MakeBeamModelFromGeometry(spec.geometry, spec.generation);
  const BeamModel& model = g.model;
  const Matrix3d& R = spec.orientation;
  auto to_world = [&](const Vector3d& p_P) -> Vector3d { return spec.position + R * p_P; };

  // Lumped masses per node (part frame).
  std::vector<Lump> lumps(model.num_nodes());
  for (int e = 0; e < model.num_elements(); ++e) {
    const BeamElement& el = model.elements()[e];
    const Vector12d d = CalcBeamLumpedMass(model.ElementProperties(e));
    const Matrix3d R_PB = model.ElementFrame(e);
    const auto [pa, pb] = model.ElasticEnds(e);
    lumps[el.node_a].Add(d[kUx], pa, R_PB * d.segment<3>(kThetaX).asDiagonal() * R_PB.transpose());
    lumps[el.node_b].Add(d[6 + kUx], pb,
                         R_PB * d.segment<3>(6 + kThetaX).asDiagonal() * R_PB.transpose());
  }
  for (const RigidPart& r : model.rigid_parts())
    lumps[r.node].Add(r.mass, model.nodes()[r.node].p_W + r.p_NC_W, r.I_C_W);

  BeamPartInfo info;
  std::vector<Vector3d> com(model.num_nodes());
  for (int i = 0; i < model.num_nodes(); ++i) {
    const Lump& l = lumps[i];
    const std::string body = spec.name + "/" + model.nodes()[i].name;
    EMB_THROW_IF(!(l.m > 0.0), "beam part '" << spec.name << "': node '" << model.nodes()[i].name
                                             << "' carries no mass; expected every node on an "
                                                "element or a rigid part");
    com[i] = l.first / l.m;
    mbs::RigidBody b;
    b.name = body;
    b.mass = l.m;
    const Matrix3d I_c =
        l.second - l.m * (com[i].squaredNorm() * Matrix3d::Identity() - com[i] * com[i].transpose());
    b.inertia_B = R * (0.5 * (I_c + I_c.transpose())) * R.transpose();
    b.p_WB = to_world(com[i]);
    b.R_WB = Matrix3d::Identity();
    b.omega_W = spec.angular_velocity;
    b.v_WB = spec.angular_velocity.cross(b.p_WB - spec.position);
    sys->AddBody(b);
    info.bodies.push_back(body);
  }
  // A marker on node i's body at part point p_P with part-frame axes R_PM.
  auto add_marker = [&](const std::string& name, int i, const Vector3d& p_P, const Matrix3d& R_PM) {
    sys->AddMarker(name, spec.name + "/" + model.nodes()[i].name, R * (p_P - com[i]), R * R_PM);
    return sys->FindMarker(name);
  };
  for (int e = 0; e < model.num_elements(); ++e) {
    const BeamElement& el = model.elements()[e];
    const auto [pa, pb] = model.ElasticEnds(e);
    const Matrix3d R_PB = model.ElementFrame(e);
    const std::string base = spec.name + "/" + el.name;
    const int mi = add_marker(base + ":a", el.node_a, pa, R_PB);
    const int mj = add_marker(base + ":b", el.node_b, pb, R_PB);
    sys->AddForceElement(std::make_shared<mbs::BeamForce>(base, mi, mj, model.ElementProperties(e),
                                                          model.stiffness_damping()));
    info.forces.push_back(base);
  }
  std::vector<std::string> names{"nose", "flange", "end_a", "end_b"};
  for (int k = 1; k <= 9; ++k) {
    names.push_back("main_journal_" + std::to_string(k));
    names.push_back("crankpin_" + std::to_string(k));
  }
  for (const std::string& n : names) {
    const int node = InterfaceNode(g, n);
    if (node < 0) continue;
    const std::string marker = spec.name + "." + n;
    add_marker(marker, node, model.nodes()[node].p_W, Matrix3d::Identity());
    info.interfaces.emplace_back(marker, model.nodes()[node].name);
  }
  return info;
}

bool IsBeamPart(const YAML::Node& body) {
  return body.IsMap() && body["model"] && body["model"].IsScalar() &&
         body["model"].as<std::string>() == "beam";
}

BeamPartSpec ReadBeamPart(const YAML::Node& node, const std::string& file) {
  MapReader r0(node, file, "body");
  BeamPartSpec s;
  s.name = r0.GetString("name");
  const std::string what = "body '" + s.name + "'";
  MapReader r(node, file, what);
  r.GetString("name");
  r.GetString("model");
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
               Where(file, node) << ": " << what << " webs: expected rigid or elastic, got '" << webs
                                 << "'");
  g.webs = webs == "rigid" ? WebModel::kRigid : WebModel::kElastic;
  g.web_width = r.GetDouble("web_width", 0.0, NumberRange::NonNegative("m"));
  // The element count is the part's length over this: bounded below.
  g.max_element_length = r.GetDouble("element_length", g.max_element_length,
                                     NumberRange::Closed(1e-4, 100.0, "m"));
  g.stiffness_damping =
      r.GetDouble("stiffness_damping", g.stiffness_damping, NumberRange::NonNegative("s"));
  if (const YAML::Node m = r.Optional("material")) {
    MapReader rm(m, file, what + " material");
    g.material.youngs_modulus = rm.GetDouble("E", g.material.youngs_modulus);
    g.material.poisson_ratio = rm.GetDouble("nu", g.material.poisson_ratio);
    g.material.density = rm.GetDouble("rho", g.material.density);
    rm.Finish();
  }
  s.position = r.GetVector3("position", Vector3d::Zero());
  if (const YAML::Node o = r.Optional("orientation"))
    s.orientation = ReadOrientation(o, file, what + " orientation");
  s.angular_velocity = r.GetVector3("angular_velocity", Vector3d::Zero());
  // The keys of `model: rigid|cms` parts from a body file may stay in the entry, so that a
  // scene switches models with the one word `model:` (they are not used here).
  for (const char* key : {"body_file", "modes", "fmax_hz", "geometric_stiffening",
                          "expect_mesh_hash", "modal_coordinates"})
    r.Optional(key);
  r.Finish();
  return s;
}

}  // namespace emb::scene
