// The two-node beam element: the seed's end stiffness (eq 1.26), its closed-form inverse, the
// 12×12 stiffness against the textbook Euler–Bernoulli and Timoshenko matrices, the rigid-body
// invariants of stiffness and mass, the frame, and static cantilever deflections (exact for a
// tip load with any number of elements) for Euler–Bernoulli and Timoshenko.

#include "libemb/beam/beam_element.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_model.h"
#include "libemb/common/error.h"
#include "tests/support/beam_models.h"

namespace emb {
namespace {

constexpr double kPi = std::numbers::pi;
// Matrices built from closed forms with a handful of flops per entry: round-off only.
constexpr double kRoundOff = 1e-12;

const IsotropicMaterial kSteel{};  // E = 210 GPa, ν = 0.3, ρ = 7850 kg/m³

// A stubby tube, so that shear matters (Φ ≈ 0.4): L = 0.3 m, Ø120 × 80 mm.
BeamElementProperties Stubby(bool shear) {
  return MakeBeamElementProperties(0.3, MakeHollowCircleSection(0.12, 0.08, 0.3), kSteel, shear,
                                   "test element");
}

// A general section with Iy ≠ Iz, so that the two bending planes are told apart.
BeamElementProperties General(bool shear) {
  return MakeBeamElementProperties(0.25, MakeGeneralSection(2e-3, 3e-7, 8e-7, 5e-7, 0.8), kSteel,
                                   shear, "general element");
}

double RelDiff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(BeamElement, EndStiffnessIsSeedEquation126) {
  const BeamElementProperties p = General(false);
  const double L = p.length, E = p.youngs_modulus, G = p.shear_modulus;
  const double A = p.section.area, Iy = p.section.second_moment_y, Iz = p.section.second_moment_z,
               J = p.section.torsion_constant;
  // Eq (1.26) written out: q¹ = x (axial), I_{q²} = Iy, I_{q³} = Iz, I_{q¹} = J.
  Matrix6d seed;
  seed << E * A / L, 0, 0, 0, 0, 0,                                          //
      0, 12 * E * Iz / std::pow(L, 3), 0, 0, 0, -6 * E * Iz / (L * L),       //
      0, 0, 12 * E * Iy / std::pow(L, 3), 0, 6 * E * Iy / (L * L), 0,        //
      0, 0, 0, G * J / L, 0, 0,                                              //
      0, 0, 6 * E * Iy / (L * L), 0, 4 * E * Iy / L, 0,                      //
      0, -6 * E * Iz / (L * L), 0, 0, 0, 4 * E * Iz / L;
  EXPECT_LE(RelDiff(CalcBeamEndStiffness(p), seed), kRoundOff);
}

TEST(BeamElement, EndComplianceInvertsEndStiffness) {
  for (bool shear : {false, true}) {
    for (const BeamElementProperties& p : {Stubby(shear), General(shear)}) {
      const Matrix6d CK = CalcBeamEndCompliance(p) * CalcBeamEndStiffness(p);
      EXPECT_LE((CK - Matrix6d::Identity()).cwiseAbs().maxCoeff(), kRoundOff) << shear;
    }
  }
}

TEST(BeamElement, StiffnessMatchesTextbookMatrices) {
  // Przemieniecki's Timoshenko element (Φ = 0: the Euler–Bernoulli one), x–y plane entries
  // and their x–z counterparts (θ_y = −dw/dx flips the signs of the w–θ_y couplings).
  for (bool shear : {false, true}) {
    const BeamElementProperties p = General(shear);
    const double L = p.length, E = p.youngs_modulus;
    const double Iz = p.section.second_moment_z, Iy = p.section.second_moment_y;
    const double fz = p.shear_parameter_z(), fy = p.shear_parameter_y();
    if (shear) {
      EXPECT_GT(fz, 0.01);
    }
    const Matrix12d K = CalcBeamStiffness(p);
    const int a = 0, b = 6;
    const double kz = E * Iz / ((1 + fz) * L * L * L), ky = E * Iy / ((1 + fy) * L * L * L);
    const double tol = kRoundOff * K.cwiseAbs().maxCoeff();
    EXPECT_NEAR(K(a + kUy, a + kUy), 12 * kz, tol);
    EXPECT_NEAR(K(a + kUy, a + kThetaZ), 6 * kz * L, tol);
    EXPECT_NEAR(K(a + kUy, b + kUy), -12 * kz, tol);
    EXPECT_NEAR(K(a + kUy, b + kThetaZ), 6 * kz * L, tol);
    EXPECT_NEAR(K(a + kThetaZ, a + kThetaZ), (4 + fz) * kz * L * L, tol);
    EXPECT_NEAR(K(a + kThetaZ, b + kThetaZ), (2 - fz) * kz * L * L, tol);
    EXPECT_NEAR(K(a + kUz, a + kThetaY), -6 * ky * L, tol);
    EXPECT_NEAR(K(a + kUz, b + kThetaY), -6 * ky * L, tol);
    EXPECT_NEAR(K(a + kThetaY, b + kThetaY), (2 - fy) * ky * L * L, tol);
    EXPECT_NEAR(K(a + kUx, b + kUx), -E * p.section.area / L, tol);
    EXPECT_NEAR(K(a + kThetaX, b + kThetaX), -p.shear_modulus * p.section.torsion_constant / L,
                tol);
  }
}

// The rigid motions of an element from 0 to L x: columns Γ(p) for both ends.
Eigen::Matrix<double, 12, 6> RigidModes(double L) {
  Eigen::Matrix<double, 12, 6> R;
  R << CalcRigidTransfer(Eigen::Vector3d::Zero()), CalcRigidTransfer(Eigen::Vector3d(L, 0, 0));
  return R;
}

TEST(BeamElement, StiffnessIsSymmetricWithTheRigidMotionsAsNullSpace) {
  for (bool shear : {false, true}) {
    const BeamElementProperties p = Stubby(shear);
    const Matrix12d K = CalcBeamStiffness(p);
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_LE((K - K.transpose()).cwiseAbs().maxCoeff(), kRoundOff * scale);
    EXPECT_LE((K * RigidModes(p.length)).cwiseAbs().maxCoeff(), kRoundOff * scale);
    // Exactly six zero eigenvalues, the rest positive.
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Matrix12d>(K).eigenvalues();
    EXPECT_LE(ev.head<6>().cwiseAbs().maxCoeff(), kRoundOff * scale);
    EXPECT_GT(ev[6], 1e-6 * scale);
  }
}

TEST(BeamElement, MassesCarryTheExactRigidBodyInertiaOfThePrism) {
  for (bool shear : {false, true}) {
    const BeamElementProperties p = Stubby(shear);
    const double L = p.length, rho = p.density, A = p.section.area;
    const double m = rho * A * L;
    const Eigen::Matrix<double, 12, 6> R = RigidModes(L);
    const Matrix6d Mc = R.transpose() * CalcBeamConsistentMass(p) * R;
    // About end a: m, first moment m L/2 along x, I_x = ρIpL, I_y = ρIyL + mL²/3.
    EXPECT_NEAR(Mc(0, 0), m, kRoundOff * m);
    EXPECT_NEAR(Mc(3, 3), rho * p.section.polar_moment() * L, kRoundOff * Mc(3, 3));
    EXPECT_NEAR(Mc(4, 4), rho * p.section.second_moment_y * L + m * L * L / 3,
                kRoundOff * Mc(4, 4));
    EXPECT_NEAR(Mc(5, 5), rho * p.section.second_moment_z * L + m * L * L / 3,
                kRoundOff * Mc(5, 5));
    EXPECT_NEAR(Mc(2, 4), -m * L / 2, kRoundOff * m * L);  // u_z from ω_y: −x ω_y
    const Matrix12d Mcons = CalcBeamConsistentMass(p);
    EXPECT_LE((Mcons - Mcons.transpose()).cwiseAbs().maxCoeff(), kRoundOff * m);
    // Lumped: the total mass exactly, half at each end.
    const Vector12d ml = CalcBeamLumpedMass(p);
    EXPECT_NEAR(ml[kUx] + ml[6 + kUx], m, kRoundOff * m);
    EXPECT_GT(ml.minCoeff(), 0.0);
  }
}

TEST(BeamElement, FrameIsRightHandedAndFollowsTheReference) {
  const Eigen::Matrix3d R0 =
      CalcBeamFrame(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d::Zero(), "x");
  EXPECT_LE((R0 - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), kRoundOff);
  const Eigen::Matrix3d R = CalcBeamFrame(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(2, 4, 4),
                                          Eigen::Vector3d(0, 0, 1), "skew");
  EXPECT_LE((R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), kRoundOff);
  EXPECT_NEAR(R.determinant(), 1.0, kRoundOff);
  EXPECT_GT(R.col(1).dot(Eigen::Vector3d(0, 0, 1)), 0.0);  // y_B leans towards the reference
  EXPECT_THROW(CalcBeamFrame(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0),
                             Eigen::Vector3d(2, 2, 0), "parallel"),
               InputError);
}

// A cantilever of n elements along x, clamped at x = 0; the tip displacement under a tip
// load `f_tip` (6 components, W) from K u = f on the free unknowns.
Vector6d CantileverTip(const BeamSection& section, double L, int n, bool shear,
                       const Vector6d& f_tip) {
  const BeamModel model = test::MakeUniformShaft(L, section, n, shear, /*clamped=*/true);
  const BeamSystem sys = AssembleBeamSystem(model, BeamMassType::kConsistent);
  const int nf = static_cast<int>(sys.free_dofs.size());
  Eigen::MatrixXd K(nf, nf);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(nf);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < nf; ++j) K(i, j) = sys.K(sys.free_dofs[i], sys.free_dofs[j]);
  f.tail<6>() = f_tip;  // the tip node's unknowns are the last six
  const Eigen::VectorXd u = K.ldlt().solve(f);
  return u.tail<6>();
}

TEST(BeamElement, CantileverTipLoadIsExactForEulerBernoulliAndTimoshenko) {
  // Closed forms: δ = PL³/(3EI) + PL/(κGA), θ = PL²/(2EI); torsion TL/(GJ); axial PL/(EA).
  const double L = 0.8, P = 1e3, T = 50.0;  // [m], [N], [N·m]
  const BeamSection s = MakeSolidCircleSection(0.1, kSteel.poisson_ratio);  // L/d = 8
  const double E = kSteel.youngs_modulus, G = kSteel.mu(), I = s.second_moment_z;
  for (bool shear : {false, true}) {
    const double shear_term = shear ? P * L / (s.shear_coefficient * G * s.area) : 0.0;
    for (int n : {1, 3}) {
      Vector6d f = Vector6d::Zero();
      f[kUy] = P;
      f[kUz] = P;
      f[kThetaX] = T;
      f[kUx] = P;
      const Vector6d u = CantileverTip(s, L, n, shear, f);
      const double defl = P * L * L * L / (3 * E * I) + shear_term;
      SCOPED_TRACE(::testing::Message() << "shear " << shear << ", " << n << " elements");
      EXPECT_NEAR(u[kUy], defl, kRoundOff * defl * 100);
      EXPECT_NEAR(u[kUz], defl, kRoundOff * defl * 100);
      EXPECT_NEAR(u[kThetaZ], P * L * L / (2 * E * I), 1e-10 * P * L * L / (2 * E * I));
      EXPECT_NEAR(u[kThetaY], -P * L * L / (2 * E * I), 1e-10 * P * L * L / (2 * E * I));
      EXPECT_NEAR(u[kThetaX], T * L / (G * s.torsion_constant), 1e-10 * u[kThetaX]);
      EXPECT_NEAR(u[kUx], P * L / (E * s.area), 1e-10 * u[kUx]);
    }
  }
}

TEST(BeamElement, RejectsBadProperties) {
  const BeamSection s = MakeSolidCircleSection(0.05, 0.3);
  EXPECT_THROW(MakeBeamElementProperties(0.0, s, kSteel, true, "zero"), InputError);
  EXPECT_THROW(MakeBeamElementProperties(-1.0, s, kSteel, true, "negative"), InputError);
  EXPECT_THROW(MakeSolidCircleSection(0.0, 0.3), InputError);
  EXPECT_THROW(MakeHollowCircleSection(0.05, 0.05, 0.3), InputError);
  EXPECT_THROW(MakeGeneralSection(1e-3, -1e-7, 1e-7, 1e-7, 0.8), InputError);
  EXPECT_THROW(MakeGeneralSection(1e-3, 1e-7, 1e-7, 0.0, 0.8), InputError);
  EXPECT_THROW(MakeGeneralSection(1e-3, 1e-7, 1e-7, 1e-7, 1.5), InputError);
  try {
    MakeGeneralSection(0.0, 1e-7, 1e-7, 1e-7, 0.8);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("area A: expected > 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb
