// The beam model and its assembly: rigid parts' 6×6 mass against the kinetic energy of a
// rigid motion, elements with rigid end offsets (rigid motions of the nodes stay free of
// strain; the offset element equals a plain one between the offset points carried rigidly),
// springs and damping in the assembled matrices, and every bad input named.

#include "libemb/beam/beam_model.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "libemb/beam/beam_assembly.h"
#include "libemb/common/error.h"
#include "tests/support/beam_models.h"

namespace emb {
namespace {

// Assembly sums a few products per entry: round-off relative to the largest entry.
constexpr double kRoundOff = 1e-12;

BeamElement Element(const std::string& name, int a, int b) {
  BeamElement e;
  e.name = name;
  e.node_a = a;
  e.node_b = b;
  e.section = MakeSolidCircleSection(0.05, 0.3);
  return e;
}

using test::InputErrorMessage;

TEST(BeamModel, RigidPartMassGivesTheKineticEnergyOfTheBody) {
  BeamModel model("body");
  model.AddNode("n", Eigen::Vector3d(0.3, -0.1, 0.2));
  RigidPart p{"web", 0, 2.5};
  p.p_NC_W = Eigen::Vector3d(0.01, -0.04, 0.02);
  p.I_C_W << 4e-3, 2e-4, -1e-4, 2e-4, 3e-3, 5e-4, -1e-4, 5e-4, 2e-3;
  model.AddRigidPart(p);
  const Matrix6d M = model.RigidPartMass(0);
  // T = ½ m |v + ω × c|² + ½ ωᵀ I_C ω for a node velocity v and angular velocity ω.
  const Eigen::Vector3d v(0.3, -1.2, 0.7), w(2.0, -0.5, 1.5);
  Vector6d q;
  q << v, w;
  const double T = 0.5 * p.mass * (v + w.cross(p.p_NC_W)).squaredNorm() + 0.5 * w.dot(p.I_C_W * w);
  EXPECT_NEAR(0.5 * q.dot(M * q), T, kRoundOff * T);
  EXPECT_LE((M - M.transpose()).cwiseAbs().maxCoeff(), kRoundOff * M.cwiseAbs().maxCoeff());
}

TEST(BeamModel, OffsetElementEqualsAPlainElementCarriedRigidly) {
  // An element hung on two nodes through offsets vs the same element between the offset
  // points: K_offset = Eᵀ K_plain E with E the rigid transfers, and rigid node motions strain
  // nothing.
  const Eigen::Vector3d pa(0, 0, 0), pb(0.1, 0, 0), oa(0.01, 0.02, 0.04), ob(-0.01, 0.02, 0.04);
  BeamModel hung("hung");
  hung.AddNode("a", pa);
  hung.AddNode("b", pb);
  BeamElement e = Element("pin", 0, 1);
  e.offset_a_W = oa;
  e.offset_b_W = ob;
  hung.AddElement(e);
  BeamModel plain("plain");
  plain.AddNode("a", pa + oa);
  plain.AddNode("b", pb + ob);
  plain.AddElement(Element("pin", 0, 1));

  Matrix12d E = Matrix12d::Zero();
  E.topLeftCorner<6, 6>() = CalcRigidTransfer(oa);
  E.bottomRightCorner<6, 6>() = CalcRigidTransfer(ob);
  for (BeamMassType type : {BeamMassType::kConsistent, BeamMassType::kLumped}) {
    const BeamSystem h = AssembleBeamSystem(hung, type), p = AssembleBeamSystem(plain, type);
    const Eigen::MatrixXd K = E.transpose() * p.K * E, M = E.transpose() * p.M * E;
    EXPECT_LE((h.K - K).cwiseAbs().maxCoeff(), kRoundOff * K.cwiseAbs().maxCoeff()) << Name(type);
    EXPECT_LE((h.M - M).cwiseAbs().maxCoeff(), kRoundOff * M.cwiseAbs().maxCoeff()) << Name(type);
    EXPECT_LE((h.K * CalcRigidBodyModes(hung)).cwiseAbs().maxCoeff(),
              kRoundOff * h.K.cwiseAbs().maxCoeff());
    // The rigid-body mass is that of the prism between the offset points.
    const MassProperties mp = CalcRigidBodyMassProperties(hung, h.M);
    const MassProperties exact = CalcBeamModelMassProperties(hung);
    EXPECT_NEAR(mp.mass, exact.mass, kRoundOff * exact.mass);
    EXPECT_LE((mp.center_of_mass - 0.5 * (pa + oa + pb + ob)).norm(), 1e-12);
    if (type == BeamMassType::kConsistent) {
      EXPECT_LE((mp.inertia_about_com - exact.inertia_about_com).cwiseAbs().maxCoeff(),
                kRoundOff * exact.inertia_about_com.cwiseAbs().maxCoeff());
    }
  }
}

TEST(BeamModel, SpringsSupportsAndDampingInTheSystem) {
  const double beta = StiffnessDampingForRatio(0.02, 500.0);  // ζ = 2 % at 500 Hz
  EXPECT_NEAR(beta, 2 * 0.02 / (2 * std::numbers::pi * 500.0), 1e-18);
  BeamModel model("sprung", beta);
  model.AddNode("a", Eigen::Vector3d::Zero());
  model.AddNode("b", Eigen::Vector3d(0.2, 0, 0));
  model.AddElement(Element("shaft", 0, 1));
  PointSpring k{"bearing", 1};
  k.stiffness << 0, 1e8, 2e8, 0, 0, 0;
  model.AddSpring(k);
  model.AddSupport({"thrust", 0, {true, false, false, true, false, false}});
  const BeamSystem sys = AssembleBeamSystem(model, BeamMassType::kConsistent);
  BeamModel bare("bare", beta);
  bare.AddNode("a", Eigen::Vector3d::Zero());
  bare.AddNode("b", Eigen::Vector3d(0.2, 0, 0));
  bare.AddElement(Element("shaft", 0, 1));
  const BeamSystem ref = AssembleBeamSystem(bare, BeamMassType::kConsistent);
  Eigen::MatrixXd springs = Eigen::MatrixXd::Zero(12, 12);
  springs(BeamModel::Dof(1, kUy), BeamModel::Dof(1, kUy)) = 1e8;
  springs(BeamModel::Dof(1, kUz), BeamModel::Dof(1, kUz)) = 2e8;
  EXPECT_LE((sys.K - ref.K - springs).cwiseAbs().maxCoeff(), kRoundOff * ref.K.cwiseAbs().maxCoeff());
  // Damping is β times the elements' stiffness, not the bearings'.
  EXPECT_LE((sys.D - beta * ref.K).cwiseAbs().maxCoeff(), kRoundOff * beta * ref.K.cwiseAbs().maxCoeff());
  EXPECT_EQ(sys.stiffness_damping, beta);
  EXPECT_EQ(sys.fixed_dofs, (std::vector<int>{BeamModel::Dof(0, kUx), BeamModel::Dof(0, kThetaX)}));
  EXPECT_EQ(sys.free_dofs.size(), 10u);
  EXPECT_EQ(sys.mass_type, BeamMassType::kConsistent);
  EXPECT_STREQ(Name(BeamMassType::kLumped), "lumped");
}

TEST(BeamModel, BadInputIsNamed) {
  BeamModel model("bad");
  model.AddNode("a", Eigen::Vector3d::Zero());
  model.AddNode("b", Eigen::Vector3d::Zero());
  model.AddNode("c", Eigen::Vector3d(0.1, 0, 0));
  std::string m = InputErrorMessage([&] { model.AddNode("a", Eigen::Vector3d(1, 0, 0)); });
  EXPECT_NE(m.find("node 'a' is defined twice"), std::string::npos) << m;

  // Zero-length segment.
  m = InputErrorMessage([&] { model.AddElement(Element("stub", 0, 1)); });
  EXPECT_NE(m.find("beam element 'stub' between nodes 'a' and 'b': length: expected > 0 m, got 0"),
            std::string::npos)
      << m;
  // Offsets that bring the elastic ends together are a zero length too.
  BeamElement folded = Element("folded", 0, 2);
  folded.offset_b_W = Eigen::Vector3d(-0.1, 0, 0);
  m = InputErrorMessage([&] { model.AddElement(folded); });
  EXPECT_NE(m.find("beam element 'folded'"), std::string::npos) << m;

  // Non-positive section properties and material.
  BeamElement e = Element("shaft", 0, 2);
  e.section.second_moment_y = -1e-9;
  m = InputErrorMessage([&] { model.AddElement(e); });
  EXPECT_NE(m.find("beam element 'shaft': section second moment Iy: expected > 0 m^4, got -1e-09"),
            std::string::npos)
      << m;
  e = Element("shaft", 0, 2);
  e.section.area = 0.0;
  m = InputErrorMessage([&] { model.AddElement(e); });
  EXPECT_NE(m.find("section area A: expected > 0 m^2, got 0"), std::string::npos) << m;
  e = Element("shaft", 0, 2);
  e.material.youngs_modulus = -1.0;
  EXPECT_THROW(model.AddElement(e), InputError);
  e = Element("shaft", 0, 7);
  m = InputErrorMessage([&] { model.AddElement(e); });
  EXPECT_NE(m.find("beam element 'shaft' end b: node index: expected 0..2, got 7"),
            std::string::npos)
      << m;
  EXPECT_EQ(model.num_elements(), 0);  // nothing half-added

  RigidPart p{"web", 0, 0.0};
  m = InputErrorMessage([&] { model.AddRigidPart(p); });
  EXPECT_NE(m.find("rigid part 'web': mass: expected > 0 kg, got 0"), std::string::npos) << m;
  p.mass = 1.0;
  p.I_C_W = Eigen::Vector3d(1e-3, -1e-3, 1e-3).asDiagonal();
  m = InputErrorMessage([&] { model.AddRigidPart(p); });
  EXPECT_NE(m.find("expected positive semi-definite"), std::string::npos) << m;
  PointSpring k{"bearing", 0};
  k.stiffness[kUy] = -1.0;
  EXPECT_THROW(model.AddSpring(k), InputError);
  m = InputErrorMessage([&] { model.AddSupport({"nothing", 0, {}}); });
  EXPECT_NE(m.find("support 'nothing': expected at least one fixed unknown"), std::string::npos) << m;
  m = InputErrorMessage([&] { model.FindNode("z"); });
  EXPECT_NE(m.find("has no node 'z'; expected one of: a, b, c"), std::string::npos) << m;
  EXPECT_THROW(BeamModel("negative damping", -0.1), InputError);
  EXPECT_THROW(StiffnessDampingForRatio(0.01, 0.0), InputError);
}

}  // namespace
}  // namespace emb
