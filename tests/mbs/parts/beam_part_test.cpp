// A part modelled as beams (mbs/flexible/beam_part.h), built in C++: the crankshaft's
// geometry expands into node bodies and beam force elements whose linearisation is the lumped
// beam FE model of the same geometry (same mass, same free-free frequencies), with markers at
// the 3-D model's interfaces (named by the generated model). The scene key `model: beam` is
// tested in tests/scene/beam_part_scene_test.cpp.

#include "libemb/mbs/parts/beam_part.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_modal.h"
#include "libemb/common/error.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/forces/force_jacobian.h"

namespace emb::mbs {
namespace {

const std::string kCrank = std::string(EMB_SOURCE_DIR) + "/meshes/crankshaft_i4.geo";

// The part's linearisation at its initial state: the frequencies [Hz, ascending] of the
// pencil (K, M), K from the force elements' Jacobian, and the total mass (the translational
// block of every body).
struct Linearised {
  Eigen::VectorXd frequencies_hz;
  double mass{0.0};
};
Linearised Linearise(const System& sys, const BeamPart& part) {
  const Eigen::VectorXd q = sys.InitialPositions(), v = sys.InitialVelocities();
  const auto bodies = CalcBodyKinematics(sys, q, v);
  DenseForceJacobian jac(sys.layout());
  for (const auto& f : sys.force_elements()) f->AddForceJacobian({&sys, &bodies, 0.0}, &jac);
  const Eigen::MatrixXd K = -jac.stiffness(), M = CalcMassMatrix(sys, bodies);
  Linearised out;
  for (int b = 1; b <= static_cast<int>(part.bodies.size()); ++b)
    out.mass += M(sys.layout().velocity(b), sys.layout().velocity(b));
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (K + K.transpose()), M,
                                                               Eigen::EigenvaluesOnly);
  EXPECT_EQ(es.info(), Eigen::Success);
  out.frequencies_hz = es.eigenvalues().cwiseMax(0.0).cwiseSqrt() / (2 * std::numbers::pi);
  return out;
}

// The lowest eight elastic frequencies of `lin` against the beam FE model's, within
// `tolerance` (relative).
void ExpectLowestElasticFrequencies(const Linearised& lin, const BeamModes& modes,
                                    double tolerance) {
  constexpr int kRigidModes = 6, kCompared = 8;
  for (int i = kRigidModes; i < kRigidModes + kCompared; ++i)
    EXPECT_NEAR(lin.frequencies_hz[i], modes.frequencies_hz[i], tolerance * modes.frequencies_hz[i])
        << "mode " << i + 1;
}

TEST(BeamPart, CrankshaftIsTheLumpedBeamModel) {
  const GeneratedBeamModel g = MakeBeamModelFromGeometry(kCrank);
  System sys;
  BeamPartPlacement placement;
  placement.p_WP = Eigen::Vector3d(0.1, -0.2, 0.3);
  placement.R_WP = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  const BeamPart info = AddBeamPart(&sys, "crank", g, placement);
  // An interface marker added by name, with axes in the part frame.
  const Eigen::Matrix3d R_PM = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const int bearing = AddInterfaceMarker(&sys, info, "bearing_3", "main_journal_3", R_PM);
  sys.Finalize();
  for (int k = 1; k <= 5; ++k)
    EXPECT_NO_THROW(sys.FindMarker("crank.main_journal_" + std::to_string(k)));
  for (int k = 1; k <= 4; ++k)
    EXPECT_NO_THROW(sys.FindMarker("crank.crankpin_" + std::to_string(k)));
  EXPECT_NO_THROW(sys.FindMarker("crank.nose"));
  EXPECT_NO_THROW(sys.FindMarker("crank.flange"));
  EXPECT_EQ(info.interfaces.size(), g.interfaces.size());
  // Every interface marker is at its node (the 3-D interface point) in the placed part frame:
  // the node is the surface's centroid to OpenCASCADE's accuracy (beam_geometry_test.cpp), the
  // axes are the part's to the round-off of a few products of rotations.
  constexpr double kCentroidTolerance = 1e-9;  // [m]
  constexpr double kAxesRoundOff = 1e-14;
  const Eigen::VectorXd q0 = sys.InitialPositions(), v0 = sys.InitialVelocities();
  const auto bodies0 = CalcBodyKinematics(sys, q0, v0);
  for (const BeamInterface& itf : g.interfaces) {
    const MarkerKinematics m =
        CalcMarkerKinematics(sys, bodies0, sys.FindMarker("crank." + itf.name));
    const Eigen::Vector3d expected = placement.p_WP + placement.R_WP * itf.centroid_W;
    EXPECT_LT((m.p_WM - expected).norm(), kCentroidTolerance) << itf.name;
    EXPECT_LT((m.R_WM - placement.R_WP).norm(), kAxesRoundOff) << itf.name;
  }
  const MarkerKinematics b3 = CalcMarkerKinematics(sys, bodies0, bearing);
  const MarkerKinematics j3 =
      CalcMarkerKinematics(sys, bodies0, sys.FindMarker("crank.main_journal_3"));
  EXPECT_EQ(b3.p_WM, j3.p_WM);  // the same body point, computed alike
  EXPECT_LT((b3.R_WM - placement.R_WP * R_PM).norm(), kAxesRoundOff);
  try {
    info.FindInterface("main_jornal_3");
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'main_journal_3'"), std::string::npos)
        << e.what();
  }

  EXPECT_EQ(static_cast<int>(info.bodies.size()), g.model.num_nodes());
  EXPECT_EQ(static_cast<int>(info.forces.size()), g.model.num_elements());
  const BeamSystem fe = AssembleBeamSystem(g.model, BeamMassType::kLumped);
  const BeamModes modes = CalcBeamModes(fe);
  ASSERT_TRUE(modes.ok()) << modes.message;

  const Linearised lin = Linearise(sys, info);
  // Sums of the same numbers in another order.
  constexpr double kRoundOff = 1e-12;
  EXPECT_NEAR(lin.mass, CalcBeamModelMassProperties(g.model).mass, kRoundOff * lin.mass);
  // Same pencil up to a congruence (node motion ↔ body CM motion, part pose): the elastic
  // frequencies agree to the round-off of two dense solves of a stiff pencil.
  constexpr double kSamePencil = 1e-7;
  ExpectLowestElasticFrequencies(lin, modes, kSamePencil);
}

// The condensed crank (the inline-4 scene's: elastic webs of the calibrated width) as a
// multibody part: one body per kept node, one link per chain, the same mass, and its
// linearisation has the plain lumped beam FE model's lowest frequencies (the condensed nodes'
// relative inertia is all it leaves out: tests/beam/beam_condensation_test.cpp).
TEST(BeamPart, CondensedCrankshaftKeepsTheLowFrequencies) {
  BeamGenerationOptions o;
  o.webs = WebModel::kElastic;
  o.web_width = 0.17;
  const GeneratedBeamModel g = MakeBeamModelFromGeometry(kCrank, o);
  EXPECT_EQ(DefaultBeamPartNodes(g), BeamPartNodes::kCondensed);
  System sys;
  BeamPartPlacement placement;
  placement.p_WP = Eigen::Vector3d(0.05, 0.1, -0.2);
  placement.R_WP = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  const BeamPart info = AddBeamPart(&sys, "crank", g, placement, BeamPartNodes::kCondensed);
  sys.Finalize();
  EXPECT_EQ(info.nodes, BeamPartNodes::kCondensed);
  EXPECT_EQ(info.num_model_nodes, g.model.num_nodes());
  EXPECT_EQ(info.bodies.size(), 19u);  // 8 webs, 5 journals, 4 pins, nose, flange
  EXPECT_EQ(info.forces.size(), 18u);  // a chain
  EXPECT_NO_THROW(sys.FindBody("crank/crankpin_2"));
  EXPECT_NE(std::find(info.forces.begin(), info.forces.end(), "crank/web_2_front~crankpin_2"),
            info.forces.end());

  const Linearised lin = Linearise(sys, info);
  constexpr double kRoundOff = 1e-12;
  EXPECT_NEAR(lin.mass, CalcBeamModelMassProperties(g.model).mass, kRoundOff * lin.mass);
  BeamModalOptions mo;
  mo.num_modes = 14;
  const BeamModes modes = CalcBeamModes(AssembleBeamSystem(g.model, BeamMassType::kLumped), mo);
  ASSERT_TRUE(modes.ok()) << modes.message;
  // Measured 0.035 % at most over these eight (to 1.33 kHz).
  constexpr double kCondensationTolerance = 1e-3;
  ExpectLowestElasticFrequencies(lin, modes, kCondensationTolerance);
  // The highest frequency left: the condensed part's top is far below the plain one's.
  const double top = lin.frequencies_hz.maxCoeff();
  std::printf("condensed crank: %zu bodies, highest frequency %.3g Hz\n", info.bodies.size(), top);
}

}  // namespace
}  // namespace emb::mbs
