// A scene part with `model: beam`: the crankshaft's geometry expands into node bodies and
// beam force elements whose linearisation is the lumped beam FE model of the same geometry
// (same mass, same free-free frequencies), with markers at the 3-D model's interfaces.

#include "libemb/scene/beam_part.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_modal.h"
#include "libemb/common/error.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/kinematics.h"
#include "libemb/scene/scene.h"
#include "libemb/mbs/forces/force_jacobian.h"

namespace emb::scene {
namespace {

const std::string kCrank = std::string(EMB_SOURCE_DIR) + "/meshes/crankshaft_i4.geo";

TEST(BeamPart, CrankshaftIsTheLumpedBeamModel) {
  mbs::System sys;
  BeamPartSpec spec;
  spec.name = "crank";
  spec.geometry = kCrank;
  spec.position = Eigen::Vector3d(0.1, -0.2, 0.3);
  spec.orientation = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  const BeamPartInfo info = AddBeamPart(spec, &sys);
  sys.Finalize();
  for (int k = 1; k <= 5; ++k)
    EXPECT_NO_THROW(sys.FindMarker("crank.main_journal_" + std::to_string(k)));
  for (int k = 1; k <= 4; ++k) EXPECT_NO_THROW(sys.FindMarker("crank.crankpin_" + std::to_string(k)));
  EXPECT_NO_THROW(sys.FindMarker("crank.nose"));
  EXPECT_NO_THROW(sys.FindMarker("crank.flange"));

  const GeneratedBeamModel g = MakeBeamModelFromGeometry(kCrank);
  EXPECT_EQ(static_cast<int>(info.bodies.size()), g.model.num_nodes());
  EXPECT_EQ(static_cast<int>(info.forces.size()), g.model.num_elements());
  const BeamSystem fe = AssembleBeamSystem(g.model, BeamMassType::kLumped);
  const BeamModes modes = CalcBeamModes(fe);
  ASSERT_TRUE(modes.ok()) << modes.message;

  const Eigen::VectorXd q = sys.InitialPositions(), v = sys.InitialVelocities();
  const auto bodies = mbs::CalcBodyKinematics(sys, q, v);
  mbs::DenseForceJacobian jac(sys.layout());
  for (const auto& f : sys.force_elements()) f->AddForceJacobian({&sys, &bodies, 0.0}, &jac);
  const Eigen::MatrixXd K = -jac.stiffness(), M = mbs::CalcMassMatrix(sys, bodies);
  // Total mass: the translational block of every body.
  double mass = 0.0;
  for (int b = 1; b <= static_cast<int>(info.bodies.size()); ++b)
    mass += M(sys.layout().velocity(b), sys.layout().velocity(b));
  // Sums of the same numbers in another order.
  constexpr double kRoundOff = 1e-12;
  EXPECT_NEAR(mass, CalcBeamModelMassProperties(g.model).mass, kRoundOff * mass);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (K + K.transpose()), M);
  ASSERT_EQ(es.info(), Eigen::Success);
  // Same pencil up to a congruence (node motion ↔ body CM motion, part pose): the elastic
  // frequencies agree to the round-off of two dense solves of a stiff pencil.
  constexpr double kSamePencil = 1e-7;
  constexpr int kRigidModes = 6, kCompared = 8;
  for (int i = kRigidModes; i < kRigidModes + kCompared; ++i) {
    const double f = std::sqrt(es.eigenvalues()[i]) / (2 * std::numbers::pi);
    EXPECT_NEAR(f, modes.frequencies_hz[i], kSamePencil * modes.frequencies_hz[i]) << "mode " << i + 1;
  }
}

TEST(BeamPart, SceneKeyModelBeam) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "emb_beam_part_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "scene.yaml").string();
  std::ofstream(path) << "bodies:\n"
                         "  - name: crank\n"
                         "    model: beam\n"
                         "    geometry: " << kCrank << "\n"
                         "    webs: elastic\n"
                         "    stiffness_damping: 1.0e-5\n";
  const Scene s = LoadScene(path);
  EXPECT_NO_THROW(s.system.FindMarker("crank.main_journal_3"));
  EXPECT_NO_THROW(s.system.FindBody("crank/web_1_front:pin"));
  std::ofstream(path) << "bodies:\n"
                         "  - name: crank\n"
                         "    model: beam\n"
                         "    geometry: " << kCrank << "\n"
                         "    webs: flexible\n";
  try {
    LoadScene(path);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("webs: expected rigid or elastic"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace emb::scene
