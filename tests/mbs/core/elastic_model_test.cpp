// The floating-frame model of a flexible body (mbs/core/elastic_model.h), built from a reduced
// body by mbs/flexible/flexible_body.h, against a node-by-node evaluation on the body's own
// finite-element mesh: at random states (pose, velocities, modal coordinates and rates) the
// kinetic energy ½ Vᵀ M(η) V equals ½ ṙᵀ M_FE ṙ with ṙ the velocities of the mesh nodes from
// the rigid motion and the mesh mode shapes, the gravity potential equals −Σ g·(M_FE r) and
// the elastic energy ½ ηᵀ K η equals ½ (Φη)ᵀ K_FE (Φη). With the consistent mass these are
// the same bilinear forms summed in another order (the invariants are exact for the FE
// interpolation), so they agree to round-off; a lumped nodal mass would only converge.

#include "libemb/mbs/core/elastic_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "libemb/cms/geometric_stiffening.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "tests/support/flexible_bar.h"

namespace emb {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

TEST(ElasticModel, EnergiesEqualTheNodeByNodeSumsOnTheMesh) {
  testing::BarSpec bar;  // 0.6 x 0.04 x 0.03 m steel, Hex20
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 4;
  bar.keep_mesh_shapes = true;
  const ReducedBody& rb = testing::FlexibleBar(bar);
  const mbs::ElasticModel model = mbs::MakeElasticModel(rb, "bar");
  const int ne = model.num_modes();
  ASSERT_EQ(ne, 6 * 2 + bar.modes - 6);
  const Mesh mesh = bar.MakeMesh();
  const SystemMatrices fe = AssembleSystem(mesh, bar.Material());
  const int n = mesh.num_nodes();
  const Eigen::MatrixXd& Phi = rb.mesh_shapes;  // 3n x ne, node-major, mesh axes
  ASSERT_EQ(Phi.rows(), 3 * n);
  ASSERT_EQ(Phi.cols(), ne);
  const Vector3d c = rb.invariants.CenterOfMass();
  const Vector3d g(1.0, -2.0, -9.81);

  double worst_kinetic = 0.0, worst_gravity = 0.0, worst_elastic = 0.0;
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto random3 = [&](double scale) {
    return Vector3d(scale * u(rng), scale * u(rng), scale * u(rng));
  };
  for (int trial = 0; trial < 5; ++trial) {
    const Vector3d p_WB = random3(1.0), v_WB = random3(2.0), omega_B = random3(300.0);
    const Matrix3d R = mbs::RotationFromQuaternion(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)));
    // Deformations of a realistic size (modal coordinates in kg^0.5 m: ~mm at the tip) and
    // rates at the modes' own frequencies.
    VectorXd eta(ne), eta_dot(ne);
    for (int k = 0; k < ne; ++k) {
      eta[k] = 1e-3 * u(rng);
      eta_dot[k] = 1e-3 * u(rng) * 2 * M_PI * model.frequencies_hz[k];
    }
    // Node by node: u_i = x_i − c + Φ_i η, r_i = p + R u_i, ṙ_i = v + R (ω × u_i + Φ_i η̇).
    const VectorXd d = Phi * eta, d_dot = Phi * eta_dot;
    VectorXd r(3 * n), r_dot(3 * n), gs(3 * n);
    for (int i = 0; i < n; ++i) {
      const Vector3d ui = mesh.nodes.col(i) - c + d.segment<3>(3 * i);
      r.segment<3>(3 * i) = p_WB + R * ui;
      r_dot.segment<3>(3 * i) = v_WB + R * (omega_B.cross(ui) + d_dot.segment<3>(3 * i));
      gs.segment<3>(3 * i) = g;
    }
    // The model's kinetic energy also holds the centrifugal stiffening's
    // T_G = -1/2 eta^T K_G(omega) eta (elastic_model.h: the second-order foreshortening, which
    // the linear node positions here lack).
    const Eigen::Matrix<double, 6, 1> cp = CentrifugalProducts(omega_B);
    double T_G = 0.0;
    for (int p = 0; p < 6; ++p) T_G -= 0.5 * cp[p] * eta.dot(model.kg_centrifugal[p] * eta);
    ASSERT_TRUE(model.geometric_stiffening);
    const double T_fe = 0.5 * r_dot.dot(fe.M * r_dot) + T_G;
    const double V_gravity_fe = -gs.dot(fe.M * r);
    const double V_elastic_fe = 0.5 * d.dot(fe.K * d);

    const mbs::FlexibleTerms t = mbs::CalcFlexibleTerms(model, p_WB, R, v_WB, omega_B, eta, eta_dot,
                                                        g, Vector3d::Zero(), false);
    VectorXd V(6 + ne);
    V << v_WB, omega_B, eta_dot;
    const double T_model = 0.5 * V.dot(t.mass * V);
    worst_kinetic = std::max(worst_kinetic, std::abs(T_model - T_fe) / T_fe);
    worst_gravity =
        std::max(worst_gravity, std::abs(t.gravity_energy - V_gravity_fe) /
                                    (std::abs(V_gravity_fe) + rb.invariants.mass * g.norm()));
    worst_elastic =
        std::max(worst_elastic, std::abs(t.elastic_energy - V_elastic_fe) / V_elastic_fe);
    // The same sums of products of the consistent mass in another order: round-off relative
    // to the energy (measured 4e-15 kinetic, 3e-16 gravity over the trials).
    constexpr double kRoundOff = 1e-13;
    EXPECT_NEAR(T_model, T_fe, kRoundOff * T_fe) << "trial " << trial;
    EXPECT_NEAR(t.kinetic_energy, T_fe, kRoundOff * T_fe) << "trial " << trial;
    EXPECT_NEAR(t.gravity_energy, V_gravity_fe,
                kRoundOff * (std::abs(V_gravity_fe) + rb.invariants.mass * g.norm()))
        << "trial " << trial;
    // K̂ = Tᵀ K T and Φ = T X with XᵀK̂X = diag(ω²): exact up to the round-off of the
    // reduction and of the stiff K (measured 2e-13).
    constexpr double kStiffnessRoundOff = 1e-11;
    EXPECT_NEAR(t.elastic_energy, V_elastic_fe, kStiffnessRoundOff * V_elastic_fe)
        << "trial " << trial;
    // The test means something only if every part contributes: rigid translation and
    // rotation and the deformation rates are all of the same order in T.
    EXPECT_GT(0.5 * eta_dot.squaredNorm(), 1e-4 * T_fe) << "trial " << trial;
  }
  std::printf("largest relative differences: kinetic %.1e, gravity %.1e, elastic %.1e\n",
              worst_kinetic, worst_gravity, worst_elastic);
}

// The evaluation runs its inertia (Sbar) products over the leading dynamic coordinates only
// when the quasi-static ones trail; with them in front it takes the general path. Both must
// give the same terms, permuted: mass, forces, energies and every derivative.
TEST(ElasticModel, TrailingQuasiStaticCoordinatesGiveTheSameTermsAsAnyOrder) {
  testing::BarSpec bar;
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 4;
  bar.damping_ratio = 0.02;
  bar.stiffening_supports = {"x0"};
  mbs::ElasticModel trailing = mbs::MakeElasticModel(testing::FlexibleBar(bar), "bar");
  const int ne = trailing.num_modes();
  std::vector<bool> flags(ne, false);
  for (int j = 6; j < ne; ++j) flags[j] = true;  // the 4 highest modes quasi-static
  // The same model with the coordinates in reverse order: quasi-static ones first.
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(ne, ne);
  for (int j = 0; j < ne; ++j) P(ne - 1 - j, j) = 1.0;
  mbs::ElasticModel leading = trailing.Transformed(P);
  std::vector<bool> reversed(flags.rbegin(), flags.rend());
  trailing.MakeQuasiStatic(flags, "bar");
  leading.MakeQuasiStatic(reversed, "bar");
  ASSERT_EQ(trailing.num_leading_dynamic(), 6);
  ASSERT_EQ(leading.num_leading_dynamic(), ne);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  VectorXd eta(ne), eta_dot(ne), accel(6 + ne);
  for (int k = 0; k < ne; ++k) eta[k] = 1e-3 * u(rng), eta_dot[k] = u(rng);
  for (int k = 0; k < 6 + ne; ++k) accel[k] = 100.0 * u(rng);
  const Vector3d p(0.1, 0.2, 0.3), v(1, -2, 3), w(300, -200, 100), g(0, 0, -9.81),
      a_B(5.0, -4.0, 3.0);
  const Matrix3d R = mbs::RotationFromQuaternion(Eigen::Vector4d(0.3, -0.4, 0.5, 0.7));
  // Body coordinates [rigid 6, eta] of the trailing model from the leading one's: Q.
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(6 + ne, 6 + ne);
  Q.bottomRightCorner(ne, ne) = P;
  const VectorXd accel_l = Q.transpose() * accel;
  const mbs::FlexibleTerms a = mbs::CalcFlexibleTerms(trailing, p, R, v, w, eta, eta_dot, g, a_B,
                                                      true, &accel);
  const mbs::FlexibleTerms b = mbs::CalcFlexibleTerms(
      leading, p, R, v, w, P.transpose() * eta, P.transpose() * eta_dot, g, a_B, true, &accel_l);
  // The same products of the same numbers in another order (and skipped zeros).
  constexpr double kRoundOff = 1e-12;
  auto same = [&](const Eigen::MatrixXd& x, const Eigen::MatrixXd& y, const char* what) {
    EXPECT_LE((x - Q * y * Q.transpose()).norm(), kRoundOff * std::max(1.0, x.norm())) << what;
  };
  same(a.mass, b.mass, "mass");
  same(a.damping, b.damping, "damping");
  same(a.stiffness, b.stiffness, "stiffness");
  same(a.inertia_stiffness, b.inertia_stiffness, "inertia stiffness");
  same(a.force_accel, b.force_accel, "force_accel");
  EXPECT_LE((a.force - Q * b.force).norm(), kRoundOff * a.force.norm());
  EXPECT_NEAR(a.kinetic_energy, b.kinetic_energy, kRoundOff * a.kinetic_energy);
  // The test is not empty: the quasi-static block of the mass is zero, the dynamic one not.
  EXPECT_EQ(a.mass.bottomRightCorner(ne - 6, ne - 6).norm(), 0.0);
  EXPECT_GT(a.mass.block(6, 6, 6, 6).norm(), 0.5);
  EXPECT_GT(a.stiffness.bottomRightCorner(ne, ne).norm(), 1.0);
}

}  // namespace
}  // namespace emb
