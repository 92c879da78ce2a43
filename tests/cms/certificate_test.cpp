// The reduction certificate: limits that grow with the conditioning (issue 14) but still fail
// a basis that is wrong — a constraint mode perturbed by 1e-5 breaks static exactness and the
// constraint-mode residual, and the certificate says so with the numbers' digits.

#include "libemb/cms/certificate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libemb/cms/craig_bampton.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(CertificateLimits, FloorsGrowWithTheConditioning) {
  EXPECT_EQ(CertificateLimits::Orthonormality(1.0), CertificateLimits::kOrthonormality);
  EXPECT_EQ(CertificateLimits::ConstraintModes(10.0), CertificateLimits::kConstraintModes);
  EXPECT_DOUBLE_EQ(CertificateLimits::Orthonormality(1e8),
                   CertificateLimits::kRoundOffMultiple * kEps * 1e8);
  EXPECT_DOUBLE_EQ(CertificateLimits::ConstraintModes(1e9),
                   CertificateLimits::kRoundOffMultiple * kEps * 1e9);
}

struct Certified {
  ReductionBasis basis;
  Eigen::MatrixXd K, M;
  OrthonormalModes modes;
  ReductionCertificate cert;
};

Certified Certify(const Mesh& mesh, const SystemMatrices& sys, ReductionBasis basis) {
  Certified c;
  c.K = basis.T.transpose() * (sys.K * basis.T);
  c.M = basis.T.transpose() * (sys.M * basis.T);
  c.K = 0.5 * (c.K + c.K.transpose()).eval();
  c.M = 0.5 * (c.M + c.M.transpose()).eval();
  c.modes = Orthonormalise(c.K, c.M, basis.rigid);
  const Eigen::MatrixXd phi = basis.T * c.modes.elastic;
  CertificateOptions o;
  o.reference = false;  // the verdicts at stake here are the static ones
  c.cert = CertifyReduction(mesh, sys, 7850.0, basis, c.K, c.M, c.modes, phi, o);
  c.basis = std::move(basis);
  return c;
}

TEST(Certificate, PassesTheBasisAndFailsItPerturbed) {
  const Mesh mesh = MakeBoxMesh({0.6, 0.06, 0.04}, {12, 2, 2}, CellType::kHex20);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  std::vector<InterfaceSpec> specs = {InterfaceSpec::Parse("x0:rbe2"),
                                      InterfaceSpec::Parse("x1:rbe3")};
  ReductionOptions ro;
  ro.selection.count = 6;
  const ReductionBasis basis = BuildReductionBasis(mesh, sys, ResolveInterfaces(mesh, specs), ro);
  const Certified good = Certify(mesh, sys, basis);
  EXPECT_TRUE(good.cert.passed()) << good.cert.failures.front();
  EXPECT_LE(good.cert.static_error, CertificateLimits::kStatic);

  // Constraint mode t_y of x1 (column 7) perturbed by 1e-3 in its interior: no longer the
  // static response. The basis still holds the rigid motions, so only the static items fail.
  ReductionBasis bad = basis;
  // (The interface compliance errs to second order in the perturbation: 1e-6 ≫ 1e-8.)
  const double amplitude = 1e-3 * bad.T.col(7).cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < bad.T.rows(); i += 7) bad.T(i, 7) += amplitude;
  const Certified wrong = Certify(mesh, sys, bad);
  EXPECT_FALSE(wrong.cert.passed());
  bool static_failure = false;
  for (const std::string& f : wrong.cert.failures) {
    static_failure |= f.find("not statically exact") != std::string::npos;
    EXPECT_EQ(f.find("0.000000"), std::string::npos) << f;  // numbers keep their digits
  }
  EXPECT_TRUE(static_failure);
  EXPECT_GT(wrong.cert.static_error, 10 * CertificateLimits::kStatic);
}

}  // namespace
}  // namespace emb
