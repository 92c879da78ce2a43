#include "libemb/scene/body_file_part.h"

#include <sstream>

#include "libemb/cms/body_file.h"
#include "libemb/common/error.h"
#include "libemb/mbs/core/system.h"

namespace emb::scene {
namespace {

// The elastic model in the CM frame from the body file's mesh-frame invariants.
mbs::ElasticModel MakeElasticModel(const ReducedBody& rb, const std::string& path) {
  const InertiaInvariants& inv = rb.invariants;
  mbs::ElasticModel e;
  e.source = path;
  e.mass = inv.mass;
  const Eigen::Vector3d c = inv.CenterOfMass();
  e.second_moment = inv.second_moment - inv.mass * c * c.transpose();
  e.St = inv.St;
  e.Ibar = inv.Ibar;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) e.Ibar.row(3 * k + l) -= c[k] * inv.St.row(l);
  e.Sbar = inv.Sbar;
  const Eigen::MatrixXd& X = rb.modes.elastic;
  e.K = rb.modes.eigenvalues.asDiagonal();
  e.D = X.transpose() * rb.D * X;
  e.D = 0.5 * (e.D + e.D.transpose());
  e.frequencies_hz = rb.modes.frequencies_hz;
  return e;
}

}  // namespace

int BodyFilePart::FindInterface(const std::string& part, const std::string& name) const {
  for (std::size_t k = 0; k < interface_names.size(); ++k)
    if (interface_names[k] == name) return static_cast<int>(k);
  std::ostringstream list;
  for (const auto& n : interface_names) list << (list.tellp() ? ", " : "") << n;
  EMB_THROW(InputError, "part '" << part << "' (" << file << ") has no interface '" << name
                                 << "'" << mbs::DidYouMean(name, interface_names)
                                 << "; its interfaces are: " << list.str());
}

BodyFilePart LoadBodyFilePart(const std::string& path, const BodyFileOptions& options,
                              const Eigen::Vector3d& mesh_origin_W, const Eigen::Matrix3d& R_WM,
                              mbs::RigidBody* body) {
  const std::string& name = body->name;
  BodyFileInfo info;
  ReducedBody rb;
  try {
    rb = ReadBodyFile(path, &info);
    if (!options.expect_mesh_hash.empty())
      CheckBodyProvenance(path, info, options.expect_mesh_hash);
  } catch (const InputError& e) {
    EMB_THROW(InputError, "part '" << name << "': " << e.what());
  }
  BodyFilePart part;
  part.file = path;
  part.flexible = options.flexible;
  part.com_mesh = rb.invariants.CenterOfMass();
  for (const auto& i : rb.interfaces) {
    part.interface_names.push_back(i.name);
    part.interface_points.push_back(i.point);
  }
  body->mass = rb.invariants.mass;
  const mbs::ElasticModel full = MakeElasticModel(rb, path);
  body->inertia_B = full.RigidInertia();
  body->p_WB = mesh_origin_W + R_WM * part.com_mesh;
  body->R_WB = R_WM;
  std::ostringstream note;
  if (!options.flexible) {
    note << "part '" << name << "': rigid, mass properties from " << path;
    part.note = note.str();
    return part;
  }

  // Modes kept: the lowest max_modes, and those up to fmax_hz.
  const int available = full.num_modes();
  EMB_THROW_IF(options.max_modes > available,
               "part '" << name << "': " << options.max_modes << " modes requested, but " << path
                        << " has " << available << " elastic modes");
  std::vector<int> keep;
  for (int k = 0; k < available; ++k) {
    if (options.max_modes >= 0 && static_cast<int>(keep.size()) >= options.max_modes) break;
    if (options.fmax_hz >= 0.0 && full.frequencies_hz[k] > options.fmax_hz) break;
    keep.push_back(k);
  }
  EMB_THROW_IF(keep.empty() && options.max_modes != 0,
               "part '" << name << "': no elastic mode of " << path << " is at or below "
                        << options.fmax_hz << " Hz (the lowest is "
                        << (available ? full.frequencies_hz[0] : 0.0) << " Hz)");
  if (keep.empty()) {
    note << "part '" << name << "': 0 of " << available << " elastic modes of " << path
         << " kept: rigid";
    part.flexible = false;
    part.note = note.str();
    return part;
  }
  auto model = std::make_shared<mbs::ElasticModel>(full.Subset(keep));
  if (options.dynamic_band_hz >= 0.0) {
    std::vector<bool> flags(keep.size());
    for (std::size_t j = 0; j < keep.size(); ++j)
      flags[j] = model->frequencies_hz[static_cast<int>(j)] > options.dynamic_band_hz;
    model->MakeQuasiStatic(flags, name);
  }
  // Geometric stiffening: used when the file has it unless switched off. The file's data are
  // about the CM (the origin of B here), per c_p(omega) and per a_k.
  const bool has_kg = rb.geometric_stiffness.present;
  EMB_THROW_IF(options.geometric_stiffening == 1 && !has_kg,
               "part '" << name << "': geometric_stiffening: true, but " << path
                        << " has no geometric stiffness data (reduce it again without "
                           "--no-geometric-stiffness)");
  model->geometric_stiffening = has_kg && options.geometric_stiffening != 0;
  if (model->geometric_stiffening) {
    auto square = [&](const Eigen::MatrixXd& A) {
      Eigen::MatrixXd out(keep.size(), keep.size());
      for (std::size_t i = 0; i < keep.size(); ++i)
        for (std::size_t j = 0; j < keep.size(); ++j) out(i, j) = A(keep[i], keep[j]);
      return out;
    };
    for (int p = 0; p < 6; ++p) model->kg_centrifugal[p] = square(rb.geometric_stiffness.centrifugal[p]);
    for (int k = 0; k < 3; ++k)
      model->kg_translational[k] = square(rb.geometric_stiffness.translational[k]);
  }
  part.interface_shapes.resize(rb.interface_shapes.rows(), static_cast<int>(keep.size()));
  for (std::size_t j = 0; j < keep.size(); ++j)
    part.interface_shapes.col(static_cast<int>(j)) = rb.interface_shapes.col(keep[j]);
  body->elastic = model;
  note << "part '" << name << "': flexible (CMS), " << keep.size() << " of " << available
       << " elastic modes of " << path;
  if (!keep.empty())
    note << " (" << model->frequencies_hz[0] << " to " << model->frequencies_hz.maxCoeff()
         << " Hz)";
  note << "; geometric stiffening " << (model->geometric_stiffening ? "on" : "off");
  part.note = note.str();
  return part;
}

}  // namespace emb::scene
