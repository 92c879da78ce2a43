#include "libemb/beam/beam_geometry.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <sstream>

#include "libemb/beam/beam_modal.h"
#include "libemb/common/error.h"
#include "libemb/mesh/gmsh_input_audit.h"
#include "libemb/mesh/gmsh_reader.h"
#include "libemb/mesh/gmsh_session.h"

namespace emb {
namespace {

constexpr const char* kSegmentPrefix = "beam_segment_";
constexpr const char* kRigidPrefix = "beam_rigid_";
constexpr int kRigidBodyModes = 6;  // of a free-free model

// Volume, centre and inertia about the centre of a set of OpenCASCADE volumes (density 1),
// and their bounding box.
struct Integrals {
  double volume{0.0};
  Eigen::Vector3d center{Eigen::Vector3d::Zero()};
  Eigen::Matrix3d inertia{Eigen::Matrix3d::Zero()};
  Eigen::Vector3d box_min{Eigen::Vector3d::Constant(1e300)}, box_max{Eigen::Vector3d::Constant(-1e300)};
};

Integrals Integrate(const std::vector<int>& volumes, const std::string& path,
                    const std::string& group) {
  MassPropertiesSum sum;  // density 1: masses are volumes
  Integrals out;
  for (int tag : volumes) {
    double v;
    Eigen::Vector3d c;
    std::vector<double> I;
    double x0, y0, z0, x1, y1, z1;
    GmshCall("integrate volume " + std::to_string(tag) + " of group '" + group + "' in", path, [&] {
      gmsh::model::occ::getMass(3, tag, v);
      gmsh::model::occ::getCenterOfMass(3, tag, c.x(), c.y(), c.z());
      gmsh::model::occ::getMatrixOfInertia(3, tag, I);
      gmsh::model::occ::getBoundingBox(3, tag, x0, y0, z0, x1, y1, z1);
    });
    EMB_THROW_IF(I.size() != 9, "geometry '" << path << "': group '" << group
                                             << "': expected a 3x3 inertia from gmsh, got "
                                             << I.size() << " values");
    sum.Add(v, c, Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(I.data()), v);
    out.box_min = out.box_min.cwiseMin(Eigen::Vector3d(x0, y0, z0));
    out.box_max = out.box_max.cwiseMax(Eigen::Vector3d(x1, y1, z1));
  }
  const MassProperties total = sum.Result();
  EMB_THROW_IF(!(total.volume > 0.0), "geometry '" << path << "': group '" << group
                                                   << "': expected a positive volume, got "
                                                   << total.volume << " m^3");
  out.volume = total.volume;
  out.center = total.center_of_mass;
  out.inertia = total.inertia_about_com;
  return out;
}

// Every physical surface group with its area centroid (the nodes are set later).
std::vector<BeamInterface> SurfaceGroupCentroids(const std::string& path) {
  std::vector<BeamInterface> out;
  gmsh::vectorpair groups;
  GmshCall("read surface groups of", path, [&] { gmsh::model::getPhysicalGroups(groups, 2); });
  for (const auto& group : groups) {
    const int dim = group.first, tag = group.second;  // captured below (clang 14: no bindings)
    BeamInterface itf;
    std::vector<int> surfaces;
    GmshCall("read surface group " + std::to_string(tag) + " of", path, [&] {
      gmsh::model::getPhysicalName(dim, tag, itf.name);
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, surfaces);
    });
    double area = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    for (int s : surfaces) {
      double a = 0.0;
      Eigen::Vector3d c;
      GmshCall("integrate surface " + std::to_string(s) + " of group '" + itf.name + "' in", path,
               [&] {
                 gmsh::model::occ::getMass(2, s, a);
                 gmsh::model::occ::getCenterOfMass(2, s, c.x(), c.y(), c.z());
               });
      area += a;
      first += a * c;
    }
    EMB_THROW_IF(itf.name.empty() || !(area > 0.0),
                 "geometry '" << path << "': surface group " << tag << " ('" << itf.name
                              << "'): expected a named group of positive area, got " << area
                              << " m^2");
    itf.centroid_W = first / area;
    out.push_back(itf);
  }
  return out;
}

MassProperties Scaled(const Integrals& g, double density) {
  MassProperties p;
  p.volume = g.volume;
  p.mass = density * g.volume;
  p.center_of_mass = g.center;
  p.inertia_about_com = density * g.inertia;
  return p;
}

// Fits a solid or hollow circular prism along x to the integrals (file comment of the
// header) and checks that it is one.
void FitSegment(const Integrals& g, const std::string& path, GeometryPart& part, double tol,
                double poisson) {
  const std::string what = "geometry '" + path + "': segment '" + part.name + "'";
  const Eigen::Matrix3d& I = g.inertia;
  const double Ixx = I(0, 0), Iyy = I(1, 1), Izz = I(2, 2);
  const double scale = I.diagonal().maxCoeff();
  // OpenCASCADE integrates analytic surfaces to ~1e-12; 1e-6 only rejects real asymmetry.
  constexpr double kSymmetryTol = 1e-6;
  EMB_THROW_IF(std::abs(I(0, 1)) > kSymmetryTol * scale || std::abs(I(0, 2)) > kSymmetryTol * scale ||
                   std::abs(I(1, 2)) > kSymmetryTol * scale ||
                   std::abs(Iyy - Izz) > kSymmetryTol * scale,
               what << ": expected a circular prism along x (inertia diag(Ixx, Iyy, Iyy)), got "
                       "inertia per unit density ["
                    << I.row(0) << "; " << I.row(1) << "; " << I.row(2) << "] m^5");
  const double L2 = 12.0 * (0.5 * (Iyy + Izz) - 0.5 * Ixx) / g.volume;
  const double L_box = g.box_max.x() - g.box_min.x();
  EMB_THROW_IF(!(L2 > 0.0) || std::abs(std::sqrt(L2) - L_box) > tol,
               what << ": expected a circular prism along x: its length from the inertia is "
                    << (L2 > 0.0 ? std::sqrt(L2) : 0.0) << " m, from its bounding box " << L_box
                    << " m");
  const double L = std::sqrt(L2);
  const double A = g.volume / L, Ip = Ixx / L;
  const double s = 2.0 * Ip / A, d = A / std::numbers::pi;
  const double ro2 = 0.5 * (s + d), ri2 = 0.5 * (s - d);
  // ri² of a solid circle is round-off of s − d (~1e-12 ro²); a real bore is far above 1e-8.
  const double ri = ri2 > 1e-8 * ro2 ? std::sqrt(ri2) : 0.0;
  const double ro = std::sqrt(ro2);
  EMB_THROW_IF(ri2 < -1e-6 * ro2,
               what << ": expected a circular section, got a polar moment " << Ip
                    << " m^4 below that of a solid circle of the same area " << A << " m^2");
  const double box_d = std::max(g.box_max.y() - g.box_min.y(), g.box_max.z() - g.box_min.z());
  EMB_THROW_IF(std::abs(box_d - 2.0 * ro) > 1e-4 * 2.0 * ro + tol,
               what << ": expected a circular section of diameter " << 2.0 * ro
                    << " m (from its area and inertia), got a bounding box " << box_d
                    << " m wide");
  part.section = MakeHollowCircleSection(2.0 * ro, 2.0 * ri, poisson);
  part.length = L;
  part.axis_point_W = Eigen::Vector3d(g.center.x(), g.center.y(), g.center.z());
  part.x_min = g.center.x() - 0.5 * L;
  part.x_max = g.center.x() + 0.5 * L;
}

// Width b of an elastic web arm: the option, else web_r_main + web_r_pin of the .geo (the
// overrides first, then the declared defaults).
double WebArmWidth(const BeamGenerationOptions& o, const std::string& path,
                   const std::vector<std::pair<std::string, double>>& declared) {
  if (o.web_width > 0.0) return o.web_width;
  EMB_THROW_IF(o.web_width < 0.0 || !std::isfinite(o.web_width),
               "beam generation: web width: expected > 0 m (or 0 for the geometry's), got "
                   << o.web_width);
  auto value = [&](const std::string& name) {
    for (const auto& p : o.parameters)
      if (p.first == name) return p.second;
    for (const auto& p : declared)
      if (p.first == name) return p.second;
    EMB_THROW(InputError, "geometry '" << path << "': elastic webs need the web width: the file "
                                          "declares no parameter '"
                                       << name << "'; give the width (web_width) explicitly");
  };
  return value("web_r_main") + value("web_r_pin");
}

// The section of an elastic web arm: a t × b rectangle, t along y_B (= x_W), b along z_B.
BeamSection WebArmSection(double t, double b, double poisson, const std::string& what) {
  const double thin = std::min(t, b), wide = std::max(t, b), ratio = thin / wide;
  const double J = wide * thin * thin * thin * (1.0 / 3.0 - 0.21 * ratio * (1.0 - std::pow(ratio, 4) / 12.0));
  const double kappa = 10.0 * (1.0 + poisson) / (12.0 + 11.0 * poisson);
  try {
    return MakeGeneralSection(t * b, b * b * b * t / 12.0, t * t * t * b / 12.0, J, kappa);
  } catch (const InputError& e) {
    EMB_THROW(InputError, what << ": web arm section " << t << " m x " << b << " m: " << e.what());
  }
}

}  // namespace

const char* Name(WebModel webs) { return webs == WebModel::kRigid ? "rigid" : "elastic"; }

GeneratedBeamModel MakeBeamModelFromGeometry(const std::string& path,
                                             const BeamGenerationOptions& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  EMB_THROW_IF(!fs::is_regular_file(path, ec), "geometry file '" << path << "' does not exist");
  EMB_THROW_IF(!(std::isfinite(o.max_element_length) && o.max_element_length > 0.0),
               "beam generation: maximum element length: expected > 0 m, got "
                   << o.max_element_length);
  EMB_THROW_IF(o.min_elements_per_segment < 1,
               "beam generation: elements per segment: expected >= 1, got "
                   << o.min_elements_per_segment);
  EMB_THROW_IF(!(o.contact_tolerance > 0.0),
               "beam generation: contact tolerance: expected > 0 m, got " << o.contact_tolerance);
  o.material.Validate();
  if (!o.trust_scripts) AuditGmshInput(path);

  auto overrides = o.parameters;
  const auto declared = GeoParameters(path);
  const bool has_hook = std::any_of(declared.begin(), declared.end(),
                                    [](const auto& p) { return p.first == "beam_parts"; });
  const bool user_set = std::any_of(overrides.begin(), overrides.end(),
                                    [](const auto& p) { return p.first == "beam_parts"; });
  if (has_hook && !user_set) overrides.emplace_back("beam_parts", 1.0);
  EMB_THROW_IF(!overrides.empty() && declared.empty(),
               "geometry '" << path << "': parameters can only be set for .geo files that "
                                       "declare them");
  const std::vector<std::string> args = GeoParameterArgs(path, overrides);

  EMB_THROW_IF(!(std::isfinite(o.damping_ratio) && o.damping_ratio >= 0.0),
               "beam generation: damping ratio: expected >= 0, got " << o.damping_ratio);
  GeneratedBeamModel out;
  out.model = BeamModel(fs::path(path).stem().string(), std::max(0.0, o.stiffness_damping));
  out.source = path;
  std::vector<Integrals> integrals;
  {
    GmshSession session(args);
    GmshOpen(path, /*trusted=*/true, /*time_limited=*/!o.trust_scripts);  // audited above
    gmsh::vectorpair groups;
    GmshCall("read physical groups of", path, [&] { gmsh::model::getPhysicalGroups(groups, 3); });
    std::string found;
    for (const auto& group : groups) {
      const int dim = group.first, tag = group.second;  // captured below (clang 14: no bindings)
      std::string name;
      gmsh::model::getPhysicalName(dim, tag, name);
      found += (found.empty() ? "'" : ", '") + name + "'";
      GeometryPart part;
      if (name.rfind(kSegmentPrefix, 0) == 0) {
        part.kind = GeometryPart::Kind::kSegment;
        part.name = name.substr(std::string(kSegmentPrefix).size());
      } else if (name.rfind(kRigidPrefix, 0) == 0) {
        part.kind = GeometryPart::Kind::kRigid;
        part.name = name.substr(std::string(kRigidPrefix).size());
      } else {
        continue;
      }
      std::vector<int> volumes;
      GmshCall("read group '" + name + "' of", path,
               [&] { gmsh::model::getEntitiesForPhysicalGroup(dim, tag, volumes); });
      EMB_THROW_IF(volumes.empty(), "geometry '" << path << "': group '" << name
                                                 << "' holds no volume; expected at least one");
      integrals.push_back(Integrate(volumes, path, name));
      out.parts.push_back(std::move(part));
    }
    EMB_THROW_IF(out.parts.empty(),
                 "geometry '" << path << "': expected physical volumes named '" << kSegmentPrefix
                              << "*' or '" << kRigidPrefix << "*', got "
                              << (found.empty() ? "no volume groups" : found));
    out.interfaces = SurfaceGroupCentroids(path);
  }

  const double rho = o.material.density;
  for (size_t i = 0; i < out.parts.size(); ++i) {
    GeometryPart& p = out.parts[i];
    p.mass_properties = Scaled(integrals[i], rho);
    if (p.kind == GeometryPart::Kind::kSegment) {
      FitSegment(integrals[i], path, p, o.contact_tolerance, o.material.poisson_ratio);
    } else {
      p.x_min = integrals[i].box_min.x();
      p.x_max = integrals[i].box_max.x();
    }
  }
  // Sort parts (and their integrals) along x.
  std::vector<size_t> order(out.parts.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return out.parts[a].x_min < out.parts[b].x_min; });
  std::vector<GeometryPart> sorted;
  for (size_t i : order) sorted.push_back(out.parts[i]);
  out.parts = std::move(sorted);

  // The chain must be continuous along x.
  const double tol = o.contact_tolerance;
  auto& parts = out.parts;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    const GeometryPart &p = parts[i], &q = parts[i + 1];
    const double gap = q.x_min - p.x_max;
    EMB_THROW_IF(gap > tol, "geometry '" << path << "': parts '" << p.name << "' and '" << q.name
                                         << "' do not touch (gap " << gap
                                         << " m along x); expected one connected chain");
    EMB_THROW_IF(gap < -tol, "geometry '" << path << "': parts '" << p.name << "' and '"
                                          << q.name << "' overlap by " << -gap
                                          << " m along x; expected parts end to end");
    EMB_THROW_IF(p.kind == GeometryPart::Kind::kRigid && q.kind == GeometryPart::Kind::kRigid,
                 "geometry '" << path << "': rigid parts '" << p.name << "' and '" << q.name
                              << "' touch; expected a beam segment between rigid parts");
    if (p.kind == GeometryPart::Kind::kSegment && q.kind == GeometryPart::Kind::kSegment) {
      const double off = (p.axis_point_W.tail<2>() - q.axis_point_W.tail<2>()).norm();
      EMB_THROW_IF(off > tol, "geometry '" << path << "': segments '" << p.name << "' and '"
                                           << q.name << "' touch but their axes are " << off
                                           << " m apart; expected coaxial segments or a rigid "
                                              "part between them");
    }
  }

  BeamModel& model = out.model;
  std::vector<int> part_node(parts.size(), -1);
  auto rigid_node = [&](size_t i) {
    if (part_node[i] < 0) {
      const Eigen::Vector3d& c = parts[i].mass_properties.center_of_mass;
      part_node[i] = model.AddNode(parts[i].name, Eigen::Vector3d(c.x(), 0.0, 0.0));
      parts[i].node = part_node[i];
    }
    return part_node[i];
  };
  // The node a segment ends on at rigid part i: the part's node, or with elastic webs and a
  // segment off the part's axis the pin node at the end of a web arm (header comment).
  auto attach_node = [&](size_t i, const GeometryPart& seg) {
    const int node = rigid_node(i);
    const Eigen::Vector3d& p_N = model.nodes()[node].p_W;
    const double radial = (seg.axis_point_W.tail<2>() - p_N.tail<2>()).norm();
    if (o.webs == WebModel::kRigid || radial <= tol) return node;
    GeometryPart& web = parts[i];
    if (web.pin_node >= 0) return web.pin_node;
    const Eigen::Vector3d p_pin(p_N.x(), seg.axis_point_W.y(), seg.axis_point_W.z());
    web.pin_node = model.AddNode(web.name + ":pin", p_pin);
    const std::string what = "geometry '" + path + "': web '" + web.name + "'";
    BeamElement arm;
    arm.name = web.name + "#web";
    arm.node_a = node;
    arm.node_b = web.pin_node;
    arm.section = WebArmSection(web.x_max - web.x_min, WebArmWidth(o, path, declared),
                                o.material.poisson_ratio, what);
    arm.material = o.material;
    arm.material.density *= kWebArmDensityFraction;
    arm.shear_deformable = o.shear_deformable;
    arm.reference_W = Eigen::Vector3d::UnitX();
    model.AddElement(arm);
    return web.pin_node;
  };
  int shared = -1;  // end node of the previous segment, shared by a coaxial successor
  for (size_t i = 0; i < parts.size(); ++i) {
    GeometryPart& p = parts[i];
    if (p.kind == GeometryPart::Kind::kRigid) {
      const int node = rigid_node(i);
      RigidPart r;
      r.name = p.name;
      r.node = node;
      r.mass = p.mass_properties.mass;
      r.p_NC_W = p.mass_properties.center_of_mass - model.nodes()[node].p_W;
      r.I_C_W = p.mass_properties.inertia_about_com;
      model.AddRigidPart(r);
      shared = -1;
      continue;
    }
    const Eigen::Vector3d p0(p.x_min, p.axis_point_W.y(), p.axis_point_W.z());
    const Eigen::Vector3d p1(p.x_max, p.axis_point_W.y(), p.axis_point_W.z());
    const bool after_rigid = i > 0 && parts[i - 1].kind == GeometryPart::Kind::kRigid;
    const bool before_rigid =
        i + 1 < parts.size() && parts[i + 1].kind == GeometryPart::Kind::kRigid;
    int n0;
    Eigen::Vector3d off0 = Eigen::Vector3d::Zero(), off1 = Eigen::Vector3d::Zero();
    if (after_rigid) {
      n0 = attach_node(i - 1, p);
      off0 = p0 - model.nodes()[n0].p_W;
    } else if (shared >= 0) {
      n0 = shared;
    } else {
      n0 = model.AddNode(p.name + ":start", p0);
    }
    int n_el = std::max(o.min_elements_per_segment,
                        static_cast<int>(std::ceil(p.length / o.max_element_length - 1e-9)));
    n_el += n_el % 2;
    std::vector<int> nodes{n0};
    for (int k = 1; k < n_el; ++k) {
      const std::string name = 2 * k == n_el ? p.name : p.name + ":" + std::to_string(k);
      nodes.push_back(model.AddNode(name, p0 + (p1 - p0) * (static_cast<double>(k) / n_el)));
    }
    if (before_rigid) {
      nodes.push_back(attach_node(i + 1, p));
      off1 = p1 - model.nodes()[nodes.back()].p_W;
      shared = -1;
    } else {
      nodes.push_back(model.AddNode(p.name + ":end", p1));
      shared = nodes.back();
    }
    for (int k = 0; k < n_el; ++k) {
      BeamElement e;
      e.name = p.name + "#" + std::to_string(k + 1);
      e.node_a = nodes[k];
      e.node_b = nodes[k + 1];
      e.section = p.section;
      e.material = o.material;
      e.shear_deformable = o.shear_deformable;
      if (k == 0) e.offset_a_W = off0;
      if (k + 1 == n_el) e.offset_b_W = off1;
      p.elements.push_back(model.AddElement(e));
    }
  }

  if (o.stiffness_damping < 0.0) {
    // ζ at the first elastic free-free mode (header): one dense solve of a small model.
    // The lowest few only: a stiff, nearly massless web arm puts the top of the spectrum
    // where its eigenpairs cannot pass the round-off checks, and f₁ is all that is needed.
    BeamModalOptions mo;
    mo.num_modes = kRigidBodyModes + 1;
    const BeamModes modes = CalcBeamModes(AssembleBeamSystem(model, BeamMassType::kConsistent), mo);
    EMB_THROW_IF(!modes.ok(), "geometry '" << path << "': the beam model's modes (for its "
                                              "damping) failed: "
                                           << modes.message);
    const int first = modes.num_rigid_modes;
    EMB_THROW_IF(first >= modes.frequencies_hz.size(),
                 "geometry '" << path << "': the beam model has no elastic mode to set its "
                                         "damping at; give stiffness_damping");
    model.SetStiffnessDamping(StiffnessDampingForRatio(o.damping_ratio, modes.frequencies_hz[first]));
  }

  // Interfaces at the beam nodes nearest their surface groups' centroids (header).
  for (BeamInterface& itf : out.interfaces) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < model.num_nodes(); ++i) {
      const double d = (model.nodes()[i].p_W - itf.centroid_W).norm();
      if (d < best) best = d, itf.node = i;
    }
    itf.offset_W = itf.centroid_W - model.nodes()[itf.node].p_W;
  }

  // Mass properties of the exact geometry: all parts together.
  MassPropertiesSum all;
  for (const GeometryPart& p : parts) all.Add(p.mass_properties);
  out.geometry = all.Result();
  return out;
}

}  // namespace emb
