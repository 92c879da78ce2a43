#include "libemb/mbs/parts/beam_part.h"

#include <memory>
#include <sstream>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/beam/beam_condensation.h"
#include "libemb/common/mass_properties.h"
#include "libemb/mbs/parts/beam_force.h"

namespace emb::mbs {

using Eigen::Matrix3d;
using Eigen::Vector3d;

const BeamPart::Interface& BeamPart::FindInterface(const std::string& interface) const {
  std::vector<std::string> names;
  for (const Interface& i : interfaces) {
    if (i.name == interface) return i;
    names.push_back(i.name);
  }
  std::ostringstream list;
  for (const auto& n : names) list << (list.tellp() ? ", " : "") << n;
  EMB_THROW(InputError, "beam part '" << name << "' has no interface '" << interface << "'"
                                      << DidYouMean(interface, names)
                                      << "; its interfaces are: " << list.str());
}

const char* Name(BeamPartNodes nodes) {
  return nodes == BeamPartNodes::kAll ? "all" : "condensed";
}

BeamPartNodes ParseBeamPartNodes(const std::string& name) {
  for (BeamPartNodes n : {BeamPartNodes::kAll, BeamPartNodes::kCondensed})
    if (name == Name(n)) return n;
  EMB_THROW(InputError, "beam nodes: expected 'all' or 'condensed', got '" << name << "'");
}

BeamPartNodes DefaultBeamPartNodes(const GeneratedBeamModel& model) {
  return model.model.rigid_parts().empty() ? BeamPartNodes::kAll : BeamPartNodes::kCondensed;
}

BeamPart AddBeamPart(System* sys, const std::string& name, const GeneratedBeamModel& g,
                     const BeamPartPlacement& placement, BeamPartNodes nodes) {
  const BeamModel& model = g.model;
  const Matrix3d& R = placement.R_WP;
  auto to_world = [&](const Vector3d& p_P) -> Vector3d { return placement.p_WP + R * p_P; };

  // The bodies: every node with its lump, or the kept nodes with theirs (part frame).
  CondensedBeamModel condensed;
  std::vector<int> body_nodes;
  std::vector<MassProperties> lumps;
  if (nodes == BeamPartNodes::kCondensed) {
    condensed = CondenseBeamModel(model, CondensationNodes(g));
    body_nodes = condensed.kept;
    lumps = condensed.lumps;
  } else {
    lumps = CalcBeamNodeLumps(model);
    for (int i = 0; i < model.num_nodes(); ++i) body_nodes.push_back(i);
  }

  BeamPart part;
  part.name = name;
  part.nodes = nodes;
  part.num_model_nodes = model.num_nodes();
  auto body_of = [&](int node) { return name + "/" + model.nodes()[node].name; };
  std::vector<Vector3d> com(model.num_nodes());
  for (std::size_t k = 0; k < body_nodes.size(); ++k) {
    const int i = body_nodes[k];
    const MassProperties& l = lumps[k];
    EMB_THROW_IF(!(l.mass > 0.0), "beam part '" << name << "': node '" << model.nodes()[i].name
                                                << "' carries no mass; expected every node on an "
                                                   "element or a rigid part");
    com[i] = l.center_of_mass;
    RigidBody b;
    b.name = body_of(i);
    b.mass = l.mass;
    b.inertia_B =
        R * (0.5 * (l.inertia_about_com + l.inertia_about_com.transpose())) * R.transpose();
    b.p_WB = to_world(com[i]);
    b.R_WB = Matrix3d::Identity();
    b.omega_W = placement.omega_W;
    b.v_WB = placement.omega_W.cross(b.p_WB - placement.p_WP);
    sys->AddBody(b);
    part.bodies.push_back(b.name);
  }
  // A marker on node i's body at part point p_P with part-frame axes R_PM.
  auto add_marker = [&](const std::string& marker, int i, const Vector3d& p_P,
                        const Matrix3d& R_PM) {
    return sys->AddMarker(marker, body_of(i), R * (p_P - com[i]), R * R_PM);
  };
  if (nodes == BeamPartNodes::kCondensed) {
    for (const BeamLink& link : condensed.links) {
      const std::string base = name + "/" + link.name;
      const Vector3d& pa = model.nodes()[link.node_a].p_W;
      const Vector3d& pb = model.nodes()[link.node_b].p_W;
      const int mi = add_marker(base + ":a", link.node_a, pa, Matrix3d::Identity());
      const int mj = add_marker(base + ":b", link.node_b, pb, Matrix3d::Identity());
      sys->AddForceElement(std::make_shared<BeamLinkForce>(
          base, mi, mj, link.compliance, pb - pa, model.stiffness_damping()));
      part.forces.push_back(base);
    }
  } else {
    for (int e = 0; e < model.num_elements(); ++e) {
      const BeamElement& el = model.elements()[e];
      const auto [pa, pb] = model.ElasticEnds(e);
      const Matrix3d R_PB = model.ElementFrame(e);
      const std::string base = name + "/" + el.name;
      const int mi = add_marker(base + ":a", el.node_a, pa, R_PB);
      const int mj = add_marker(base + ":b", el.node_b, pb, R_PB);
      sys->AddForceElement(std::make_shared<BeamForce>(base, mi, mj, model.ElementProperties(e),
                                                       model.stiffness_damping()));
      part.forces.push_back(base);
    }
  }
  for (const BeamInterface& itf : g.interfaces) {
    const std::string marker = name + "." + itf.name;
    add_marker(marker, itf.node, model.nodes()[itf.node].p_W, Matrix3d::Identity());
    part.interfaces.push_back({itf.name, marker, model.nodes()[itf.node].name});
  }
  return part;
}

int AddInterfaceMarker(System* sys, const BeamPart& part, const std::string& marker,
                       const std::string& interface, const Matrix3d& R_PM) {
  const BeamPart::Interface& itf = part.FindInterface(interface);
  const Marker m = sys->marker(sys->FindMarker(itf.marker));
  return sys->AddMarker(marker, sys->body(m.body).name, m.p_BM, m.R_BM * R_PM);
}

}  // namespace emb::mbs
