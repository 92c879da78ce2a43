#include "libemb/cms/body_file.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sstream>

#include "libemb/cms/body_codec.h"
#include "libemb/cms/modal_stress.h"
#include "libemb/common/error.h"
#include "libemb/io/atomic_file.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/io/mesh_io.h"
#include "libemb/io/xdmf_writer.h"

namespace emb {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using body_codec::Codec;

// The optional stress-stiffening group: absent when not computed (and in files written before
// it existed), so it adds nothing to their digest.
void TransferGeometricStiffness(Codec& c, GeometricStiffness& g) {
  if (c.writing() ? !g.present : !c.Exists(kGeometricStiffnessGroup)) return;
  const std::string group = kGeometricStiffnessGroup;
  c.Stack(group + "/centrifugal", g.centrifugal);
  c.Stack(group + "/translational", g.translational);
  Eigen::VectorXd point = g.reference_point;
  c.Vector(group + "/reference_point", point);
  EMB_THROW_IF(point.size() != 3, "'" << group << "/reference_point': expected 3 values, got "
                                      << point.size());
  g.reference_point = point;
  g.present = true;
}

// The numeric content of a body, in one fixed order. Reading, every dataset is checked
// against the sizes read before it (nr from K, nb from the interfaces, ne from the
// frequencies).
void Transfer(Codec& c, ReducedBody& b) {
  c.Matrix("/reduced/K", b.K);
  const Eigen::Index nr = b.K.rows();
  c.ExpectShape("/reduced/K", b.K, nr, nr);
  c.Matrix("/reduced/M", b.M);
  c.ExpectShape("/reduced/M", b.M, nr, nr);
  c.Matrix("/reduced/D", b.D);
  c.ExpectShape("/reduced/D", b.D, nr, nr);
  const Eigen::Index nb = static_cast<Eigen::Index>(b.interfaces.size());
  Eigen::MatrixXd points(nb, 3);
  for (Eigen::Index j = 0; j < nb; ++j) points.row(j) = b.interfaces[j].point.transpose();
  c.Matrix("/interfaces/points", points);
  c.ExpectShape("/interfaces/points", points, nb, 3);
  for (Eigen::Index j = 0; j < nb; ++j) {
    Interface& itf = b.interfaces[j];
    itf.point = points.row(j).transpose();
    c.Ints("/interfaces/" + itf.name + "/nodes", itf.nodes);
    c.Vector("/interfaces/" + itf.name + "/weights", itf.weights);
    c.ExpectSize("/interfaces/" + itf.name + "/weights", itf.weights.size(),
                 static_cast<Eigen::Index>(itf.nodes.size()));
  }
  c.Vector("/fixed_interface/frequencies_hz", b.fixed_interface_hz);
  c.Vector("/modes/frequencies_hz", b.modes.frequencies_hz);
  const Eigen::Index ne = b.modes.frequencies_hz.size();
  c.Vector("/modes/eigenvalues", b.modes.eigenvalues);
  c.ExpectSize("/modes/eigenvalues", b.modes.eigenvalues.size(), ne);
  c.Vector("/modes/damping_ratios", b.damping_ratios);
  c.ExpectSize("/modes/damping_ratios", b.damping_ratios.size(), ne);
  c.Matrix("/modes/X", b.modes.elastic);
  c.ExpectShape("/modes/X", b.modes.elastic, nr, ne);
  c.Matrix("/modes/rigid", b.modes.rigid);
  c.ExpectShape("/modes/rigid", b.modes.rigid, nr, 6);
  c.Matrix("/modes/interface_shapes", b.interface_shapes);
  c.ExpectShape("/modes/interface_shapes", b.interface_shapes, 6 * nb, ne);
  c.Vector("/modes/rigid_frequencies_hz", b.modes.rigid_frequencies_hz);
  InertiaInvariants& inv = b.invariants;
  c.Scalar("/invariants", "mass", inv.mass);
  Eigen::VectorXd first = inv.first_moment;
  c.Vector("/invariants/first_moment", first);
  c.ExpectSize("/invariants/first_moment", first.size(), 3);
  inv.first_moment = first;
  Eigen::MatrixXd second = inv.second_moment;
  c.Matrix("/invariants/second_moment", second);
  c.ExpectShape("/invariants/second_moment", second, 3, 3);
  inv.second_moment = second;
  c.Matrix("/invariants/St", inv.St);
  c.ExpectShape("/invariants/St", inv.St, 3, ne);
  c.Matrix("/invariants/Ibar", inv.Ibar);
  c.ExpectShape("/invariants/Ibar", inv.Ibar, 9, ne);
  // Sbar as one (9, ne, ne) dataset: stack the 9 matrices row-wise into (9·ne, ne).
  Eigen::MatrixXd stacked(9 * ne, ne);
  for (int k = 0; k < 9; ++k)
    if (inv.Sbar[k].size() == ne * ne) stacked.middleRows(k * ne, ne) = inv.Sbar[k];
  c.Matrix("/invariants/Sbar", stacked);
  c.ExpectShape("/invariants/Sbar", stacked, 9 * ne, ne);
  for (int k = 0; k < 9; ++k) inv.Sbar[k] = stacked.middleRows(k * ne, ne);
  TransferGeometricStiffness(c, b.geometric_stiffness);
  TransferModalStresses(c, b.stress_groups, b.stress_surface, ne);
}

// Format version 2 of the digest also covers everything else the reader uses (the
// attributes and the interface names), in this order; version 1 covered the numeric
// datasets only, so a changed damping ratio or material went unnoticed.
// Version 3 is version 2 with the optional modal stresses (modal_stress.h) digested; a file
// without them is written as version 2, so that older readers still take it.
// Version 4 is version 3 with the whole-surface modal stresses (surface_stress.h) digested
// too; files without them keep version 2 or 3, so that older readers still take those.
constexpr long long kDigestVersion = 2;
constexpr long long kDigestVersionStress = 3;
constexpr long long kDigestVersionSurface = 4;
constexpr const char* kStressSurfaceGroup = "/stress/surface";

long long DigestVersionOf(const ReducedBody& b) {
  if (!b.stress_surface.empty()) return kDigestVersionSurface;
  return b.stress_groups.empty() ? kDigestVersion : kDigestVersionStress;
}

void TransferMetadata(Codec& c, const BodyFileInfo& info, const ReducedBody& b) {
  for (const std::string* s :
       {&info.provenance.command, &info.provenance.source, &info.provenance.mesh_hash,
        &info.provenance.options, &info.element_types, &info.interfaces, &info.selection,
        &info.material.name, &b.selection_note})
    c.Text(*s);
  for (double x : {info.shift_hz, info.material.youngs_modulus, info.material.poisson_ratio,
                   info.material.density, double(b.num_boundary), double(b.free_free),
                   double(b.num_fe_dofs)})
    c.Number(x);
  for (const Interface& itf : b.interfaces) {
    c.Text(itf.name);
    c.Text(Name(itf.coupling));
    c.Text(itf.point_source);
  }
  if (b.damping.kind == DampingModel::Kind::kModal) {
    c.Text("modal");
    c.Number(b.damping.ratio);
  } else {
    c.Text("rayleigh");
    c.Number(b.damping.alpha);
    c.Number(b.damping.beta);
  }
  if (b.geometric_stiffness.present) c.Text(b.geometric_stiffness.support);
}

// The parts of a body that Transfer reads or writes (not the large mesh shapes).
ReducedBody NumericContent(const ReducedBody& b) {
  ReducedBody c;
  c.K = b.K;
  c.M = b.M;
  c.D = b.D;
  c.interfaces = b.interfaces;
  c.fixed_interface_hz = b.fixed_interface_hz;
  c.modes = b.modes;
  c.damping_ratios = b.damping_ratios;
  c.interface_shapes = b.interface_shapes;
  c.invariants = b.invariants;
  c.geometric_stiffness = b.geometric_stiffness;
  c.stress_groups = b.stress_groups;
  c.stress_surface = b.stress_surface;
  return c;
}

std::string ElementTypes(const Mesh& mesh) {
  std::string s;
  for (const auto& b : mesh.blocks) s += (s.empty() ? "" : ", ") + std::string(Name(b.type));
  return s;
}

}  // namespace

void WriteBodyFile(const std::string& path, const std::string& xdmf_path, const ReducedBody& body,
                   const BodyFileInfo& info, const Mesh* mesh) {
  AtomicFile out(path);
  const bool shapes = mesh != nullptr && body.mesh_shapes.size() > 0;
  {
    std::optional<H5File> file;
    out.Create([&](const std::string& temp) { file.emplace(temp, H5File::Mode::kCreate); });
    H5File& h5 = *file;
    h5.SetAttribute("/", "format", std::string(kBodyFormat));
    h5.SetAttribute("/", "format_version", static_cast<long long>(kBodyFormatVersion));
    h5.SetAttribute("/", "emb_version", std::string(EMB_VERSION));
    h5.SetAttribute("/", "units",
                    std::string("SI: m, kg, s, N, rad; frequencies in Hz; eigenvalues in "
                                "rad^2/s^2; modes mass-normalised"));
    WriteProvenance(h5, info.provenance);
    h5.SetAttribute("/provenance", "element_types",
                    mesh ? ElementTypes(*mesh) : info.element_types);
    h5.SetAttribute("/provenance", "interfaces", info.interfaces);
    h5.SetAttribute("/provenance", "selection", info.selection);
    h5.SetAttribute("/provenance", "shift_hz", info.shift_hz);
    h5.SetAttribute("/material", "name", info.material.name);
    h5.SetAttribute("/material", "youngs_modulus", info.material.youngs_modulus);
    h5.SetAttribute("/material", "poisson_ratio", info.material.poisson_ratio);
    h5.SetAttribute("/material", "density", info.material.density);

    std::vector<std::string> names, couplings, sources;
    for (const auto& itf : body.interfaces) {
      names.push_back(itf.name);
      couplings.push_back(Name(itf.coupling));
      sources.push_back(itf.point_source);
    }
    if (!names.empty()) {
      h5.Write("/interfaces/names", names);
      h5.Write("/interfaces/couplings", couplings);
      h5.Write("/interfaces/point_sources", sources);
    }
    h5.SetAttribute("/reduced", "num_boundary", static_cast<long long>(body.num_boundary));
    h5.SetAttribute("/reduced", "free_free", static_cast<long long>(body.free_free));
    h5.SetAttribute("/reduced", "num_fe_dofs", static_cast<long long>(body.num_fe_dofs));
    h5.SetAttribute("/fixed_interface", "selection_note", body.selection_note);
    const ReductionCertificate& ct = body.certificate;
    h5.SetAttribute("/fixed_interface", "eigen_log", ct.reduction_log);
    h5.SetAttribute("/damping", "model",
                    std::string(body.damping.kind == DampingModel::Kind::kModal ? "modal" : "rayleigh"));
    if (body.damping.kind == DampingModel::Kind::kModal) {
      h5.SetAttribute("/damping", "ratio", body.damping.ratio);
    } else {
      h5.SetAttribute("/damping", "alpha", body.damping.alpha);
      h5.SetAttribute("/damping", "beta", body.damping.beta);
    }
    h5.SetAttribute("/invariants", "form", std::string("Shabana"));
    h5.SetAttribute("/invariants", "frame", std::string("mesh"));

    ReducedBody content = NumericContent(body);  // Transfer works on a mutable body
    Codec codec(h5, true);
    Transfer(codec, content);
    BodyFileInfo written = info;
    written.element_types = mesh ? ElementTypes(*mesh) : info.element_types;
    TransferMetadata(codec, written, body);
    h5.SetAttribute("/", "content_digest", codec.Hex());
    h5.SetAttribute("/", "content_digest_version", DigestVersionOf(body));
    if (body.geometric_stiffness.present) {
      h5.SetAttribute(kGeometricStiffnessGroup, "support", body.geometric_stiffness.support);
      h5.SetAttribute(kGeometricStiffnessGroup, "centrifugal_products",
                      std::string(kCentrifugalProducts));
      h5.SetAttribute(kGeometricStiffnessGroup, "translational_components",
                      std::string("ax, ay, az"));
    }

    // Certificate.
    const std::string c = "/certificate";
    h5.SetAttribute(c, "passed", static_cast<long long>(ct.passed()));
    h5.SetAttribute(c, "mass_error", ct.mass_error);
    h5.SetAttribute(c, "com_error", ct.com_error);
    h5.SetAttribute(c, "inertia_error", ct.inertia_error);
    h5.SetAttribute(c, "quadrature_mass_error", ct.quadrature_mass_error);
    h5.SetAttribute(c, "num_near_zero", static_cast<long long>(ct.num_near_zero));
    h5.SetAttribute(c, "orthonormality_error", ct.orthonormality_error);
    h5.SetAttribute(c, "k_diagonality_error", ct.k_diagonality_error);
    h5.SetAttribute(c, "degenerate_coupling", ct.degenerate_coupling);
    h5.SetAttribute(c, "rigid_stiffness", ct.rigid_stiffness);
    h5.SetAttribute(c, "fmax_hz", ct.fmax_hz);
    h5.SetAttribute(c, "reference_run", static_cast<long long>(ct.reference_run));
    h5.SetAttribute(c, "max_frequency_error", ct.max_frequency_error);
    h5.SetAttribute(c, "min_mac", ct.min_mac);
    h5.SetAttribute(c, "reference_log", ct.reference_log);
    h5.SetAttribute(c, "static_run", static_cast<long long>(ct.static_run));
    h5.SetAttribute(c, "static_note", ct.static_note);
    h5.SetAttribute(c, "static_error", ct.static_error);
    h5.SetAttribute(c, "reduction_log", ct.reduction_log);
    h5.SetAttribute(c, "constraint_mode_residual", ct.constraint_mode_residual);
    h5.SetAttribute(c, "constraint_mode_iterations", static_cast<long long>(ct.constraint_mode_iterations));
    if (ct.rigid_hz.size() > 0) h5.Write(c + "/rigid_hz", ct.rigid_hz.data(), {std::uint64_t(ct.rigid_hz.size())});
    if (!ct.pairs.empty()) {
      RowMajor pairs(ct.pairs.size(), 6);
      for (size_t i = 0; i < ct.pairs.size(); ++i) {
        const ModePair& p = ct.pairs[i];
        pairs.row(i) << p.full_mode, p.full_hz, p.reduced_mode, p.reduced_hz, p.relative_error, p.mac;
      }
      h5.Write(c + "/pairs", pairs.data(), {std::uint64_t(pairs.rows()), 6});
    }
    if (!ct.failures.empty()) h5.Write(c + "/failures", ct.failures);

    if (shapes) {
      WriteMesh(h5, *mesh);
      const std::uint64_t ne = body.mesh_shapes.cols(), n = mesh->num_nodes();
      h5.Write("/modes/mesh_shapes", body.mesh_shapes.data(), {ne, n, 3});
    }
    h5.Close();
  }

  // Both files are complete before either takes its name.
  std::optional<AtomicFile> xdmf;
  if (shapes && !xdmf_path.empty()) {
    std::vector<double> steps;
    std::vector<std::string> names;
    for (int k = 0; k < body.modes.frequencies_hz.size(); ++k) {
      steps.push_back(k + 1);
      char buf[64];
      std::snprintf(buf, sizeof buf, "elastic mode %d: %.6g Hz", k + 1, body.modes.frequencies_hz[k]);
      names.emplace_back(buf);
    }
    const std::string h5_name = std::filesystem::path(path).filename().string();
    xdmf.emplace(xdmf_path);
    xdmf->WriteText(
        MakeXdmfSteps(h5_name, *mesh, "/modes/mesh_shapes", "mode_shape", steps, names));
  }
  out.Commit();
  if (xdmf) xdmf->Commit();
}

ReducedBody ReadBodyFile(const std::string& path, BodyFileInfo* info_out) {
  std::error_code ec;
  EMB_THROW_IF(!std::filesystem::is_regular_file(path, ec),
               "body file '" << path << "': no such file");
  H5File h5(path, H5File::Mode::kRead);
  auto attr = [&](const std::string& o, const std::string& n) {
    EMB_THROW_IF(!h5.Exists(o), "body file '" << path << "': missing " << o);
    return h5.ReadStringAttribute(o, n);
  };
  const std::string format =
      h5.HasAttribute("/", "format") ? h5.ReadStringAttribute("/", "format") : "(none)";
  EMB_THROW_IF(format != kBodyFormat, "body file '" << path << "': expected format '" << kBodyFormat
                                                    << "', got '" << format << "'");
  BodyFileInfo info;
  info.format_version = static_cast<int>(h5.ReadIntAttribute("/", "format_version"));
  EMB_THROW_IF(info.format_version != kBodyFormatVersion,
               "body file '" << path << "': expected format version " << kBodyFormatVersion
                             << ", got " << info.format_version);
  info.content_digest = h5.ReadStringAttribute("/", "content_digest");
  info.provenance.command = attr("/provenance", "command");
  info.provenance.source = attr("/provenance", "source");
  info.provenance.mesh_hash = attr("/provenance", "mesh_hash");
  info.provenance.options = attr("/provenance", "options");
  info.element_types = attr("/provenance", "element_types");
  info.interfaces = attr("/provenance", "interfaces");
  info.selection = attr("/provenance", "selection");
  info.shift_hz = h5.ReadDoubleAttribute("/provenance", "shift_hz");
  info.material.name = attr("/material", "name");
  info.material.youngs_modulus = h5.ReadDoubleAttribute("/material", "youngs_modulus");
  info.material.poisson_ratio = h5.ReadDoubleAttribute("/material", "poisson_ratio");
  info.material.density = h5.ReadDoubleAttribute("/material", "density");

  ReducedBody b;
  b.num_boundary = static_cast<int>(h5.ReadIntAttribute("/reduced", "num_boundary"));
  b.free_free = h5.ReadIntAttribute("/reduced", "free_free") != 0;
  b.num_fe_dofs = static_cast<int>(h5.ReadIntAttribute("/reduced", "num_fe_dofs"));
  b.selection_note = attr("/fixed_interface", "selection_note");
  if (h5.Exists("/interfaces/names")) {
    const auto names = h5.ReadStrings("/interfaces/names");
    const auto couplings = h5.ReadStrings("/interfaces/couplings");
    const auto sources = h5.ReadStrings("/interfaces/point_sources");
    EMB_THROW_IF(couplings.size() != names.size() || sources.size() != names.size(),
                 "body file '" << path << "': /interfaces datasets of different lengths");
    for (size_t j = 0; j < names.size(); ++j) {
      Interface itf;
      itf.name = names[j];
      EMB_THROW_IF(couplings[j] != "rbe2" && couplings[j] != "rbe3",
                   "body file '" << path << "': interface '" << names[j]
                                 << "': expected coupling rbe2 or rbe3, got '" << couplings[j] << "'");
      itf.coupling = couplings[j] == "rbe2" ? Coupling::kRbe2 : Coupling::kRbe3;
      itf.point_source = sources[j];
      b.interfaces.push_back(std::move(itf));
    }
  }
  const std::string model = attr("/damping", "model");
  if (model == "modal") {
    b.damping.kind = DampingModel::Kind::kModal;
    b.damping.ratio = h5.ReadDoubleAttribute("/damping", "ratio");
  } else {
    EMB_THROW_IF(model != "rayleigh", "body file '" << path << "': expected damping model modal or "
                                                       "rayleigh, got '" << model << "'");
    b.damping.kind = DampingModel::Kind::kRayleigh;
    b.damping.alpha = h5.ReadDoubleAttribute("/damping", "alpha");
    b.damping.beta = h5.ReadDoubleAttribute("/damping", "beta");
  }
  for (const auto& p : {"/reduced/K", "/modes/X", "/invariants/Sbar"})
    EMB_THROW_IF(!h5.Exists(p), "body file '" << path << "': missing dataset " << p);
  const long long digest_version =
      h5.HasAttribute("/", "content_digest_version")
          ? h5.ReadIntAttribute("/", "content_digest_version")
          : 1;
  EMB_THROW_IF(digest_version < 1 || digest_version > kDigestVersionSurface,
               "body file '" << path << "': expected content digest version 1 to "
                             << kDigestVersionSurface << ", got " << digest_version);
  // The version says which optional stress data the digest covers: a group removed or added
  // afterwards is refused here, before the digest would say so less clearly.
  for (const auto& [group, from] : {std::pair{kStressGroup, kDigestVersionStress},
                                    std::pair{kStressSurfaceGroup, kDigestVersionSurface}})
    EMB_THROW_IF(h5.Exists(group) != (digest_version >= from),
                 "body file '" << path << "': content digest version " << digest_version
                               << (digest_version >= from ? " without" : " with") << " a "
                               << group << " group: the file was modified after "
                               << "it was written; refusing it");
  if (h5.Exists(kGeometricStiffnessGroup))
    b.geometric_stiffness.support = h5.ReadStringAttribute(kGeometricStiffnessGroup, "support");
  Codec codec(h5, false);
  Transfer(codec, b);
  if (digest_version >= 2) TransferMetadata(codec, info, b);
  EMB_THROW_IF(codec.Hex() != info.content_digest,
               "body file '" << path << "': content digest " << codec.Hex()
                             << " does not match the recorded " << info.content_digest
                             << ": the file was modified after it was written; refusing it");
  const int nr = static_cast<int>(b.K.rows());
  const int ne = static_cast<int>(b.modes.elastic.cols());
  GeometricStiffness& g = b.geometric_stiffness;
  if (g.present) {
    const std::string products =
        h5.ReadStringAttribute(kGeometricStiffnessGroup, "centrifugal_products");
    EMB_THROW_IF(products != kCentrifugalProducts,
                 "body file '" << path << "': " << kGeometricStiffnessGroup
                               << ": expected the product order '" << kCentrifugalProducts
                               << "', got '" << products << "'");
    EMB_THROW_IF(g.centrifugal[0].rows() != ne || g.centrifugal[0].cols() != ne ||
                     g.translational[0].rows() != ne || g.translational[0].cols() != ne,
                 "body file '" << path << "': " << kGeometricStiffnessGroup
                               << ": expected (k, " << ne << ", " << ne << ") matrices, got ("
                               << g.centrifugal[0].rows() << ", " << g.centrifugal[0].cols()
                               << ")");
  }
  EMB_THROW_IF(b.K.cols() != nr || b.M.rows() != nr || b.D.rows() != nr || b.modes.elastic.rows() != nr ||
                   b.modes.frequencies_hz.size() != ne ||
                   b.interface_shapes.rows() != 6 * static_cast<int>(b.interfaces.size()),
               "body file '" << path << "': inconsistent dataset sizes");
  // Values no reduction writes (a file from elsewhere, or one written before the digest
  // covered its attributes).
  try {
    info.material.Validate();
  } catch (const InputError& e) {
    EMB_THROW(InputError, "body file '" << path << "': " << e.what());
  }
  const DampingModel& d = b.damping;
  EMB_THROW_IF(!(std::isfinite(d.ratio) && d.ratio >= 0.0 && std::isfinite(d.alpha) &&
                 d.alpha >= 0.0 && std::isfinite(d.beta) && d.beta >= 0.0),
               "body file '" << path << "': damping: expected finite values >= 0, got ratio "
                             << d.ratio << ", alpha " << d.alpha << " 1/s, beta " << d.beta
                             << " s");
  EMB_THROW_IF(b.num_boundary < 0 || b.num_boundary > nr,
               "body file '" << path << "': /reduced@num_boundary: expected 0.." << nr
                             << ", got " << b.num_boundary);
  for (const auto& [name, A] :
       {std::pair<const char*, const Eigen::MatrixXd*>{"/reduced/K", &b.K},
        {"/reduced/M", &b.M}, {"/reduced/D", &b.D}, {"/modes/X", &b.modes.elastic},
        {"/modes/interface_shapes", &b.interface_shapes}, {"/invariants/St", &b.invariants.St},
        {"/invariants/Ibar", &b.invariants.Ibar}})
    EMB_THROW_IF(!A->allFinite(), "body file '" << path << "': " << name
                                                << " holds a non-finite value (NaN or inf)");
  EMB_THROW_IF(!b.modes.eigenvalues.allFinite() || !std::isfinite(b.invariants.mass) ||
                   !(b.invariants.mass > 0.0),
               "body file '" << path << "': expected finite eigenvalues and a positive mass");
  if (info_out) *info_out = info;
  return b;
}

void CheckBodyProvenance(const std::string& path, const BodyFileInfo& info,
                         const std::string& expected_mesh_hash,
                         const IsotropicMaterial* expected) {
  EMB_THROW_IF(info.provenance.mesh_hash != expected_mesh_hash,
               "body file '" << path << "' was reduced from mesh " << info.provenance.mesh_hash
                             << " but the model uses mesh " << expected_mesh_hash
                             << ": stale basis, run emb reduce again");
  if (expected) {
    const IsotropicMaterial& m = info.material;
    EMB_THROW_IF(m.youngs_modulus != expected->youngs_modulus ||
                     m.poisson_ratio != expected->poisson_ratio || m.density != expected->density,
                 "body file '" << path << "' was reduced with E = " << m.youngs_modulus
                               << " Pa, nu = " << m.poisson_ratio << ", rho = " << m.density
                               << " kg/m^3 but the model uses E = " << expected->youngs_modulus
                               << " Pa, nu = " << expected->poisson_ratio
                               << ", rho = " << expected->density
                               << " kg/m^3: stale basis, run emb reduce again");
  }
}

}  // namespace emb
