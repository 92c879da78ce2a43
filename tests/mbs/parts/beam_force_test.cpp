// The beam force element (seed eq. 1.26 between two markers): a cantilever of N beam forces
// between rigid node bodies carrying the lumped beam masses is the lumped beam FE model of
// libemb/beam — the same static tip deflection and, linearised at rest, the same natural
// frequencies — and its analytic force Jacobian matches central differences at a deformed,
// moving state.

#include "libemb/mbs/parts/beam_force.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <memory>
#include <numbers>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_modal.h"
#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/forces/applied_load.h"
#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/dynamics.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mbs/forces/force_jacobian.h"

namespace emb::mbs {
namespace {

constexpr double kLength = 0.6;     // cantilever [m]
constexpr double kDiameter = 0.03;  // solid circle [m]
constexpr int kElements = 8;
constexpr double kTipLoad = 10.0;   // [N], along −y: tip deflection ~1.4e-4 of the length
constexpr double kBeta = 1e-4;      // stiffness damping [s]

BeamElementProperties ElementProperties() {
  const IsotropicMaterial steel;
  return MakeBeamElementProperties(kLength / kElements,
                                   MakeSolidCircleSection(kDiameter, steel.poisson_ratio), steel,
                                   /*shear_deformable=*/true, "cantilever element");
}

// The lumped beam FE cantilever, clamped at node 0.
BeamSystem BeamFeCantilever() {
  const IsotropicMaterial steel;
  BeamModel model("cantilever", kBeta);
  for (int k = 0; k <= kElements; ++k)
    model.AddNode("n" + std::to_string(k), Eigen::Vector3d(kLength * k / kElements, 0, 0));
  for (int k = 0; k < kElements; ++k) {
    BeamElement e;
    e.name = "e" + std::to_string(k + 1);
    e.node_a = k;
    e.node_b = k + 1;
    e.section = MakeSolidCircleSection(kDiameter, steel.poisson_ratio);
    e.material = steel;
    model.AddElement(e);
  }
  Support clamp;
  clamp.name = "clamp";
  clamp.node = 0;
  clamp.fixed.fill(true);
  model.AddSupport(clamp);
  return AssembleBeamSystem(model, BeamMassType::kLumped);
}

// The same as node bodies and beam forces; marker "n0" on the ground is the clamp.
System MbsCantilever(bool tip_load) {
  const BeamElementProperties p = ElementProperties();
  const Vector12d lumped = CalcBeamLumpedMass(p);  // half an element per end, diagonal
  System s;
  s.AddMarker("n0", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  for (int k = 1; k <= kElements; ++k) {
    const double halves = k < kElements ? 2.0 : 1.0;  // the tip node has one element
    RigidBody b;
    b.name = "node_" + std::to_string(k);
    b.mass = halves * lumped[kUx];
    b.inertia_B = (halves * lumped.segment<3>(kThetaX)).asDiagonal();
    b.p_WB = Eigen::Vector3d(kLength * k / kElements, 0, 0);
    s.AddBody(b);
    s.AddMarker("n" + std::to_string(k), b.name, Eigen::Vector3d::Zero(),
                Eigen::Matrix3d::Identity());
  }
  for (int k = 1; k <= kElements; ++k)
    s.AddForceElement(std::make_shared<BeamForce>(
        "beam_" + std::to_string(k), s.FindMarker("n" + std::to_string(k - 1)),
        s.FindMarker("n" + std::to_string(k)), p, kBeta));
  if (tip_load)
    s.AddForceElement(std::make_shared<AppliedLoad>(
        "tip", AppliedLoad::Kind::kForce, s.FindMarker("n" + std::to_string(kElements)),
        Eigen::Vector3d(0, -1, 0), AppliedLoad::Frame::kWorld, TimeFunction::Constant(kTipLoad)));
  s.Finalize();
  return s;
}

TEST(BeamForce, CantileverStaticTipDeflectionIsTheBeamFe) {
  const System s = MbsCantilever(/*tip_load=*/true);
  AnalysisSettings st;
  st.type = AnalysisType::kStatic;
  // The axial stiffness EA/h ≈ 2e9 N/m times the round-off of absolute positions (ε · 0.6 m)
  // leaves ~3e-7 N of force noise per element: the default 1e-9 is below that floor.
  st.static_force_tolerance = 1e-6;
  Sample out;
  const RunResult r = RunAnalysis(PrepareRun(s, st), st, [&](const Sample& smp) { out = smp; });
  ASSERT_TRUE(r.ok()) << r.message;
  const int tip = s.FindBody("node_" + std::to_string(kElements));
  const double tip_y = CalcBodyKinematics(s, out.q, {})[tip].p_WB.y();

  const BeamSystem fe = BeamFeCantilever();
  const int n = static_cast<int>(fe.free_dofs.size());
  Eigen::MatrixXd K(n, n);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) K(a, b) = fe.K(fe.free_dofs[a], fe.free_dofs[b]);
    if (fe.free_dofs[a] == BeamModel::Dof(kElements, kUy)) f[a] = -kTipLoad;
  }
  const Eigen::VectorXd u = K.ldlt().solve(f);
  double fe_tip = 0.0;
  for (int a = 0; a < n; ++a)
    if (fe.free_dofs[a] == BeamModel::Dof(kElements, kUy)) fe_tip = u[a];
  // Timoshenko cantilever under an end load: the element is exact, P L³/3EI + P L/κGA.
  const BeamElementProperties p = ElementProperties();
  const double closed = -kTipLoad * std::pow(kLength, 3) /
                            (3 * p.youngs_modulus * p.section.second_moment_z) -
                        kTipLoad * kLength /
                            (p.section.shear_coefficient * p.shear_modulus * p.section.area);
  // The FE element is exact for end loads: round-off of a dense solve.
  constexpr double kExact = 1e-9;
  EXPECT_NEAR(fe_tip, closed, kExact * std::abs(closed));
  // The multibody model is geometrically exact: it differs from linear theory by
  // O((δ/L)²) ~ 2e-8 relative at this load.
  constexpr double kGeometricNonlinearity = 1e-6;
  EXPECT_NEAR(tip_y, fe_tip, kGeometricNonlinearity * std::abs(fe_tip));
}

TEST(BeamForce, CantileverFrequenciesAreTheLumpedBeamFe) {
  const System s = MbsCantilever(/*tip_load=*/false);
  const Eigen::VectorXd q = s.InitialPositions(), v = s.InitialVelocities();
  const auto bodies = CalcBodyKinematics(s, q, v);
  DenseForceJacobian jac(s.layout());
  for (const auto& fe : s.force_elements()) fe->AddForceJacobian({&s, &bodies, 0.0}, &jac);
  const Eigen::MatrixXd K = -jac.stiffness(), M = CalcMassMatrix(s, bodies);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (K + K.transpose()), M);
  ASSERT_EQ(es.info(), Eigen::Success);
  const BeamModes fe = CalcBeamModes(BeamFeCantilever());
  ASSERT_TRUE(fe.ok()) << fe.message;
  ASSERT_EQ(fe.frequencies_hz.size(), es.eigenvalues().size());
  // The element linearised at rest is K_e = Bᵀ K_bb B (beam_force.h): the same pencil,
  // round-off of two dense eigen-solves.
  constexpr double kSamePencil = 1e-8;
  constexpr int kCompared = 8;  // two bending pairs, torsion, axial and more
  for (int i = 0; i < kCompared; ++i) {
    const double f_mbs = std::sqrt(es.eigenvalues()[i]) / (2 * std::numbers::pi);
    EXPECT_NEAR(f_mbs, fe.frequencies_hz[i], kSamePencil * fe.frequencies_hz[i]) << "mode " << i + 1;
  }
  // Damping D = β K: the damping Jacobian is β times the stiffness one at rest.
  EXPECT_LE((jac.damping() - kBeta * jac.stiffness()).cwiseAbs().maxCoeff(),
            1e-12 * jac.stiffness().cwiseAbs().maxCoeff());
}

TEST(BeamForce, JacobianMatchesCentralDifferences) {
  // Two free bodies, deformed, turned and moving: every term of the Jacobian is exercised.
  System s;
  RigidBody a, b;
  a.name = "a";
  a.mass = 1.0;
  a.inertia_B = Eigen::Vector3d(0.01, 0.02, 0.02).asDiagonal();
  a.R_WB = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  a.v_WB = Eigen::Vector3d(0.1, -0.2, 0.3);
  a.omega_W = Eigen::Vector3d(1.0, -2.0, 0.5);
  b = a;
  b.name = "b";
  b.p_WB = a.R_WB * Eigen::Vector3d(0.08, 0.003, -0.002) + Eigen::Vector3d(0.001, 0, 0);
  b.R_WB = a.R_WB * Eigen::AngleAxisd(0.05, Eigen::Vector3d(0.3, 1, -1).normalized()).toRotationMatrix();
  b.omega_W = Eigen::Vector3d(-0.5, 1.5, 2.0);
  s.AddBody(a);
  s.AddBody(b);
  s.AddMarker("end_a", "a", Eigen::Vector3d(0.01, 0.02, 0), Eigen::Matrix3d::Identity());
  s.AddMarker("end_b", "b", Eigen::Vector3d(0.01, 0.02, 0), Eigen::Matrix3d::Identity());
  BeamElementProperties p = ElementProperties();
  p.length = 0.08;
  s.AddForceElement(
      std::make_shared<BeamForce>("beam", s.FindMarker("end_a"), s.FindMarker("end_b"), p, 1e-3));
  s.Finalize();
  const StateLayout& L = s.layout();
  const Eigen::VectorXd q = s.InitialPositions(), v = s.InitialVelocities();
  const ForceElement& fe = *s.force_elements()[0];
  auto forces = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv) {
    const auto bodies = CalcBodyKinematics(s, qq, vv);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(L.nv());
    fe.AddForces({&s, &bodies, 0.0}, f);
    return f;
  };
  const auto bodies = CalcBodyKinematics(s, q, v);
  DenseForceJacobian analytic(L);
  fe.AddForceJacobian({&s, &bodies, 0.0}, &analytic);
  const double h = 1e-6;
  Eigen::MatrixXd K(L.nv(), L.nv()), D(L.nv(), L.nv());
  for (int j = 0; j < L.nv(); ++j) {
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(L.nv());
    dx[j] = h;
    K.col(j) = (forces(ApplyDisplacement(s, q, dx), v) - forces(ApplyDisplacement(s, q, -dx), v)) /
               (2 * h);
    D.col(j) = (forces(q, v + dx) - forces(q, v - dx)) / (2 * h);
  }
  // Central differences at h = 1e-6: truncation ~1e-12, cancellation ~eps/h ~ 2e-10 of the
  // largest entry; 1e-7 as in force_element_test.
  constexpr double kDerivativeTolerance = 1e-7;
  const double scale = std::max({1.0, K.cwiseAbs().maxCoeff(), D.cwiseAbs().maxCoeff()});
  EXPECT_LT((analytic.stiffness() - K).cwiseAbs().maxCoeff(), kDerivativeTolerance * scale);
  EXPECT_LT((analytic.damping() - D).cwiseAbs().maxCoeff(), kDerivativeTolerance * scale);
}

TEST(BeamForce, BadPropertiesAreNamed) {
  BeamElementProperties p = ElementProperties();
  p.length = 0.0;
  try {
    BeamForce("shaft", 0, 1, p, 0.0);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("beam force 'shaft': length"), std::string::npos)
        << e.what();
  }
  p = ElementProperties();
  p.section.area = -1.0;
  EXPECT_THROW(BeamForce("shaft", 0, 1, p, 0.0), InputError);
  EXPECT_THROW(BeamForce("shaft", 0, 1, ElementProperties(), -1.0), InputError);
}

}  // namespace
}  // namespace emb::mbs
