#include "libemb/cms/certificate.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "libemb/cms/coupled_model.h"
#include "libemb/cms/static_exactness.h"
#include "libemb/common/error.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/fe/rigid_body_modes.h"
#include "libemb/linalg/sparse_dense_product.h"

namespace emb {

double CertificateLimits::Orthonormality(double mass_condition) {
  return std::max(kOrthonormality, kRoundOffMultiple * std::numeric_limits<double>::epsilon() *
                                       std::max(mass_condition, 1.0));
}
double CertificateLimits::ConstraintModes(double stiffness_condition) {
  return std::max(kConstraintModes, kRoundOffMultiple * std::numeric_limits<double>::epsilon() *
                                        std::max(stiffness_condition, 1.0));
}

namespace {
// A small number with its digits ("4.6e-10", not std::to_string's "0.000000").
std::string Sci(double v) {
  std::ostringstream o;
  o << std::setprecision(2) << v;
  return o.str();
}
}  // namespace
namespace {

constexpr double kPairedMac = 0.5;

double RelativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / b.norm();
}

std::string EigenLog(const EigenResult& r) {
  std::ostringstream o;
  o << r.method << ", shift " << r.shift << " rad^2/s^2, " << r.iterations << " restarts, "
    << r.num_solves << " solves, " << r.num_converged << "/" << r.num_requested
    << " converged, worst backward error " << r.max_backward_error;
  return o.str();
}

}  // namespace

ReductionCertificate CertifyReduction(const Mesh& mesh, const SystemMatrices& sys, double density,
                                      const ReductionBasis& basis, const Eigen::MatrixXd& Khat,
                                      const Eigen::MatrixXd& Mhat, const OrthonormalModes& modes,
                                      const Eigen::MatrixXd& elastic_shapes,
                                      const CertificateOptions& options,
                                      const ProgressFn& progress) {
  ReductionCertificate cert;
  auto fail = [&](const std::string& what) { cert.failures.push_back(what); };

  // 1. Mass properties.
  const Eigen::Matrix<double, 6, 6> full_rr = [&] {
    const Eigen::MatrixXd R = RigidBodyModes(mesh);  // N × 6: not held into the solves below
    return Eigen::Matrix<double, 6, 6>(R.transpose() * (sys.M * R));
  }();
  const Eigen::Matrix<double, 6, 6> red_rr = basis.rigid.transpose() * Mhat * basis.rigid;
  cert.full = MassPropertiesFromRigidMass(full_rr);
  cert.reduced = MassPropertiesFromRigidMass(red_rr);
  cert.quadrature = CalcMassProperties(mesh, density);
  cert.mass_error = std::abs(cert.reduced.mass - cert.full.mass) / cert.full.mass;
  // Centre of mass relative to the radius of gyration (the centre may be at the origin).
  const double gyration = std::sqrt(cert.full.inertia_about_com.trace() / (2.0 * cert.full.mass));
  cert.com_error = (cert.reduced.center_of_mass - cert.full.center_of_mass).norm() / gyration;
  cert.inertia_error = RelativeError(cert.reduced.inertia_about_com, cert.full.inertia_about_com);
  cert.quadrature_mass_error = std::abs(cert.full.mass - cert.quadrature.mass) / cert.quadrature.mass;
  constexpr double kMassLimit = CertificateLimits::kMassProperties;
  if (!(cert.mass_error <= kMassLimit && cert.com_error <= kMassLimit &&
        cert.inertia_error <= kMassLimit))
    fail("mass properties of the reduced body differ from the full model (mass, centre and "
         "inertia errors " + Sci(cert.mass_error) + ", " + Sci(cert.com_error) + ", " +
         Sci(cert.inertia_error) + ", limit " + Sci(kMassLimit) + ")");
  // Two quadratures of the same mass integrals: round-off apart.
  if (!(cert.quadrature_mass_error <= kMassLimit))
    fail("the consistent mass matrix disagrees with the mesh's mass quadrature");

  // 2. Rigid modes.
  cert.rigid_hz = modes.rigid_frequencies_hz;
  cert.num_near_zero = modes.num_near_zero;
  if (cert.num_near_zero != 6)
    fail("expected exactly 6 rigid-body modes, found " + std::to_string(cert.num_near_zero));

  // 3. Orthonormality.
  cert.orthonormality_error = modes.orthonormality_error;
  cert.k_diagonality_error = modes.k_diagonality_error;
  cert.degenerate_coupling = modes.degenerate_coupling;
  cert.rigid_stiffness = modes.rigid_stiffness;
  cert.orthonormality_limit = CertificateLimits::Orthonormality(modes.mass_condition);
  if (!(cert.orthonormality_error <= cert.orthonormality_limit &&
        cert.k_diagonality_error <= cert.orthonormality_limit))
    fail("the orthonormalised basis is not M-orthonormal and K-diagonal (errors " +
         Sci(cert.orthonormality_error) + " and " + Sci(cert.k_diagonality_error) + ", limit " +
         Sci(cert.orthonormality_limit) + " at mass condition " + Sci(modes.mass_condition) + ")");

  // 4. Free-free frequencies vs the full model.
  const int ne = static_cast<int>(modes.frequencies_hz.size());
  // Default band: half the highest fixed-interface frequency kept (a CB basis is accurate well
  // below its cut-off; see ModeSelection::band_factor); for a free-free basis all its modes.
  const Eigen::VectorXd& kept = basis.mode_frequencies_hz;
  if (options.fmax_hz > 0)
    cert.fmax_hz = options.fmax_hz;
  else if (basis.free_free)
    cert.fmax_hz = ne > 0 ? modes.frequencies_hz[ne - 1] : 0.0;
  else
    cert.fmax_hz = kept.size() > 0 ? kept.maxCoeff() / ModeSelection().band_factor : 0.0;
  // The full model with the same couplings: the reference of items 4 and 5, built once (and
  // only if one of them runs).
  const bool compare = options.reference && ne > 0;
  const bool statics = options.static_check && !basis.free_free && basis.interfaces.size() >= 2;
  Stopwatch coupled_sw;
  const CoupledModel model =
      compare || statics ? BuildCoupledModel(mesh, sys, basis.interfaces) : CoupledModel{};
  if (compare || statics) cert.times.Add("coupled model", coupled_sw.seconds());
  ReturnFreedMemory();  // the temporaries of the coupled model and of the invariants
  if (compare) {
    Stopwatch sw;
    int in_band = 0;
    while (in_band < ne && modes.frequencies_hz[in_band] <= cert.fmax_hz) ++in_band;
    // Free-free modes of the coupled model, the rigid ones too (σ below the spectrum), until
    // the highest passes fmax.
    EigenSolverOptions so = options.solver;
    so.shift = LambdaFromHz(-1.0);
    // A part in one piece: its six rigid motions are all of the null space, locked from the
    // start instead of searched for.
    if (ConnectedPieces(mesh).count == 1) so.null_space = model.rigid;
    // Blocks of kReferenceBlockSize unless the options say: the Krylov basis (about the wanted
    // pairs plus four blocks, block_krylov_schur.h) is held with the full model's factorisation
    // and the reduced body's shapes, where a reduction's memory peaks. On the 293k-DOF
    // crankshaft (21 pairs) blocks of 8 hold 61 basis columns instead of 101 (−190 MB).
    constexpr int kReferenceBlockSize = 8;
    if (so.block_size == 0) so.block_size = kReferenceBlockSize;
    const SparseMatrix none(0, model.size());
    ShiftInvertSolver solver(model.K, model.M, none, so.backend);
    // Factorised here so that the factorisation's freed temporaries (K − σM, CHOLMOD's
    // workspace) are returned before the Krylov basis is allocated; the solve reuses it (and
    // factorises itself, with its own error report, if this failed).
    if (solver.Prepare(so.shift)) ReturnFreedMemory();
    const EigenResult ref =
        SolveLowestModes(solver, so, 6 + std::max(in_band, 1) + 4, cert.fmax_hz, model.size(), progress);
    cert.reference_log = EigenLog(ref);
    if (!ref.ok()) {
      fail("the full model's eigen-solve failed: " + ref.message);
    } else {
      cert.reference_run = true;
      // Expanded modes, both M-orthonormal in the full model: the MAC of a pair is
      // (φ_rᵀ M P φ_y)².
      const Eigen::MatrixXd& Phi_r = elastic_shapes;
      const Eigen::MatrixXd MPphi = MultiplySymmetric(sys.M, model.P * ref.vectors);
      const Eigen::MatrixXd cross = (Phi_r.transpose() * MPphi).cwiseAbs2();
      const int num_rigid = CountRigidModes(ref.eigenvalues, NormOne(model.K) / NormOne(model.M));
      for (int i = num_rigid; i < ref.eigenvalues.size(); ++i) {
        const double f = FrequencyHz(ref.eigenvalues[i]);
        if (f > cert.fmax_hz) break;
        ModePair p;
        p.full_mode = i + 1 - num_rigid;
        p.full_hz = f;
        int best;
        cross.col(i).maxCoeff(&best);
        p.reduced_mode = best + 1;
        p.reduced_hz = modes.frequencies_hz[best];
        p.relative_error = (p.reduced_hz - f) / f;
        // A degenerate group shares one subspace: sum the MAC over it.
        for (int j = 0; j < ne; ++j)
          if (std::abs(modes.frequencies_hz[j] - p.reduced_hz) <= 1e-3 * p.reduced_hz)
            p.mac += cross(j, i);
        // A full mode the basis cannot represent (MAC < 0.5) is listed, not paired.
        p.paired = p.mac >= kPairedMac;
        if (p.paired) {
          cert.max_frequency_error = std::max(cert.max_frequency_error, std::abs(p.relative_error));
          cert.min_mac = std::min(cert.min_mac, p.mac);
        } else {
          ++cert.num_unrepresented;
        }
        cert.pairs.push_back(p);
      }
    }
    cert.times.Add("reference modes", sw.seconds());
  }
  ReturnFreedMemory();  // the reference factorisation and Krylov basis

  // 5. Static exactness.
  if (options.static_check) {
    const Stopwatch static_sw;
    StaticExactness st = CheckStaticExactness(mesh, model, basis, Khat, options.stress_operator);
    cert.static_full_stresses = std::move(st.full_stresses);
    cert.static_reduced_z = std::move(st.reduced_z);
    cert.static_run = st.run;
    cert.static_note = st.note;
    cert.static_loads = st.num_loads;
    cert.static_error = st.max_error;
    if (st.run) cert.times.Add("static check", static_sw.seconds());
    ReturnFreedMemory();  // the pinned factorisation
    if (st.run && !(st.max_error <= CertificateLimits::kStatic))
      fail("the reduced body is not statically exact at its interfaces (error " +
           Sci(st.max_error) + ", limit " + Sci(CertificateLimits::kStatic) + ")");
  } else {
    cert.static_note = "not run (switched off)";
  }

  // 6. The reduction's eigen-solve.
  cert.reduction_log = basis.eig.num_requested > 0 ? EigenLog(basis.eig) : "no eigen-solve";
  cert.constraint_mode_iterations = basis.static_iterations;
  cert.constraint_mode_residual = basis.static_residual;
  cert.constraint_mode_limit = CertificateLimits::ConstraintModes(basis.stiffness_condition);
  if (!basis.free_free && !(basis.static_residual <= cert.constraint_mode_limit))
    fail("the constraint modes are inaccurate (relative residual " +
         Sci(basis.static_residual) + ", limit " + Sci(cert.constraint_mode_limit) +
         " at stiffness condition " + Sci(basis.stiffness_condition) + ")");
  return cert;
}

}  // namespace emb
