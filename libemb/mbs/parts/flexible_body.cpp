#include "libemb/mbs/parts/flexible_body.h"

#include <memory>
#include <sstream>

#include "libemb/cms/body_file.h"
#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"

namespace emb::mbs {

ElasticModel MakeElasticModel(const ReducedBody& reduced, const std::string& source) {
  const InertiaInvariants& inv = reduced.invariants;
  ElasticModel e;
  e.source = source;
  e.mass = inv.mass;
  const Eigen::Vector3d c = inv.CenterOfMass();
  e.second_moment = inv.second_moment - inv.mass * c * c.transpose();
  e.St = inv.St;
  e.Ibar = inv.Ibar;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) e.Ibar.row(3 * k + l) -= c[k] * inv.St.row(l);
  e.Sbar = inv.Sbar;
  const Eigen::MatrixXd& X = reduced.modes.elastic;
  e.K = reduced.modes.eigenvalues.asDiagonal();
  e.D = X.transpose() * reduced.D * X;
  e.D = 0.5 * (e.D + e.D.transpose());
  e.frequencies_hz = reduced.modes.frequencies_hz;
  const GeometricStiffness& kg = reduced.geometric_stiffness;
  e.geometric_stiffening = kg.present;
  if (kg.present) {
    e.kg_centrifugal = kg.centrifugal;
    e.kg_translational = kg.translational;
  }
  return e;
}

std::vector<int> SelectModes(const Eigen::VectorXd& frequencies_hz, const ModeSelection& s,
                             const std::string& part, const std::string& source) {
  const int available = static_cast<int>(frequencies_hz.size());
  EMB_THROW_IF(s.max_modes > available, "part '" << part << "': " << s.max_modes
                                                 << " modes requested, but " << source << " has "
                                                 << available << " elastic modes");
  std::vector<int> keep;
  for (int k = 0; k < available; ++k) {
    if (s.max_modes >= 0 && static_cast<int>(keep.size()) >= s.max_modes) break;
    if (s.fmax_hz >= 0.0 && frequencies_hz[k] > s.fmax_hz) break;
    keep.push_back(k);
  }
  EMB_THROW_IF(keep.empty() && s.max_modes != 0,
               "part '" << part << "': no elastic mode of " << source << " is at or below "
                        << s.fmax_hz << " Hz (the lowest is "
                        << (available ? frequencies_hz[0] : 0.0) << " Hz)");
  return keep;
}

int FlexiblePart::FindInterface(const std::string& interface) const {
  for (std::size_t k = 0; k < interface_names.size(); ++k)
    if (interface_names[k] == interface) return static_cast<int>(k);
  std::ostringstream list;
  for (const auto& n : interface_names) list << (list.tellp() ? ", " : "") << n;
  EMB_THROW(InputError, "part '" << name << "' (" << source << ") has no interface '"
                                 << interface << "'" << DidYouMean(interface, interface_names)
                                 << "; its interfaces are: " << list.str());
}

FlexibleBodyModel MakeFlexibleBody(const std::string& name, const ReducedBody& reduced,
                                   const std::string& source, const FlexibleBodyOptions& options,
                                   const PartPlacement& placement) {
  FlexibleBodyModel out;
  FlexiblePart& part = out.part;
  part.name = name;
  part.source = source;
  part.com_mesh = reduced.invariants.CenterOfMass();
  part.num_available_modes = static_cast<int>(reduced.modes.frequencies_hz.size());
  for (const auto& i : reduced.interfaces) {
    part.interface_names.push_back(i.name);
    part.interface_points.push_back(i.point);
  }
  RigidBody& body = out.body;
  body.name = name;
  body.mass = reduced.invariants.mass;
  body.inertia_B = reduced.invariants.InertiaAboutCom();
  body.R_WB = placement.R_WM;
  body.p_WB = placement.p_WM + placement.R_WM * part.com_mesh;
  body.omega_W = placement.omega_W;
  body.v_WB = placement.v_WB ? *placement.v_WB
                             : Eigen::Vector3d(placement.omega_W.cross(body.p_WB - placement.p_WM));

  std::ostringstream note;
  if (!options.flexible) {
    note << "part '" << name << "': rigid, mass properties from " << source;
    part.note = note.str();
    return out;
  }
  part.kept_modes = SelectModes(reduced.modes.frequencies_hz, options.modes, name, source);
  if (part.kept_modes.empty()) {
    note << "part '" << name << "': 0 of " << part.num_available_modes << " elastic modes of "
         << source << " kept: rigid";
    part.note = note.str();
    return out;
  }
  const bool has_kg = reduced.geometric_stiffness.present;
  EMB_THROW_IF(options.geometric_stiffening == GeometricStiffening::kOn && !has_kg,
               "part '" << name << "': geometric stiffening asked for, but " << source
                        << " has no geometric stiffness data (reduce it again without "
                           "--no-geometric-stiffness)");
  ElasticModel full = MakeElasticModel(reduced, source);
  full.geometric_stiffening = has_kg && options.geometric_stiffening != GeometricStiffening::kOff;
  auto model = std::make_shared<ElasticModel>(full.Subset(part.kept_modes));
  int num_quasi_static = 0;
  if (options.modes.dynamic_band_hz >= 0.0) {
    std::vector<bool> flags(part.kept_modes.size());
    for (int j = 0; j < part.num_modes(); ++j) {
      flags[j] = model->frequencies_hz[j] > options.modes.dynamic_band_hz;
      num_quasi_static += flags[j] ? 1 : 0;
    }
    model->MakeQuasiStatic(flags, name);
  }
  part.flexible = true;
  part.available_eigenvalues = reduced.modes.eigenvalues;
  part.available_interface_shapes = reduced.interface_shapes;
  part.interface_shapes.resize(reduced.interface_shapes.rows(), part.num_modes());
  for (int j = 0; j < part.num_modes(); ++j)
    part.interface_shapes.col(j) = reduced.interface_shapes.col(part.kept_modes[j]);
  note << "part '" << name << "': flexible (CMS), " << part.num_modes() << " of "
       << part.num_available_modes << " elastic modes of " << source << " ("
       << model->frequencies_hz[0] << " to " << model->frequencies_hz.maxCoeff()
       << " Hz)";
  if (num_quasi_static > 0)
    note << ", " << num_quasi_static << " of them above " << options.modes.dynamic_band_hz
         << " Hz quasi-static (massless)";
  note << "; geometric stiffening " << (model->geometric_stiffening ? "on" : "off");
  part.note = note.str();
  body.elastic = std::move(model);
  return out;
}

FlexiblePart AddFlexibleBody(System* sys, const std::string& name, const ReducedBody& reduced,
                             const std::string& source, const FlexibleBodyOptions& options,
                             const PartPlacement& placement, const Eigen::VectorXd& eta0,
                             const Eigen::VectorXd& eta_dot0) {
  FlexibleBodyModel m = MakeFlexibleBody(name, reduced, source, options, placement);
  for (const Eigen::VectorXd* v : {&eta0, &eta_dot0})
    EMB_THROW_IF(v->size() != 0 && v->size() != m.part.num_modes(),
                 "part '" << name << "': expected " << m.part.num_modes() << " initial modal "
                          << (v == &eta0 ? "coordinates" : "rates") << " (one per kept mode), got "
                          << v->size());
  m.body.eta0 = eta0;
  m.body.eta_dot0 = eta_dot0;
  m.part.body = sys->AddBody(m.body);
  return m.part;
}

int AddInterfaceMarker(System* sys, const FlexiblePart& part, const std::string& marker,
                       const std::string& interface, const Eigen::Matrix3d& R_BM) {
  const int k = part.FindInterface(interface);
  const Eigen::Vector3d p_BM = part.MeshToBody(part.interface_points[k]);
  if (!part.flexible) return sys->AddMarker(marker, part.name, p_BM, R_BM);
  return sys->AddFlexibleMarker(marker, part.name, p_BM, R_BM,
                                part.interface_shapes.middleRows(6 * k, 3),
                                part.interface_shapes.middleRows(6 * k + 3, 3));
}

ReducedBody ReadPartBodyFile(const std::string& path, const std::string& part,
                             const std::string& expect_mesh_hash) {
  try {
    BodyFileInfo info;
    ReducedBody reduced = ReadBodyFile(path, &info);
    if (!expect_mesh_hash.empty()) CheckBodyProvenance(path, info, expect_mesh_hash);
    return reduced;
  } catch (const InputError& e) {
    EMB_THROW(InputError, "part '" << part << "': " << e.what());
  }
}

}  // namespace emb::mbs
