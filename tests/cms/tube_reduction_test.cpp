// The driveshaft tube reduced to its two end flanges (RBE2, the default interfaces) with the
// default mode count: its first ten elastic free-free frequencies within 0.1 % of the full FE
// model with the same couplings, every degenerate bending pair kept whole.

#include <gtest/gtest.h>

#include "libemb/cms/reduction.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/gmsh_reader.h"

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
}

}  // namespace
}  // namespace emb
