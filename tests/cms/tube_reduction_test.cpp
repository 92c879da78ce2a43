// The driveshaft tube reduced to its two end flanges (RBE2, the default interfaces) with the
// default mode count: its first ten elastic free-free frequencies within 0.1 % of the full FE
// model with the same couplings (the certificate's reference), every degenerate bending pair
// kept whole, and — an oracle independent of the library's certificate — its first bending
// pair against Timoshenko beam theory.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "libemb/cms/reduction.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tests/support/timoshenko_beam.h"

namespace emb {
namespace {

TEST(TubeReduction, FirstTenElasticFrequenciesWithinATenthOfAPercent) {
  MeshingOptions o;
  o.parameters = {{"n_circ", 16}, {"h", 0.03}};  // 27k dof: a coarse mesh of the default tube
  const Mesh mesh = ReadMesh(std::string(EMB_SOURCE_DIR) + "/meshes/tube.geo", o);
  const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  ReductionJob job;
  job.interfaces = DefaultInterfaces(mesh);
  ASSERT_EQ(job.interfaces.size(), 2u);
  job.certificate.fmax_hz = 1420.0;  // just above the tenth elastic mode (1400 Hz)
  job.keep_mesh_shapes = false;
  job.geometric_stiffness = false;  // not what this test checks (and ~3 s at 27k dof)
  const ReducedBody body = ReduceBody(mesh, sys, IsotropicMaterial{}, job);
  const ReductionCertificate& c = body.certificate;
  EXPECT_TRUE(c.passed()) << (c.failures.empty() ? "" : c.failures[0]);
  ASSERT_TRUE(c.reference_run);
  ASSERT_GE(c.pairs.size(), 10u);
  constexpr double kIssueLimit = 1e-3;  // the issue's 0.1 %
  for (int i = 0; i < 10; ++i) {
    const ModePair& p = c.pairs[i];
    EXPECT_TRUE(p.paired) << "mode " << p.full_mode;
    EXPECT_LT(std::abs(p.relative_error), kIssueLimit) << "mode " << p.full_mode << " at " << p.full_hz;
    EXPECT_GT(p.mac, 0.99) << "mode " << p.full_mode;
  }
  // Bending comes in exact pairs (axisymmetric tube): both partners are in the reduced body.
  EXPECT_NEAR(body.modes.frequencies_hz[0], body.modes.frequencies_hz[1],
              1e-6 * body.modes.frequencies_hz[0]);
  EXPECT_LE(c.static_error, CertificateLimits::kStatic);

  // Independent of the certificate: the first elastic pair is the first free-free bending
  // pair of the tube (L = 1.5 m, Ø90 x 2 mm steel, tests/fe/tube_modes_test.cpp identifies it
  // by shape on the full model), against Timoshenko theory for a hollow circle.
  constexpr double kL = 1.5, kRo = 0.045, kRi = 0.043;  // [m]
  const IsotropicMaterial steel;
  const double A = std::numbers::pi * (kRo * kRo - kRi * kRi);
  const double I = std::numbers::pi / 4 * (std::pow(kRo, 4) - std::pow(kRi, 4));
  const test::BeamSection sec{steel.youngs_modulus, steel.mu(), steel.density, A, I,
                              test::KappaHollowCircle(steel.poisson_ratio, kRi, kRo)};
  const double f_bend = test::Hz(
      test::TimoshenkoFrequencies(sec, kL, test::BeamEnd::kFree, test::BeamEnd::kFree, 1)[0]);
  std::printf("reduced bending pair %.3f / %.3f Hz, Timoshenko %.3f Hz\n",
              body.modes.frequencies_hz[0], body.modes.frequencies_hz[1], f_bend);
  // The beam theory's 1 % (the issue's bending target, met by the full model on finer meshes
  // in tube_modes_test) covers this coarse mesh and the rigid end spiders (measured +0.09 %).
  constexpr double kBendingTolerance = 0.01;
  EXPECT_NEAR(body.modes.frequencies_hz[0] / f_bend, 1.0, kBendingTolerance);
  EXPECT_NEAR(body.modes.frequencies_hz[1] / f_bend, 1.0, kBendingTolerance);
}

}  // namespace
}  // namespace emb
