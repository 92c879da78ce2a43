#include "libemb/compare/part_comparison.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_modal.h"
#include "libemb/beam/tmm_solver.h"
#include "libemb/cms/interface.h"
#include "libemb/cms/reduction.h"
#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/compare/mode_pairing.h"
#include "libemb/compare/station_sampling.h"
#include "libemb/fe/assembly.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/linalg/dense_eigen.h"

namespace emb {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Headroom of the automatic TMM band over the highest reference frequency, so a beam mode
// a little above it (beams are stiffer) is still found.
constexpr double kTmmBandFactor = 1.25;
// Beam modes offered to the MAC pairing per reference mode (a stiff beam's modes come in a
// different order, and rigid-web crankshafts are ~2× too stiff).
constexpr int kBeamCandidatesPerMode = 4;

bool IsJournal(const std::string& name) { return name.rfind("main_journal_", 0) == 0; }

// The reference modes' elastic part: columns and frequencies above kRigidModeHz.
struct Modes {
  Eigen::VectorXd hz;
  Eigen::MatrixXd shapes;
};
Modes Elastic(const Eigen::VectorXd& hz, const Eigen::MatrixXd& shapes, int max_count) {
  std::vector<int> keep;
  for (int i = 0; i < hz.size() && static_cast<int>(keep.size()) < max_count; ++i)
    if (hz[i] > kRigidModeHz) keep.push_back(i);
  Modes m;
  m.hz.resize(keep.size());
  m.shapes.resize(shapes.rows(), keep.size());
  for (size_t k = 0; k < keep.size(); ++k) {
    m.hz[k] = hz[keep[k]];
    if (shapes.size()) m.shapes.col(k) = shapes.col(keep[k]);
  }
  return m;
}

// The supports of the installed case on a beam model: journals radially, journal 1 axially.
void AddJournalSupports(BeamModel& model, const std::vector<std::string>& journals) {
  for (const std::string& j : journals) {
    Support s;
    s.name = j;
    s.node = model.FindNode(j);
    s.fixed[kUy] = s.fixed[kUz] = true;
    s.fixed[kUx] = (j == journals.front());
    model.AddSupport(s);
  }
}

// Components held of interface j of the installed case (reference-node unknowns t_x..θ_z).
std::vector<int> HeldComponents(size_t j) {
  return j == 0 ? std::vector<int>{0, 1, 2} : std::vector<int>{1, 2};
}

// Lowest eigenpairs of dense (K, M) without the rows/columns `held`, ascending [Hz].
Eigen::VectorXd DenseFrequenciesHz(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                                   const std::vector<int>& held) {
  std::vector<int> free;
  for (int i = 0; i < K.rows(); ++i)
    if (std::find(held.begin(), held.end(), i) == held.end()) free.push_back(i);
  const int n = static_cast<int>(free.size());
  Eigen::MatrixXd Kf(n, n), Mf(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      Kf(a, b) = K(free[a], free[b]);
      Mf(a, b) = M(free[a], free[b]);
    }
  const DenseEigenpairs es = SolveDenseEigenpairs(Kf, Mf);
  if (!es.ok)
    EMB_THROW(NumericalError, "reduced eigen-problem (" << n << " unknowns) failed: its mass "
                                                            "matrix is not positive definite");
  // The reduced pencils are small and well scaled: round-off level backward errors.
  constexpr double kReducedResidualTolerance = 1e-8;
  if (!es.check.Passed(kReducedResidualTolerance))
    EMB_THROW(NumericalError, "reduced eigen-problem (" << n << " unknowns): eigenpair check "
                                                            "failed: "
                                                         << es.check.Describe(
                                                                kReducedResidualTolerance));
  return es.eigenvalues.unaryExpr([](double l) { return FrequencyHz(l); });
}

struct Context {
  const ComparisonOptions& o;
  const ProgressFn& progress;
  PartComparison& out;
  Mesh mesh;
  SystemMatrices sys;
  std::vector<Station> stations;
  SampledShapes reference_samples;
  std::vector<std::string> journals;
  std::vector<InterfaceSpec> interfaces;
};

// The beam model's options; of the meshing parameters only those its .geo declares (the
// mesh's own, e.g. n_curv, may not exist in a separate beam geometry).
BeamGenerationOptions GenerationOptions(const ComparisonOptions& o, WebModel webs) {
  BeamGenerationOptions g;
  const std::string& path = o.beam_geometry.empty() ? o.geometry : o.beam_geometry;
  const auto declared = GeoParameters(path);
  for (const auto& p : o.meshing.parameters)
    if (path == o.geometry || std::any_of(declared.begin(), declared.end(),
                                          [&](const auto& d) { return d.first == p.first; }))
      g.parameters.push_back(p);
  g.material = o.material;
  g.max_element_length = o.beam_element_length;
  g.shear_deformable = o.shear_deformable;
  g.webs = webs;
  g.web_width = o.web_width;
  g.trust_scripts = o.meshing.trust_scripts;
  return g;
}

void CheckSamePart(const GeneratedBeamModel& beam, const Context& c) {
  const ComparisonOptions& o = c.o;
  const double m_beam = beam.geometry.mass, m_fe = c.sys.mass;
  double x0 = 1e300, x1 = -1e300;
  for (const GeometryPart& p : beam.parts) {
    x0 = std::min(x0, p.x_min);
    x1 = std::max(x1, p.x_max);
  }
  const double l_beam = x1 - x0;
  const double l_fe = c.mesh.nodes.row(0).maxCoeff() - c.mesh.nodes.row(0).minCoeff();
  const bool mass_ok = std::abs(m_beam - m_fe) <= o.same_part_tolerance * m_fe;
  const bool length_ok = std::abs(l_beam - l_fe) <= o.same_part_tolerance * l_fe;
  EMB_THROW_IF(!mass_ok || !length_ok,
               "the beam model of '" << beam.source << "' (" << m_beam << " kg, " << l_beam
                                     << " m along x) and the 3-D model of '" << c.mesh.source
                                     << "' (" << m_fe << " kg, " << l_fe
                                     << " m) are not of the same part: expected mass and length "
                                        "within "
                                     << 100 * o.same_part_tolerance << " %");
}

void RunReference(Context& c) {
  const ComparisonOptions& o = c.o;
  Stopwatch sw;
  EigenResult eig;
  Eigen::VectorXd hz;
  if (o.support == SupportCase::kFreeFree) {
    ModalOptions mo;
    mo.num_modes = o.num_modes + 6;
    const ModalResult r = ComputeModes(c.sys, mo, c.progress);
    eig = r.eig;
    hz = r.frequencies_hz;
  } else {
    // C: the held rows of each journal's RBE3 average.
    const std::vector<Interface> ifs = ResolveInterfaces(c.mesh, c.interfaces);
    std::vector<Eigen::Triplet<double>> t;
    int row = 0;
    for (size_t j = 0; j < ifs.size(); ++j) {
      const Eigen::MatrixXd W = ifs[j].AveragingOperator(c.mesh);
      for (int comp : HeldComponents(j)) {
        for (size_t s = 0; s < ifs[j].nodes.size(); ++s)
          for (int d = 0; d < 3; ++d)
            t.emplace_back(row, 3 * ifs[j].nodes[s] + d, W(comp, 3 * static_cast<int>(s) + d));
        ++row;
      }
    }
    SparseMatrix C(row, c.sys.num_dofs());
    C.setFromTriplets(t.begin(), t.end());
    EigenSolverOptions so;
    so.num_modes = o.num_modes + 1;
    so.shift = LambdaFromHz(-1.0);
    eig = SolveGeneralizedEigen(c.sys.K, c.sys.M, C, so, c.progress);
    hz.resize(eig.eigenvalues.size());
    for (int i = 0; i < hz.size(); ++i) hz[i] = FrequencyHz(eig.eigenvalues[i]);
  }
  if (!eig.ok())
    EMB_THROW(NumericalError, "3-D reference eigen-solve " << Name(eig.status) << ": "
                                                           << eig.message);
  const Modes m = Elastic(hz, eig.vectors, o.num_modes);
  RouteResult r;
  r.name = "fe";
  r.method = "fe";
  r.variant = "3-D " + c.out.mesh_summary;
  r.num_unknowns = c.sys.num_dofs();
  r.seconds = c.out.mesh_seconds + c.out.assembly_seconds + sw.seconds();
  r.pairing = "reference";
  r.frequencies_hz = m.hz;
  r.mac = Eigen::VectorXd::Ones(m.hz.size());
  c.reference_samples = SampleMeshShapes(c.mesh, c.stations, m.shapes);
  for (int j = 0; j < m.hz.size(); ++j) {
    ReferenceMode rm;
    rm.frequency_hz = m.hz[j];
    rm.section_deformation = c.reference_samples.section_deformation[j];
    rm.beam_like = rm.section_deformation < o.shell_threshold;
    c.out.reference.push_back(rm);
  }
  c.out.routes.push_back(r);
}

void RunCms(Context& c, int count) {
  Stopwatch sw;
  ReductionJob job;
  job.interfaces = c.interfaces;
  job.reduction.selection.kind = ModeSelection::Kind::kCount;
  job.reduction.selection.count = count;
  job.certificate.reference = false;
  job.certificate.static_check = false;
  job.keep_mesh_shapes = false;
  const ReducedBody body = ReduceBody(c.mesh, c.sys, c.o.material, job, c.progress);
  if (!body.ok())
    EMB_THROW(NumericalError, "CMS side: the reduction failed (" << Name(body.status)
                                                                 << "): " << body.message);
  Eigen::VectorXd hz;
  if (c.o.support == SupportCase::kFreeFree) {
    hz = body.modes.frequencies_hz;
  } else {
    std::vector<int> held;
    for (size_t j = 0; j < body.interfaces.size(); ++j)
      for (int comp : HeldComponents(j)) held.push_back(6 * static_cast<int>(j) + comp);
    hz = DenseFrequenciesHz(body.K, body.M, held);
  }
  const Modes m = Elastic(hz, Eigen::MatrixXd(), static_cast<int>(c.out.reference.size()));
  RouteResult r;
  r.name = "cms " + std::to_string(count);
  r.method = "cms";
  r.variant = std::to_string(count) + " modes";
  r.num_unknowns = static_cast<int>(body.K.rows());
  r.seconds = c.out.mesh_seconds + c.out.assembly_seconds + sw.seconds();
  r.pairing = "order (Ritz bounds)";
  const int nref = static_cast<int>(c.out.reference.size());
  r.frequencies_hz = Eigen::VectorXd::Constant(nref, kNaN);
  r.mac = Eigen::VectorXd::Constant(nref, kNaN);
  for (int j = 0; j < std::min<int>(nref, m.hz.size()); ++j) r.frequencies_hz[j] = m.hz[j];
  if (m.hz.size() < nref)
    r.note = "the reduced body has " + std::to_string(m.hz.size()) + " elastic modes";
  c.out.routes.push_back(r);
}

// Beam FE (lumped and consistent) and TMM for one web model.
void RunBeams(Context& c, WebModel webs, bool has_webs) {
  const ComparisonOptions& o = c.o;
  const std::string suffix = has_webs ? std::string(", ") + Name(webs) + " webs" : "";
  Stopwatch sw;
  GeneratedBeamModel g =
      MakeBeamModelFromGeometry(c.out.beam_geometry, GenerationOptions(o, webs));
  if (o.support == SupportCase::kInstalled) AddJournalSupports(g.model, c.journals);
  const double t_generate = sw.seconds();
  const int nref = static_cast<int>(c.out.reference.size());
  std::vector<int> lumped_position(nref, -1);  // spectrum position of the lumped match
  Eigen::VectorXd lumped_hz;
  for (BeamMassType mass : {BeamMassType::kLumped, BeamMassType::kConsistent}) {
    sw.Restart();
    const BeamSystem sys = AssembleBeamSystem(g.model, mass);
    // Enough candidates for the pairing, not the whole spectrum: a stiff, nearly massless
    // elastic web arm puts its top where eigenpairs cannot pass the round-off checks.
    BeamModalOptions mo;
    mo.num_modes = kBeamCandidatesPerMode * nref + 6;
    const BeamModes modes = CalcBeamModes(sys, mo);
    const double t_solve = sw.seconds();
    if (!modes.ok())
      EMB_THROW(NumericalError, "beam modes (" << Name(mass) << suffix << "): " << modes.message);
    int first_elastic = 0;
    while (first_elastic < modes.frequencies_hz.size() &&
           modes.frequencies_hz[first_elastic] <= kRigidModeHz)
      ++first_elastic;
    const int ne = static_cast<int>(modes.frequencies_hz.size()) - first_elastic;
    const Eigen::VectorXd hz = modes.frequencies_hz.tail(ne);
    const SampledShapes s =
        SampleBeamShapes(g.model, c.stations, modes.shapes.rightCols(ne));
    // Only beam-like reference modes are paired: a shell mode's rigid fit is ~0, and the
    // MAC of what is left says nothing.
    std::vector<int> beam_like;
    for (int j = 0; j < nref; ++j)
      if (c.out.reference[j].beam_like) beam_like.push_back(j);
    Eigen::MatrixXd ref(c.reference_samples.values.rows(), beam_like.size());
    for (size_t k = 0; k < beam_like.size(); ++k)
      ref.col(k) = c.reference_samples.values.col(beam_like[k]);
    const ModePairing pairing = PairModesByShape(ref, s.values, hz);
    RouteResult r;
    r.name = std::string("beam ") + Name(mass) + suffix;
    r.method = "beam";
    r.variant = std::string(Name(mass)) + suffix;
    r.num_unknowns = static_cast<int>(sys.free_dofs.size());
    r.seconds = t_generate + t_solve;
    r.pairing = "MAC";
    r.frequencies_hz = Eigen::VectorXd::Constant(nref, kNaN);
    r.mac = Eigen::VectorXd::Constant(nref, kNaN);
    for (size_t k = 0; k < beam_like.size(); ++k) {
      const int j = beam_like[k], i = pairing.match[k];
      r.mac[j] = pairing.score[k];
      if (i < 0) continue;
      r.frequencies_hz[j] = hz[i];
      if (mass == BeamMassType::kLumped) lumped_position[j] = first_elastic + i + 1;
    }
    if (mass == BeamMassType::kLumped) lumped_hz = modes.frequencies_hz;
    c.out.routes.push_back(r);
  }

  // TMM: the lumped model's equations; its roots pair as the lumped modes do. The automatic
  // band covers the reference and every paired lumped mode (a stiff beam's are far above).
  double band = 0.0;
  for (const ReferenceMode& m : c.out.reference) band = std::max(band, kTmmBandFactor * m.frequency_hz);
  for (int p : lumped_position)
    if (p > 0) band = std::max(band, kTmmBandFactor * lumped_hz[p - 1]);
  TmmOptions to;
  to.min_hz = o.tmm_min_hz;
  to.max_hz = o.tmm_max_hz > 0.0 ? o.tmm_max_hz : band;
  to.scan_intervals = o.tmm_scan_intervals;
  sw.Restart();
  const TmmResult t = CalcTmmModes(g.model, to);
  const double t_tmm = sw.seconds();
  EMB_THROW_IF(t.status == TmmStatus::kNoRoots && o.tmm_max_hz > 0.0,
               "TMM band [" << to.min_hz << ", " << to.max_hz << "] Hz holds no natural frequency "
                            << "of the beam model" << suffix << " (" << t.num_below_band
                            << " modes lie below it): " << t.message);
  RouteResult r;
  r.name = "tmm" + suffix;
  r.method = "tmm";
  r.variant = std::string("lumped") + suffix;
  r.num_unknowns = static_cast<int>(t.node_order.size()) * kBeamNodeDofs;
  r.seconds = t_generate + t_tmm;
  r.pairing = "as the lumped beam";
  r.frequencies_hz = Eigen::VectorXd::Constant(nref, kNaN);
  r.mac = Eigen::VectorXd::Constant(nref, kNaN);
  if (!t.ok()) r.note = std::string(Name(t.status)) + ": " + t.message;
  for (const TmmMode& m : t.modes) {
    if (m.index - 1 < lumped_hz.size() && lumped_hz[m.index - 1] > kRigidModeHz)
      c.out.tmm_vs_lumped = std::max(
          c.out.tmm_vs_lumped, std::abs(m.frequency_hz - lumped_hz[m.index - 1]) / lumped_hz[m.index - 1]);
    for (int j = 0; j < nref; ++j)
      if (lumped_position[j] == m.index) r.frequencies_hz[j] = m.frequency_hz;
  }
  c.out.routes.push_back(r);
}

}  // namespace

const char* Name(SupportCase s) { return s == SupportCase::kFreeFree ? "free-free" : "installed"; }

double RouteResult::Error(const std::vector<ReferenceMode>& reference, int j) const {
  if (j < 0 || j >= frequencies_hz.size() || j >= static_cast<int>(reference.size())) return kNaN;
  return frequencies_hz[j] / reference[j].frequency_hz - 1.0;
}

PartComparison RunPartComparison(const ComparisonOptions& o, const ProgressFn& progress) {
  EMB_THROW_IF(o.num_modes < 1, "number of modes to compare: expected >= 1, got " << o.num_modes);
  for (int n : o.cms_modes)
    EMB_THROW_IF(n < 0, "CMS mode count: expected >= 0, got " << n);
  EMB_THROW_IF(o.webs.empty(), "web models: expected at least one (rigid, elastic)");
  EMB_THROW_IF(!(std::isfinite(o.web_width) && o.web_width >= 0.0),
               "web width: expected > 0 m (or 0 for the geometry's), got " << o.web_width);
  EMB_THROW_IF(!(o.shell_threshold > 0.0 && o.shell_threshold < 1.0),
               "shell threshold: expected in (0, 1), got " << o.shell_threshold);
  EMB_THROW_IF(!(o.same_part_tolerance > 0.0),
               "same-part tolerance: expected > 0, got " << o.same_part_tolerance);
  EMB_THROW_IF(o.tmm_max_hz < 0.0 || o.tmm_min_hz < 0.0 ||
                   (o.tmm_max_hz > 0.0 && o.tmm_max_hz <= o.tmm_min_hz),
               "TMM band: expected 0 <= min < max [Hz], got [" << o.tmm_min_hz << ", "
                                                               << o.tmm_max_hz << "]");
  o.material.Validate();

  PartComparison out;
  out.geometry = o.geometry;
  out.beam_geometry = o.beam_geometry.empty() ? o.geometry : o.beam_geometry;
  out.part = std::filesystem::path(o.geometry).stem().string();
  out.support = o.support;
  Context c{o, progress, out, {}, {}, {}, {}, {}, {}};

  // The solid, not the beam parts: gmsh keeps a parameter set in one session (the beam
  // generator's beam_parts = 1) for the next, so the mesh names its own value.
  MeshingOptions meshing = o.meshing;
  const auto declared = GeoParameters(o.geometry);
  const auto named = [](const auto& list) {
    return std::any_of(list.begin(), list.end(), [](const auto& p) { return p.first == "beam_parts"; });
  };
  if (named(declared) && !named(meshing.parameters)) meshing.parameters.emplace_back("beam_parts", 0.0);
  Stopwatch sw;
  c.mesh = ReadMesh(o.geometry, meshing, progress);
  out.mesh_seconds = sw.seconds();
  out.mesh_summary = c.mesh.Summary();
  sw.Restart();
  c.sys = AssembleSystem(c.mesh, o.material, progress);
  out.assembly_seconds = sw.seconds();
  // The beam model after the mesh: gmsh keeps global options set by a .geo for the next
  // session in the process, and a separate beam geometry's (e.g. the tube's high-order
  // optimisation) would slow the part's meshing several-fold.
  const GeneratedBeamModel probe =
      MakeBeamModelFromGeometry(out.beam_geometry, GenerationOptions(o, WebModel::kRigid));
  for (const GeometryPart& p : probe.parts)
    if (p.kind == GeometryPart::Kind::kSegment && IsJournal(p.name)) c.journals.push_back(p.name);
  std::sort(c.journals.begin(), c.journals.end());
  const bool has_webs = !probe.model.rigid_parts().empty();
  EMB_THROW_IF(o.support == SupportCase::kInstalled && c.journals.empty(),
               "installed case: the part '" << out.beam_geometry
                                            << "' has no main journals (beam segments "
                                               "'main_journal_*') to support; use free-free");

  out.fe_dofs = c.sys.num_dofs();
  out.fe_mass_kg = c.sys.mass;
  out.geometry_mass_kg = probe.geometry.mass;
  CheckSamePart(probe, c);

  c.stations = MakeStations(probe, c.mesh, o.axis_stations);
  for (const Station& s : c.stations) out.stations.push_back(s.name);
  if (!c.journals.empty()) {
    for (const std::string& j : c.journals) c.interfaces.push_back({j, Coupling::kRbe3, {}});
  } else {
    for (const InterfaceSpec& s : DefaultInterfaces(c.mesh))
      c.interfaces.push_back({s.group, Coupling::kRbe3, s.point});
  }
  for (const InterfaceSpec& s : c.interfaces) out.interfaces.push_back(s.ToString());
  EMB_THROW_IF(c.interfaces.empty(), "CMS routes: the mesh of '"
                                         << o.geometry
                                         << "' has none of emb's interface groups (main_journal_*, "
                                            "end_a/end_b); groups: "
                                         << c.mesh.GroupNames());
  out.support_description =
      o.support == SupportCase::kFreeFree
          ? "free-free (six rigid-body modes dropped)"
          : "journal centres held radially, " + c.journals.front() +
                " also axially; spin about the axis free (3-D and CMS: RBE3 averages of the "
                "journal surfaces held)";

  RunReference(c);
  for (int n : o.cms_modes) RunCms(c, n);
  if (has_webs) {
    for (WebModel w : o.webs) RunBeams(c, w, true);
  } else {
    RunBeams(c, WebModel::kRigid, false);
  }
  int shells = 0;
  for (const ReferenceMode& m : out.reference) shells += !m.beam_like;
  if (shells > 0)
    out.notes.push_back(std::to_string(shells) +
                        " reference mode(s) deform their cross-sections (shell/ovalling): no "
                        "beam can represent them");
  return out;
}

}  // namespace emb
