#include "libemb/cms/reduction.h"

#include <algorithm>
#include <sstream>

#include <Eigen/Dense>

#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/fe/mass_properties.h"
#include "libemb/linalg/extended_product.h"
#include "libemb/linalg/sparse_dense_product.h"

namespace emb {

std::string DampingModel::Describe() const {
  std::ostringstream o;
  if (kind == Kind::kModal)
    o << "modal, ratio " << ratio << " for every elastic mode";
  else
    o << "Rayleigh, alpha " << alpha << " 1/s, beta " << beta << " s";
  return o.str();
}

namespace {

// Frees the interfaces not in `supports` in the static inertial load cases (held so far):
// with the held ones at zero, the free boundary coordinates q_F of the exact static response
// solve K̂_FF q_F = Ψ_Fᵀ F (Craig–Bampton static condensation is exact: the interface-held
// response is K-orthogonal to the constraint modes), added as Ψ_F q_F. Returns the support
// description for the body file.
std::string ReleaseFreeInterfaces(const ReducedBody& body, ReductionBasis& basis,
                                  const Eigen::MatrixXd& loads,
                                  const std::vector<std::string>& supports) {
  std::vector<int> free;
  std::string held, released;
  for (std::size_t j = 0; j < body.interfaces.size(); ++j) {
    const std::string& name = body.interfaces[j].name;
    const bool is_held = std::find(supports.begin(), supports.end(), name) != supports.end();
    std::string& list = is_held ? held : released;
    list += (list.empty() ? "" : ", ") + name;
    if (!is_held)
      for (int c = 0; c < 6; ++c) free.push_back(6 * static_cast<int>(j) + c);
  }
  if (!free.empty()) {
    const int nf = static_cast<int>(free.size());
    Eigen::MatrixXd Tf(basis.T.rows(), nf), Kff(nf, nf);
    for (int a = 0; a < nf; ++a) {
      Tf.col(a) = basis.T.col(free[a]);
      for (int b = 0; b < nf; ++b) Kff(a, b) = body.K(free[a], free[b]);
    }
    const Eigen::MatrixXd q = Kff.ldlt().solve(Tf.transpose() * loads);
    basis.static_responses += Tf * q;
  }
  return std::string(kSupportInterfacesHeld) + " (" + held +
         (released.empty() ? "" : "; free: " + released) + ")";
}

}  // namespace

ReducedBody ReduceBody(const Mesh& mesh, const SystemMatrices& sys,
                       const IsotropicMaterial& material, const ReductionJob& job,
                       const ProgressFn& progress) {
  EMB_THROW_IF(job.damping.kind == DampingModel::Kind::kModal && !(job.damping.ratio >= 0.0),
               "damping ratio: expected 0 or more, got " << job.damping.ratio);
  EMB_THROW_IF(job.damping.kind == DampingModel::Kind::kRayleigh &&
                   !(job.damping.alpha >= 0.0 && job.damping.beta >= 0.0),
               "Rayleigh damping: expected alpha, beta >= 0, got " << job.damping.alpha << ", "
                                                                   << job.damping.beta);
  ReducedBody body;
  body.num_fe_dofs = sys.num_dofs();
  Stopwatch sw;
  const std::vector<Interface> interfaces = ResolveInterfaces(mesh, job.interfaces);
  EMB_THROW_IF(!job.stiffening_supports.empty() && interfaces.empty(),
               "stiffening supports: expected interfaces, but the body is free-free (its load "
               "cases use inertia relief)");
  for (const std::string& name : job.stiffening_supports)
    EMB_THROW_IF(std::none_of(interfaces.begin(), interfaces.end(),
                              [&](const Interface& i) { return i.name == name; }),
                 "stiffening supports: '" << name << "' is not an interface of the body");
  // A wrong stress group fails before the expensive part.
  SparseMatrix stress_operator =
      job.stress_groups.empty()
          ? SparseMatrix()
          : BuildGroupStressOperator(mesh, material, job.stress_groups);
  body.times.Add("interfaces", sw.seconds());

  // The nine inertial load cases about the undeformed centre of mass (geometric_stiffening.h).
  Eigen::MatrixXd inertial_loads;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double load_seconds = 0.0;
  if (job.geometric_stiffness) {
    sw.Restart();
    centre = CalcMassProperties(mesh, material.density).center_of_mass;
    inertial_loads = sys.M * InertialLoadFields(mesh, centre);
    load_seconds = sw.seconds();
  }
  ReductionBasis basis =
      BuildReductionBasis(mesh, sys, interfaces, job.reduction, progress, inertial_loads);
  for (const auto& [name, s] : basis.times.phases) body.times.Add(name, s);
  ReturnFreedMemory();  // the interior factorisation and the Krylov basis
  if (!basis.ok()) {
    body.status = basis.status;
    body.message = basis.message;
    return body;
  }
  if (!basis.on_this_process) {  // an MPI rank that took part in the solves: rank 0 goes on
    body.on_this_process = false;
    return body;
  }
  body.interfaces = basis.interfaces;
  body.free_free = basis.free_free;
  body.num_boundary = basis.num_boundary;
  body.fixed_interface_hz = basis.mode_frequencies_hz;
  body.selection_note = basis.selection_note;

  sw.Restart();
  if (progress) progress("reduced matrices", 0.0);
  // The constraint-mode block Ψᵀ K Ψ in extended precision: rigid-like columns have K ψ ≈ 0
  // from cancelling large terms. The blocks with the fixed-interface modes (Ψᵀ K Φ = 0 and
  // Φᵀ K Φ = Λ in exact arithmetic) carry no such cancellation and are formed in double.
  const int nb = basis.num_boundary, nr = static_cast<int>(basis.T.cols());
  {  // K T (N × nr) only while K̂ is formed
    const auto Tb = basis.T.leftCols(nb);
    const auto Tm = basis.T.rightCols(nr - nb);
    const Eigen::MatrixXd KTb = MultiplyExtended(sys.K, Tb, Symmetry::kSymmetric);
    const Eigen::MatrixXd KTm = MultiplySymmetric(sys.K, Tm);
    body.K.resize(nr, nr);
    body.K.topLeftCorner(nb, nb) = TransposeProductExtended(Tb, KTb);
    body.K.topRightCorner(nb, nr - nb) = Tb.transpose() * KTm;
    body.K.bottomLeftCorner(nr - nb, nb) = body.K.topRightCorner(nb, nr - nb).transpose();
    body.K.bottomRightCorner(nr - nb, nr - nb) = Tm.transpose() * KTm;
  }
  body.M = basis.T.transpose() * MultiplySymmetric(sys.M, basis.T);
  body.K = 0.5 * (body.K + body.K.transpose()).eval();
  body.M = 0.5 * (body.M + body.M.transpose()).eval();
  body.times.Add("reduced matrices", sw.seconds());

  sw.Restart();
  body.modes = Orthonormalise(body.K, body.M, basis.rigid);
  body.times.Add("orthonormalisation", sw.seconds());
  if (!body.modes.ok()) {
    body.status = ReductionStatus::kReducedPencilFailed;
    body.message = body.modes.failure;
    return body;
  }
  const Eigen::MatrixXd& X = body.modes.elastic;
  const int ne = static_cast<int>(X.cols());
  body.interface_shapes = basis.free_free ? Eigen::MatrixXd(0, ne)
                                          : Eigen::MatrixXd(X.topRows(basis.num_boundary));

  sw.Restart();
  if (progress) progress("invariants", 0.0);
  Eigen::MatrixXd Phi = basis.T * X;
  body.invariants = CalcInertiaInvariants(mesh.nodes, sys.M, Phi);
  body.times.Add("invariants", sw.seconds());

  // The last use of T (N × nr): interfaces free in service take their static response in the
  // inertial load cases. T is released before the certificate, whose factorisations set the
  // reduction's peak memory (a 293k-DOF crankshaft: 173 MB of ~3.9 GB).
  double release_seconds = 0.0;
  std::string stiffening_support = basis.static_support;
  if (job.geometric_stiffness && !job.stiffening_supports.empty()) {
    sw.Restart();
    stiffening_support =
        ReleaseFreeInterfaces(body, basis, inertial_loads, job.stiffening_supports);
    release_seconds = sw.seconds();
  }
  basis.T = Eigen::MatrixXd();
  inertial_loads = Eigen::MatrixXd();

  // Damping in z: modal D = M̂ X diag(2 ζ ω) Xᵀ M̂ (as XᵀM̂X = I), or Rayleigh α M̂ + β K̂.
  body.damping = job.damping;
  const Eigen::VectorXd omega = body.modes.eigenvalues.cwiseMax(0.0).cwiseSqrt();
  if (job.damping.kind == DampingModel::Kind::kModal) {
    body.damping_ratios = Eigen::VectorXd::Constant(ne, job.damping.ratio);
    const Eigen::MatrixXd MX = body.M * X;
    body.D = MX * (2.0 * body.damping_ratios.cwiseProduct(omega)).asDiagonal() * MX.transpose();
  } else {
    body.damping_ratios = (job.damping.alpha / omega.array().max(1e-300) +
                           job.damping.beta * omega.array()) / 2.0;
    body.D = job.damping.alpha * body.M + job.damping.beta * body.K;
  }

  sw.Restart();
  CertificateOptions certificate_options = job.certificate;
  certificate_options.stress_operator.swap(stress_operator);  // not copied (Eigen 3.4 has no move)
  body.certificate = CertifyReduction(mesh, sys, material.density, basis, body.K, body.M,
                                      body.modes, Phi, certificate_options, progress);
  body.times.Add("certificate", sw.seconds());

  if (!job.stress_groups.empty()) {
    sw.Restart();
    if (progress) progress("modal stresses", 0.0);
    body.stress_groups = CalcModalStresses(mesh, material, Phi, job.stress_groups);
    ReductionCertificate& ct = body.certificate;
    body.stress_check =
        CheckModalStresses(body.stress_groups, ct.static_full_stresses, ct.static_reduced_z, X,
                           body.M, ct.static_note);
    ct.static_full_stresses.resize(0, 0);
    ct.static_reduced_z.resize(0, 0);
    body.times.Add("modal stresses", sw.seconds());
  }

  if (job.stress_surface) {
    sw.Restart();
    if (progress) progress("surface modal stresses", 0.0);
    body.stress_surface = CalcSurfaceModalStresses(mesh, material, Phi);
    body.times.Add("surface modal stresses", sw.seconds());
  }

  if (job.geometric_stiffness) {
    sw.Restart();
    if (progress) progress("geometric stiffness", 0.0);
    body.geometric_stiffness =
        ReduceGeometricStiffness(mesh, material, sys.K, basis.static_responses, Phi);
    body.geometric_stiffness.reference_point = centre;
    body.geometric_stiffness.support = stiffening_support;
    body.times.Add("geometric stiffness", load_seconds + release_seconds + sw.seconds());
  }
  if (job.keep_mesh_shapes) body.mesh_shapes = std::move(Phi);
  return body;
}

}  // namespace emb
