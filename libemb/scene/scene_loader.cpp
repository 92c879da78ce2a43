#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <tuple>
#include <utility>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/io/output_path.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/parts/beam_part.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "libemb/mbs/forces/applied_load.h"
#include "libemb/mbs/forces/bushing.h"
#include "libemb/mbs/forces/spring_damper.h"
#include "libemb/results/channels.h"
#include "libemb/scene/beam_part_reader.h"
#include "libemb/scene/output_point_reader.h"
#include "libemb/scene/stress_output_reader.h"
#include "libemb/scene/scene.h"
#include "libemb/scene/scene_parts.h"
#include "libemb/scene/sensor_reader.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Parts of the scene that are not single rigid bodies, by part name (for the markers on
// their interfaces).
struct Parts {
  std::map<std::string, mbs::FlexiblePart> from_body_files;
  /// The modal stresses of those parts' body files (cms/modal_stress.h), by part.
  std::map<std::string, PartStresses> stresses;
  std::map<std::string, mbs::BeamPart> beams;
  std::map<std::string, BeamPartOutputs> beam_outputs;  // the same, for output points
  /// Parts with `basis: installed` (the analysis builds their basis at the start).
  std::vector<mbs::InstalledBasisRequest> installed_bases;
  /// Interface markers on flexible body-file parts: marker, part, interface index (the
  /// truncation error indicator needs their shapes in the full basis).
  struct InterfaceMarker {
    std::string marker, part;
    int interface{-1};
  };
  std::vector<InterfaceMarker> interface_markers;
};

// The flexible body-file parts without an installed basis, with their full bases and
// interface markers, for the truncation error indicator (mbs/analysis/basis_truncation.h).
std::vector<mbs::TruncatedBasis> TruncatedBases(const Parts& parts) {
  std::vector<mbs::TruncatedBasis> out;
  for (const auto& entry : parts.from_body_files) {
    // Not a structured binding: clang 14 cannot capture those in the lambda below.
    const std::string& name = entry.first;
    const auto& part = entry.second;
    if (!part.flexible || std::any_of(parts.installed_bases.begin(), parts.installed_bases.end(),
                                      [&](const auto& r) { return r.body == name; }))
      continue;
    mbs::TruncatedBasis tb;
    tb.body = name;
    tb.source = part.source;
    tb.full_eigenvalues = part.available_eigenvalues;
    tb.kept = part.kept_modes;
    for (const Parts::InterfaceMarker& m : parts.interface_markers)
      if (m.part == name)
        tb.markers.emplace_back(m.marker, part.available_interface_shapes.middleRows(6 * m.interface, 6));
    out.push_back(std::move(tb));
  }
  return out;
}

// A path in the scene relative to the scene file's directory.
std::string ScenePath(const std::string& file, const std::string& p) {
  if (std::filesystem::path(p).is_absolute()) return p;
  return (std::filesystem::path(file).parent_path() / p).lexically_normal().string();
}

mbs::FlexibleBodyOptions ReadFlexibleBodyOptions(MapReader& rb, bool flexible) {
  mbs::FlexibleBodyOptions o;
  o.flexible = flexible;
  o.modes.max_modes = rb.GetInt("modes", -1, 0, 100000);  // -1 (absent): all
  o.modes.fmax_hz = rb.GetDouble("fmax_hz", -1.0, NumberRange::Positive("Hz"));  // -1: no limit
  o.modes.dynamic_band_hz =
      rb.GetDouble("dynamic_band_hz", -1.0, NumberRange::Positive("Hz"));  // -1: all dynamic
  if (rb.Has("geometric_stiffening"))
    o.geometric_stiffening = rb.GetBool("geometric_stiffening", true)
                                 ? mbs::GeometricStiffening::kOn
                                 : mbs::GeometricStiffening::kOff;
  else
    rb.Optional("geometric_stiffening");
  return o;
}

// A part from a body file (`model: rigid|cms` with `body_file`), built by
// mbs/flexible/flexible_body.h.
void ReadBodyFilePart(MapReader& rb, const std::string& file, bool flexible, mbs::System* sys,
                      Parts* parts, std::vector<std::string>* notes,
                      std::vector<std::string>* inputs) {
  const std::string& what = rb.what();
  for (const char* key : {"mass", "inertia"})
    EMB_THROW_IF(rb.Has(key), what << ": '" << key << "' comes from the body file; remove it");
  const std::string name = rb.GetString("name");
  rb.set_section("bodies: body file");
  const std::string path = ScenePath(file, rb.GetString("body_file"));
  inputs->push_back(path);
  mbs::FlexibleBodyOptions options = ReadFlexibleBodyOptions(rb, flexible);
  const std::string basis = rb.GetString("basis", "free-free");
  EMB_THROW_IF(basis != "free-free" && basis != "installed",
               what << " basis: expected 'free-free' or 'installed', got '" << basis << "'");
  if (basis == "installed" && flexible) {
    EMB_THROW_IF(options.modes.dynamic_band_hz < 0.0,
                 what << ": basis 'installed' needs dynamic_band_hz (the band of installed "
                         "modes to keep dynamic) [Hz]");
    mbs::InstalledBasisRequest request{name, options.modes.dynamic_band_hz};
    request.relaxation = rb.GetDouble("quasi_static_relaxation", request.relaxation,
                                      NumberRange::Closed(0.0, 10.0));
    parts->installed_bases.push_back(request);
    options.modes.dynamic_band_hz = -1.0;  // the installed basis decides what is quasi-static
  } else {
    EMB_THROW_IF(rb.Has("quasi_static_relaxation"),
                 what << ": quasi_static_relaxation is for basis 'installed'");
  }
  const std::string expect_mesh_hash = rb.GetString("expect_mesh_hash", "");
  mbs::PartPlacement placement;
  placement.p_WM = rb.GetVector3("position", Vector3d::Zero());
  if (const YAML::Node o = rb.Optional("orientation"))
    placement.R_WM = ReadOrientation(o, file, what + " orientation");
  if (rb.Has("velocity"))
    placement.v_WB = rb.GetVector3("velocity");
  else
    rb.Optional("velocity");
  placement.omega_W = rb.GetVector3("angular_velocity", Vector3d::Zero());
  // The keys of `model: beam` (beam_part_reader.h) may stay in the entry: one-word switch.
  for (const char* key : {"geometry", "parameters", "webs", "web_width", "beam_nodes", "element_length",
                          "stiffness_damping", "material"})
    rb.Ignore(key);
  // Initial modal coordinates eta(t0) and rates eta'(t0), one per kept mode (AsDouble refuses
  // non-finite numbers). A key given with an empty list is refused below: leaving it out
  // means zeros, an empty list more likely a script that wrote nothing.
  std::vector<double> eta0, eta_dot0;
  bool given[2] = {false, false};
  for (auto [key, values, was_given] :
       {std::tuple{"modal_coordinates", &eta0, &given[0]},
        std::tuple{"modal_velocities", &eta_dot0, &given[1]}}) {
    *was_given = rb.Has(key);
    if (*was_given)
      *values = rb.GetDoubles(key);
    else
      rb.Optional(key);
  }
  rb.Finish();
  ReducedBody reduced = mbs::ReadPartBodyFile(path, name, expect_mesh_hash);
  mbs::FlexibleBodyModel m = mbs::MakeFlexibleBody(name, reduced, path, options, placement);
  for (auto [key, values, target, was_given] :
       {std::tuple{"modal_coordinates", &eta0, &m.body.eta0, given[0]},
        std::tuple{"modal_velocities", &eta_dot0, &m.body.eta_dot0, given[1]}}) {
    if (!was_given) continue;
    EMB_THROW_IF(static_cast<int>(values->size()) != m.part.num_modes(),
                 what << " " << key << ": expected " << m.part.num_modes() << " initial modal "
                      << (values == &eta0 ? "coordinates" : "velocities")
                      << " (one per mode kept), got " << values->size()
                      << (values->empty() ? " (leave the key out for zeros)" : ""));
    *target = Eigen::Map<const Eigen::VectorXd>(values->data(),
                                                static_cast<Eigen::Index>(values->size()));
  }
  m.part.body = sys->AddBody(m.body);
  notes->push_back(m.part.note);
  parts->from_body_files[name] = std::move(m.part);
  parts->stresses[name] = {std::move(reduced.stress_groups), std::move(reduced.stress_surface)};
}

void ReadBodies(const YAML::Node& list, const std::string& file, const SceneOptions& options,
                mbs::System* sys, Parts* parts, std::vector<std::string>* notes,
                std::vector<std::string>* inputs) {
  ReadNamedList(
      list, file, "bodies", "body",
      [&](MapReader& rb, const std::string& name, const YAML::Node& node) {
        if (IsBeamPart(node)) {  // model: beam (beam_part_reader.h)
          BeamPartSpec spec = ReadBeamPart(node, file);
          spec.generation.trust_scripts = options.trust_geo_scripts;
          inputs->push_back(spec.geometry);
          const GeneratedBeamModel beam = MakeBeamModelFromGeometry(spec.geometry, spec.generation);
          parts->beams[name] = mbs::AddBeamPart(
              sys, name, beam, spec.placement,
              spec.nodes ? *spec.nodes : mbs::DefaultBeamPartNodes(beam));
          if (parts->beams[name].nodes == mbs::BeamPartNodes::kCondensed)
            notes->push_back("beam part '" + name + "': " +
                             std::to_string(parts->beams[name].num_model_nodes) +
                             " beam nodes condensed onto " +
                             std::to_string(parts->beams[name].bodies.size()) +
                             " (rigid parts and interfaces; beam_nodes: all keeps them)");
          parts->beam_outputs[name] = {parts->beams[name], spec.placement, spec.body_file};
          if (!spec.body_file.empty()) inputs->push_back(spec.body_file);
          return;
        }
        const std::string model = rb.GetString("model", "rigid");
        EMB_THROW_IF(model != "rigid" && model != "cms",
                     Where(file, node)
                         << ": " << rb.what() << " model: expected 'rigid' or 'cms', got '" << model
                         << "'");
        const bool from_file = rb.Has("body_file");
        EMB_THROW_IF(model == "cms" && !from_file, Where(file, node)
                                                       << ": " << rb.what()
                                                       << ": model 'cms' needs a body_file (from "
                                                       << "emb reduce)");
        if (from_file) return ReadBodyFilePart(rb, file, model == "cms", sys, parts, notes, inputs);
        rb.set_section("bodies: rigid");
        mbs::RigidBody b;
        b.name = name;
        b.p_WB = rb.GetVector3("position", Vector3d::Zero());
        if (const YAML::Node o = rb.Optional("orientation"))
          b.R_WB = ReadOrientation(o, file, rb.what() + " orientation");
        b.v_WB = rb.GetVector3("velocity", Vector3d::Zero());
        b.omega_W = rb.GetVector3("angular_velocity", Vector3d::Zero());
        b.mass = rb.GetDouble("mass");
        b.inertia_B = ReadInertia(rb.Require("inertia"), file, rb.what() + " inertia");
        rb.Finish();
        sys->AddBody(b);
      });
}

void ReadMarkers(const YAML::Node& list, const std::string& file, mbs::System* sys,
                 Parts* parts) {
  ReadNamedList(
      list, file, "markers", "marker",
      [&](MapReader& r, const std::string& name, const YAML::Node& node) {
        const std::string body = r.GetString("body");
        const std::string frame = r.GetString("frame", "body");
        EMB_THROW_IF(frame != "body" && frame != "world",
                     Where(file, node)
                         << ": marker '" << name << "' frame: expected 'body' or 'world', got '"
                         << frame << "'");
        const std::string interface = r.GetString("interface", "");
        // With an interface, a position (part/mesh coordinates) is the point of a beam part's
        // interface node body the marker sits at; on a body-file part it must be the
        // interface's point (checked below).
        const bool at_point = r.Has("position");
        const Vector3d p = r.GetVector3("position", Vector3d::Zero());
        Matrix3d R = Matrix3d::Identity();
        if (const YAML::Node o = r.Optional("orientation"))
          R = ReadOrientation(o, file, "marker '" + name + "' orientation");
        r.Finish();
        // A beam part is no single body: an interface marker goes on the node body of the
        // interface, with the orientation in part axes (mbs/flexible/beam_part.h).
        if (const auto beam = parts->beams.find(body);
            beam != parts->beams.end() && !interface.empty()) {
          if (!at_point) {
            mbs::AddInterfaceMarker(sys, beam->second, name, interface, R);
            return;
          }
          // At part point p on the interface's node body (a beam section is rigid); axes R in
          // the part frame, as the interface marker's (which has the part's axes).
          const mbs::Marker& itf = sys->marker(sys->FindMarker(beam->second.FindInterface(interface).marker));
          const mbs::BeamPartPlacement& pl = parts->beam_outputs.at(body).placement;
          const mbs::RigidBody& nb = sys->body(itf.body);
          sys->AddMarker(name, nb.name, nb.R_WB.transpose() * (pl.p_WP + pl.R_WP * p - nb.p_WB),
                         itf.R_BM * R);
          return;
        }
        const int b = sys->FindBody(body);
        const mbs::RigidBody& rb = sys->body(b);
        const auto part = parts->from_body_files.find(body);
        if (!interface.empty()) {
          EMB_THROW_IF(
              part == parts->from_body_files.end(),
              "marker '" << name << "': body '" << body << "' has no body_file, so no interfaces");
          if (at_point) {
            const Vector3d q = part->second.interface_points.at(
                static_cast<std::size_t>(part->second.FindInterface(interface)));
            EMB_THROW_IF((q - p).norm() > 1e-9 * std::max(1.0, q.norm()),
                         Where(file, node) << ": marker '" << name << "': position "
                                           << p.transpose() << " is not the point of interface '"
                                           << interface << "' (" << q.transpose()
                                           << "); a marker on a part from a body file sits on "
                                              "its interface's point");
          }
          mbs::AddInterfaceMarker(sys, part->second, name, interface, R);
          parts->interface_markers.push_back({name, body, part->second.FindInterface(interface)});
          return;
        }
        EMB_THROW_IF(
            rb.elastic != nullptr,
            "marker '" << name << "': body '" << body
                       << "' is flexible; expected `interface: NAME` (a marker must sit on "
                          "an interface node to follow the deformation)");
        Vector3d p_BM = p;
        Matrix3d R_BM = R;
        if (frame == "world") {  // given at the initial configuration
          p_BM = rb.R_WB.transpose() * (p - rb.p_WB);
          R_BM = rb.R_WB.transpose() * R;
        } else if (part != parts->from_body_files.end()) {  // mesh coordinates
          p_BM = part->second.MeshToBody(p);
        }
        sys->AddMarker(name, body, p_BM, R_BM);
      });
}

void ReadJoints(const YAML::Node& list, const std::string& file, mbs::System* sys) {
  ReadNamedList(list, file, "joints", "joint",
                [&](MapReader& r, const std::string& name, const YAML::Node&) {
                  const std::string type = r.GetString("type");
                  const std::string i = r.GetString("i"), j = r.GetString("j");
                  r.Finish();
                  sys->AddJoint(name, mbs::ParseJointType(type), i, j);
                });
}

void ReadMotions(const YAML::Node& list, const std::string& file, mbs::System* sys) {
  ReadNamedList(list, file, "motions", "motion",
                [&](MapReader& r, const std::string& name, const YAML::Node&) {
                  const std::string joint = r.GetString("joint");
                  const mbs::JointCoordinate c = ReadCoordinate(r, "coordinate");
                  const mbs::TimeFunction f =
                      ReadFunction(r.Require("function"), file, r.what() + " function");
                  r.Finish();
                  sys->AddMotion(name, joint, c, f);
                });
}

void ReadCouplers(const YAML::Node& list, const std::string& file, mbs::System* sys) {
  ReadNamedList(list, file, "couplers", "coupler",
                [&](MapReader& r, const std::string& name, const YAML::Node&) {
                  const std::string j1 = r.GetString("joint1"), j2 = r.GetString("joint2");
                  const mbs::JointCoordinate c1 = ReadCoordinate(r, "coordinate1");
                  const mbs::JointCoordinate c2 = ReadCoordinate(r, "coordinate2");
                  const double ratio = r.GetDouble("ratio");
                  const double offset = r.GetDouble("offset", 0.0);
                  r.Finish();
                  sys->AddCoupler(name, j1, c1, j2, c2, ratio, offset);
                });
}

void ReadSteadyState(const YAML::Node& node, const std::string& file,
                     results::SteadyStateSettings* s) {
  MapReader r(node, file, "analysis steady_state", "analysis: steady_state");
  s->period = r.GetDouble("period", NumberRange::Positive("s"));
  const YAML::Node ch = r.Require("channels");
  EMB_THROW_IF(!ch.IsSequence(), Where(file, ch) << ": steady_state channels: expected a list");
  for (const auto& c : ch) s->channels.push_back(c.Scalar());
  s->tolerance = r.GetDouble("tolerance", s->tolerance, NumberRange::Positive());
  s->min_cycles = r.GetInt("min_cycles", s->min_cycles, 1, 100000);
  s->max_cycles = r.GetInt("max_cycles", s->max_cycles, 1, 100000);
  r.Finish();
}

void ReadAnalysis(const YAML::Node& node, const std::string& file, mbs::AnalysisSettings* s,
                  results::SteadyStateSettings* steady) {
  MapReader r(node, file, "analysis", "analysis");
  s->type = mbs::ParseAnalysisType(r.GetString("type", "dynamic"));
  using R = NumberRange;
  s->t_start = r.GetDouble("t_start", s->t_start, R::Finite("s"));
  s->t_end = r.GetDouble("t_end", s->t_end, R::Finite("s"));
  s->output_step = r.GetDouble("output_step", s->output_step, R::Positive("s"));
  s->ida.rtol = r.GetDouble("rtol", s->ida.rtol, R::Open(0.0, 1.0));
  s->ida.atol = r.GetDouble("atol", s->ida.atol, R::Positive());
  s->velocity_atol = r.GetDouble("velocity_atol", s->velocity_atol, R::NonNegative());
  s->ida.stop_at_outputs = r.GetBool("stop_at_outputs", s->ida.stop_at_outputs);
  s->atol_floor_relative =
      r.GetDouble("atol_floor_relative", s->atol_floor_relative, R::Closed(0.0, 1.0));
  s->initial_step_fraction =
      r.GetDouble("initial_step_fraction", s->initial_step_fraction, R::Closed(0.0, 1.0));
  s->newton_convergence_factor = r.GetDouble(
      "newton_convergence_factor", s->newton_convergence_factor, R::Open(0.0, 1.0));
  s->newton_refreshes = r.GetInt("newton_refreshes", s->newton_refreshes, -1, 10);
  s->ida.max_order = r.GetInt("max_order", s->ida.max_order, 1, 5);
  s->multiplier_atol = r.GetDouble("multiplier_atol", s->multiplier_atol, R::NonNegative("N"));
  if (r.Has("multiplier_atol_relative"))
    s->multiplier_atol_relative = r.GetDouble("multiplier_atol_relative", R::Open(0.0, 1.0));
  else
    r.Optional("multiplier_atol_relative");
  s->multiplier_atol_rtol_factor = r.GetDouble(
      "multiplier_atol_rtol_factor", s->multiplier_atol_rtol_factor, R::Open(0.0, 1.0e6));
  s->modal_velocity_atol_by_frequency =
      r.GetBool("modal_velocity_atol_by_frequency", s->modal_velocity_atol_by_frequency);
  s->ida.max_step = r.GetDouble("max_step", s->ida.max_step, R::NonNegative("s"));
  s->ida.max_num_steps =
      r.GetInt("max_steps", static_cast<int>(s->ida.max_num_steps), 1, 1000000000);
  s->max_events = r.GetInt("max_events", static_cast<int>(s->max_events), 1, 1000000000);
  try {
    s->ida.linear_solver = ParseLinearSolverKind(r.GetString("linear_solver", "auto"));
    s->integrator = mbs::ParseDynamicIntegrator(r.GetString("integrator", Name(s->integrator)));
    s->elastic_start = mbs::ParseElasticStart(r.GetString("elastic_start", Name(s->elastic_start)));
  } catch (const InputError& e) {
    EMB_THROW(InputError, Where(file, node) << ": analysis " << e.what());
  }
  s->rho_inf = r.GetDouble("rho_inf", s->rho_inf);
  EMB_THROW_IF(!(s->rho_inf >= 0.0 && s->rho_inf <= 1.0),
               Where(file, node) << ": analysis rho_inf: expected a value in [0, 1], got "
                                 << s->rho_inf);
  s->remove_redundant = r.GetBool("remove_redundant", s->remove_redundant);
  s->assembly.tolerance =
      r.GetDouble("assembly_tolerance", s->assembly.tolerance, R::Open(0.0, 1.0));
  s->assembly.max_iterations =
      r.GetInt("assembly_iterations", s->assembly.max_iterations, 1, 100000);
  s->static_force_tolerance =
      r.GetDouble("static_tolerance", s->static_force_tolerance, R::Open(0.0, 1.0));
  s->static_max_iterations = r.GetInt("static_iterations", s->static_max_iterations, 1, 100000);
  const bool t_end_given = r.Has("t_end");
  if (const YAML::Node n = r.Optional("steady_state")) {
    ReadSteadyState(n, file, steady);
    EMB_THROW_IF(t_end_given, Where(file, node)
                                  << ": analysis: give either t_end or steady_state (which "
                                     "ends the run at steady state or after max_cycles)");
    EMB_THROW_IF(s->type != mbs::AnalysisType::kDynamic,
                 Where(file, node) << ": analysis steady_state: only for a dynamic analysis");
    results::CheckSteadyStateSettings(*steady, s->output_step, Where(file, n));
    s->t_end = s->t_start + steady->max_cycles * steady->period;
  }
  r.Finish();
  EMB_THROW_IF(!(s->output_step > 0), Where(file, node) << ": analysis output_step: expected > 0");
  EMB_THROW_IF(!(s->t_end >= s->t_start), Where(file, node)
                                              << ": analysis: expected t_end >= t_start");
  EMB_THROW_IF(!(s->ida.rtol > 0 && s->ida.atol > 0),
               Where(file, node) << ": analysis: expected rtol > 0 and atol > 0, got "
                                 << s->ida.rtol << " and " << s->ida.atol);
  EMB_THROW_IF(!(s->atol_floor_relative >= 0 && s->multiplier_atol >= 0 &&
                 s->multiplier_atol_relative >= 0 && s->multiplier_atol_rtol_factor > 0 &&
                 s->initial_step_fraction >= 0),
               Where(file, node) << ": analysis: expected atol_floor_relative >= 0, "
                                    "multiplier_atol >= 0, multiplier_atol_relative >= 0, "
                                    "multiplier_atol_rtol_factor > 0 and "
                                    "initial_step_fraction >= 0, got "
                                 << s->atol_floor_relative << ", " << s->multiplier_atol << ", "
                                 << s->multiplier_atol_relative << ", "
                                 << s->multiplier_atol_rtol_factor << " and "
                                 << s->initial_step_fraction);
  EMB_THROW_IF(s->static_max_iterations < 1,
               Where(file, node) << ": analysis static_iterations: expected >= 1, got "
                                 << s->static_max_iterations);
}

// `planar: true` (the plane normal is the world z axis) or `planar: {normal: [x, y, z]}`
// (mbs::AnalysisSettings::plane_normal); `planar: false` is the default, a 3-D model.
Vector3d ReadPlanar(const YAML::Node& node, const std::string& file) {
  if (node.IsScalar()) {
    try {
      return node.as<bool>() ? Vector3d(Vector3d::UnitZ()) : Vector3d(Vector3d::Zero());
    } catch (const YAML::Exception&) {
      EMB_THROW(InputError, Where(file, node) << ": planar: expected true, false or "
                                                 "{normal: [x, y, z]}, got '"
                                              << node.Scalar() << "'");
    }
  }
  MapReader r(node, file, "planar", "planar");
  const Vector3d n = r.GetVector3("normal");
  r.Finish();
  EMB_THROW_IF(!(n.norm() > 0.0), Where(file, node) << ": planar normal: expected a non-zero "
                                                        "vector, got ["
                                                     << n.transpose() << "]");
  return n.normalized();
}

void ReadOutput(const YAML::Node& node, const std::string& file, OutputSpec* o) {
  MapReader r(node, file, "output", "output");
  o->file = r.GetString("file", "");
  o->csv = r.GetString("csv", "");
  if (const YAML::Node ch = r.Optional("channels")) {
    EMB_THROW_IF(!ch.IsSequence(), Where(file, ch) << ": output channels: expected a list");
    for (const auto& c : ch) o->channels.push_back(c.Scalar());
  }
  r.Finish();
}

}  // namespace

Scene ParseScene(const std::string& text, const std::string& source, const SceneOptions& options) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    EMB_THROW(InputError, source << ":" << e.mark.line + 1 << ": YAML syntax error: " << e.msg);
  }
  CheckUniqueKeys(root, source);
  MapReader r(root, source, "scene", "scene");
  Scene scene;
  scene.source = source;
  scene.name = r.GetString("name", "scene");
  scene.description = r.GetString("description", "");
  if (r.Has("gravity"))
    scene.system.SetGravity(r.GetVector3("gravity"));
  else
    r.Optional("gravity");
  Parts parts;
  scene.inputs.push_back(source);
  ReadBodies(r.Require("bodies"), source, options, &scene.system, &parts, &scene.notes,
             &scene.inputs);
  if (const YAML::Node n = r.Optional("markers")) ReadMarkers(n, source, &scene.system, &parts);
  if (const YAML::Node n = r.Optional("joints")) ReadJoints(n, source, &scene.system);
  if (const YAML::Node n = r.Optional("motions")) ReadMotions(n, source, &scene.system);
  if (const YAML::Node n = r.Optional("couplers")) ReadCouplers(n, source, &scene.system);
  if (const YAML::Node n = r.Optional("forces")) ReadForces(n, source, &scene.system, &scene.notes);
  if (const YAML::Node n = r.Optional("sensors")) ReadSensors(n, source, &scene.system);
  if (const YAML::Node n = r.Optional("output_points"))
    ReadOutputPoints(n, source, &scene.system, parts.from_body_files, parts.beam_outputs);
  if (const YAML::Node n = r.Optional("stress_outputs"))
    scene.stress_outputs = ReadStressOutputs(n, source, &scene.system, parts.from_body_files,
                                             parts.stresses);
  YAML::Node analysis_node = r.Optional("analysis");
  if (analysis_node) ReadAnalysis(analysis_node, source, &scene.analysis, &scene.steady_state);
  CheckStressOutputTimes(scene.stress_outputs, scene.analysis.t_start, scene.analysis.t_end);
  scene.analysis.installed_bases = parts.installed_bases;
  scene.analysis.truncated_bases = TruncatedBases(parts);
  if (const YAML::Node n = r.Optional("planar"))
    scene.analysis.plane_normal = ReadPlanar(n, source);
  if (const YAML::Node n = r.Optional("output")) ReadOutput(n, source, &scene.output);
  r.Finish();
  scene.system.Finalize();
  if (scene.steady_state.enabled()) {
    try {
      results::ChannelSet(scene.system, scene.steady_state.channels);
    } catch (const InputError& e) {
      EMB_THROW(InputError, Where(source, analysis_node) << ": analysis steady_state: " << e.what());
    }
  }
  return scene;
}

std::string ReadSceneText(const std::string& path) {
  std::error_code ec;
  EMB_THROW_IF(!std::filesystem::exists(path, ec),
               "scene file '" << path << "' does not exist");
  EMB_THROW_IF(!std::filesystem::is_regular_file(path, ec),
               "scene file '" << path << "' is not a regular file; expected a YAML file");
  std::ifstream in(path);
  EMB_THROW_IF(!in, "scene file '" << path << "' cannot be read (permissions?)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Scene LoadSceneText(const std::string& text, const std::string& path, const SceneOptions& options) {
  Scene scene = ParseScene(text, path, options);
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  const std::string scene_dir = dir.empty() ? "." : dir.string();
  for (auto [p, key] : {std::pair{&scene.output.file, "output.file"},
                        std::pair{&scene.output.csv, "output.csv"}}) {
    if (p->empty()) continue;
    if (std::filesystem::path(*p).is_relative()) *p = (dir / *p).lexically_normal().string();
    CheckConfined(*p, {scene_dir, "."}, path + ": " + key);
  }
  return scene;
}

Scene LoadScene(const std::string& path, const SceneOptions& options) {
  return LoadSceneText(ReadSceneText(path), path, options);
}

}  // namespace emb::scene
