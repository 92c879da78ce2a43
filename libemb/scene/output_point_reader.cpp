#include "libemb/scene/output_point_reader.h"

#include <memory>

#include "libemb/common/error.h"
#include "libemb/mbs/parts/output_points.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {
namespace {

using Spec = mbs::OutputPointSpec;

Eigen::Vector3d Unit(const Eigen::Vector3d& v, const std::string& what) {
  EMB_THROW_IF(!(std::abs(v.norm() - 1.0) <= 1e-6),
               what << ": expected a unit vector, got length " << v.norm());
  return v;
}

Spec ReadSpec(MapReader& r, const std::string& name) {
  Spec s;
  s.name = r.GetString("name");
  if (r.Has("node"))
    s.node = r.GetInt("node", 0);
  else
    r.Optional("node");
  if (r.Has("position"))
    s.position = r.GetVector3("position");
  else
    r.Optional("position");
  s.tolerance = r.GetDouble("tolerance", s.tolerance, NumberRange::Positive("m"));
  s.group = r.GetString("group", "");
  const std::string quantity = r.GetString("quantity", "motion");
  EMB_THROW_IF(
      quantity != "motion" && quantity != "radiated_power",
      r.what() << " quantity: expected 'motion' or 'radiated_power', got '" << quantity << "'");
  s.quantity = quantity == "motion" ? Spec::Quantity::kMotion : Spec::Quantity::kRadiatedPower;
  if (const YAML::Node d = r.Optional("direction")) {
    if (d.IsSequence()) {
      s.direction = Spec::Direction::kFixed;
      s.vector = Unit(r.GetVector3("direction"), r.what() + " direction");
    } else {
      const std::string kind = d.Scalar();
      EMB_THROW_IF(kind != "radial" && kind != "normal",
                   Where(r.file(), d)
                       << ": " << r.what()
                       << " direction: expected radial, normal or [x, y, z], got '" << kind << "'");
      s.direction = kind == "radial" ? Spec::Direction::kRadial : Spec::Direction::kNormal;
    }
  }
  if (const YAML::Node a = r.Optional("axis")) {
    EMB_THROW_IF(s.direction != Spec::Direction::kRadial,
                 Where(r.file(), a) << ": " << r.what() << ": 'axis' is for direction: radial");
    MapReader ra(a, r.file(), r.what() + " axis", "output_points: axis");
    s.axis_point = ra.GetVector3("point", Eigen::Vector3d::Zero());
    s.axis = Unit(ra.GetVector3("direction"), r.what() + " axis direction");
    ra.Finish();
  } else {
    EMB_THROW_IF(s.direction == Spec::Direction::kRadial,
                 r.what() << ": direction radial needs an axis: {point: [...], direction: [...]}");
  }
  (void)name;
  return s;
}

}  // namespace

void ReadOutputPoints(const YAML::Node& list, const std::string& file, mbs::System* sys,
                      const std::map<std::string, mbs::FlexiblePart>& body_file_parts,
                      const std::map<std::string, BeamPartOutputs>& beam_parts) {
  std::map<std::string, mbs::BodyMeshShapes> meshes;  // by body file, read once
  auto mesh_of = [&](const std::string& path,
                     const std::string& part) -> const mbs::BodyMeshShapes& {
    auto it = meshes.find(path);
    if (it == meshes.end()) it = meshes.emplace(path, mbs::ReadBodyMeshShapes(path, part)).first;
    return it->second;
  };
  ReadNamedList(
      list, file, "output_points", "output point",
      [&](MapReader& r, const std::string& name, const YAML::Node&) {
        const std::string body = r.GetString("body");
        const Spec spec = ReadSpec(r, name);
        r.Finish();
        if (const auto f = body_file_parts.find(body); f != body_file_parts.end()) {
          const mbs::BodyMeshShapes& m = mesh_of(f->second.source, body);
          sys->AddProbe(mbs::MakeOutputPoint(*sys, f->second, m, spec));
          return;
        }
        if (const auto b = beam_parts.find(body); b != beam_parts.end()) {
          EMB_THROW_IF(b->second.body_file.empty(), "output point '"
                                                        << name << "': beam part '" << body
                                                        << "' has no body_file (the mesh of its "
                                                           "3-D model, which output points use)");
          const mbs::BodyMeshShapes& m = mesh_of(b->second.body_file, body);
          sys->AddProbe(
              mbs::MakeOutputPoint(*sys, b->second.part, b->second.placement, m.mesh, spec));
          return;
        }
        sys->FindBody(body);  // an unknown body: did-you-mean
        EMB_THROW(InputError, "output point '" << name << "': body '" << body
                                               << "' has no body_file, so no mesh; output points "
                                                  "sit on parts from body files (model: cms, "
                                                  "rigid or beam)");
      });
}

}  // namespace emb::scene
