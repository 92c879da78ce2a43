// Standard free-vibration benchmarks that need supports other than a clamp (issue 16):
//  - NAFEMS FV5, deep simply-supported beam (NAFEMS R0015 "Selected benchmarks for natural
//    frequency analysis", 1987; The Standard NAFEMS Benchmarks TNSB Rev. 3, 1990): 10 m × 2 m
//    × 2 m, E = 200 GPa, ν = 0.3, ρ = 8000 kg/m³; end A: x, y, z and the twist held, end B:
//    y, z held. Targets (Timoshenko beam): flexural 42.649 Hz (pair), extensional 125.00 Hz,
//    flexural 148.31 Hz (pair). The torsional targets of R0015 (77.542, 233.10 Hz) take the
//    polar moment for the torsion constant; a solid warps freely, so its reference is
//    Saint-Venant's, f = (2k−1)/(4L) √(G J/(ρ I_p)) with J of the square (71.20 Hz, as the
//    FV5 sheet of caesarsystems.co.uk/NAFEMS_benchmarks lists).
//    As a solid, "simply supported" is an RBE3 reference node on each end face with those
//    components held; a point support (one node per end) is not mesh-converged: the solid
//    under a point force is infinitely soft, so each refinement lowers the frequencies.
//  - NAFEMS FV52, simply-supported solid square plate (R0015): 10 m × 10 m × 1 m, same
//    material, u_z = 0 along the four edges of the bottom face; three rigid modes (in-plane),
//    then 45.897, 109.44 (pair), 167.89, 193.59, 206.19 (pair) Hz.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "libemb/cms/supports.h"
#include "libemb/fe/assembly.h"
#include "libemb/fe/modal_analysis.h"
#include "libemb/mesh/box_mesh.h"
#include "tests/support/supported_modes.h"

namespace emb {
namespace {

const IsotropicMaterial kNafemsSteel{200e9, 0.3, 8000.0};
constexpr double kBeamL = 10.0, kBeamA = 2.0;  // FV5 length, square side [m]

// The node at point p (a mesh node there must exist).
std::size_t NodeTagAt(const Mesh& mesh, const Eigen::Vector3d& p) {
  for (int a = 0; a < mesh.num_nodes(); ++a)
    if ((mesh.nodes.col(a) - p).norm() < 1e-9) return mesh.node_tags[a];
  ADD_FAILURE() << "no node at " << p.transpose();
  return 0;
}

ModalResult Solve(const Mesh& mesh, const SupportSpecs& specs, int num_modes,
                  Supports* out = nullptr) {
  return test::SupportedModes(mesh, specs, kNafemsSteel, num_modes, out);
}

Mesh BeamMesh(int n) { return MakeBoxMesh({kBeamL, kBeamA, kBeamA}, {5 * n, n, n}, CellType::kHex20); }

// FV5 with RBE3 end supports: A holds x, y, z, rx; B holds y, z. Solved once per mesh.
ModalResult Fv5Distributed(int n) {
  static std::map<int, ModalResult> solved;
  if (const auto it = solved.find(n); it != solved.end()) return it->second;
  SupportSpecs s;
  s.reference.push_back(ReferenceSupport::Parse("x0:x,y,z,rx", Coupling::kRbe3));
  s.reference.push_back(ReferenceSupport::Parse("x1:y,z", Coupling::kRbe3));
  Supports sup;
  const ModalResult r = Solve(BeamMesh(n), s, 9, &sup);
  EXPECT_EQ(sup.expected_rigid_modes, 0);
  return solved[n] = r;
}

// FV5 with point supports: the centre node of each end face (x, y, z at A; y, z at B), as
// single-term equations. The twist about the line through both points is free: one rigid mode.
ModalResult Fv5Points(int n) {
  const Mesh mesh = BeamMesh(n);
  const std::size_t a = NodeTagAt(mesh, {0, 1, 1}), b = NodeTagAt(mesh, {kBeamL, 1, 1});
  SupportSpecs s;
  for (const auto& [tag, c] : {std::pair{a, "x"}, {a, "y"}, {a, "z"}, {b, "y"}, {b, "z"}})
    s.equations.push_back(NodeEquation::Parse("1 " + std::to_string(tag) + " " + c, "point"));
  Supports sup;
  const ModalResult r = Solve(mesh, s, 4, &sup);
  EXPECT_EQ(sup.expected_rigid_modes, 1);
  EXPECT_EQ(r.num_rigid_modes, 1);
  return r;
}

// Saint-Venant torsion constant of an a × a square, J = (a⁴/3)(1 − (192/π⁵) Σ_{k odd}
// tanh(kπ/2)/k⁵) [m⁴].
double SquareTorsionConstant(double a) {
  double sum = 0.0;
  for (int k = 1; k < 40; k += 2) sum += std::tanh(k * std::numbers::pi / 2) / std::pow(k, 5);
  return std::pow(a, 4) / 3.0 * (1.0 - 192.0 / std::pow(std::numbers::pi, 5) * sum);
}

// The 3-D solid against the targets at L/a = 5 on Hex20 20 × 4 × 4 (measured: flexural
// −0.07 %, −0.27 %, −0.62 % for the three pairs; torsion −1.0 %, −1.0 %): the section's
// in-plane deformation and free warping that beam theory leaves out. 1.5 % bounds them; an
// RBE2 at the ends (it clamps warping) or a lost component would not pass.
constexpr double kFv5BeamTheoryTol = 0.015;
// The extensional mode converges at O(h) (measured 111.39, 118.50, 121.86 Hz for n = 1, 2, 4,
// differences halving): the RBE3 average spreads its reaction by equal shares of face area over
// a Quad8's 8 nodes, not as a consistent traction, a mesh-scale self-equilibrated load whose
// error decays like h. Richardson's extrapolation of the three (measured 125.3 Hz) is checked
// against the target at 1 %.
constexpr double kFv5ExtrapolatedTol = 0.01;

TEST(NafemsFv5, DeepBeamOnDistributedSupportsMatchesTheTargets) {
  const ModalResult r1 = Fv5Distributed(1), r2 = Fv5Distributed(2), r = Fv5Distributed(4);
  ASSERT_EQ(r.num_rigid_modes, 0);
  const Eigen::VectorXd& f = r.frequencies_hz;
  const double G = kNafemsSteel.mu(), rho = kNafemsSteel.density;
  const double Ip = std::pow(kBeamA, 4) / 6.0;
  const double f_torsion = std::sqrt(G * SquareTorsionConstant(kBeamA) / (rho * Ip)) / (4 * kBeamL);
  EXPECT_NEAR(f_torsion, 71.20, 0.01);  // the closed form as listed for FV5
  // Order: flexural pair, torsion, extension, flexural pair, torsion, flexural pair.
  for (int k : {0, 1}) EXPECT_NEAR(f[k] / 42.649, 1.0, kFv5BeamTheoryTol) << k;
  EXPECT_NEAR(f[2] / f_torsion, 1.0, kFv5BeamTheoryTol);
  for (int k : {4, 5}) EXPECT_NEAR(f[k] / 148.31, 1.0, kFv5BeamTheoryTol) << k;
  EXPECT_NEAR(f[6] / (3 * f_torsion), 1.0, kFv5BeamTheoryTol);
  for (int k : {7, 8}) EXPECT_NEAR(f[k] / 284.55, 1.0, kFv5BeamTheoryTol) << k;
  const double e1 = r1.frequencies_hz[3], e2 = r2.frequencies_hz[3], e4 = f[3];
  EXPECT_LT(e1, e2);
  EXPECT_LT(e2, e4);
  const double extrapolated = e4 + (e4 - e2) * (e4 - e2) / ((e2 - e1) - (e4 - e2));
  EXPECT_NEAR(extrapolated / 125.00, 1.0, kFv5ExtrapolatedTol);
  // The exact symmetry of the square section: the flexural pairs are degenerate.
  EXPECT_NEAR(f[1] / f[0], 1.0, 1e-8);
  EXPECT_NEAR(f[5] / f[4], 1.0, 1e-8);
}

// Mesh convergence of the first frequency, n = 2 → 4 (one cross-section element per metre →
// two): with distributed supports the change is the discretisation error of a smooth solution
// (measured +0.05 %, 42.595 → 42.618 Hz); with point supports the support itself softens with
// every refinement (measured −5.3 %, 40.677 → 38.524 Hz, and 34.770 Hz at n = 8 in
// benchmarks/). The distributed change must stay under kConvergedChange, the point one be
// at least kPointSofteningFactor times larger.
constexpr double kConvergedChange = 0.002;
constexpr double kPointSofteningFactor = 10.0;

TEST(NafemsFv5, DistributedSupportsConvergeWherePointSupportsDoNot) {
  const double d2 = Fv5Distributed(2).frequencies_hz[0], d4 = Fv5Distributed(4).frequencies_hz[0];
  const double p2 = Fv5Points(2).frequencies_hz[1], p4 = Fv5Points(4).frequencies_hz[1];
  const double change_distributed = std::abs(d4 / d2 - 1.0);
  const double change_point = std::abs(p4 / p2 - 1.0);
  RecordProperty("distributed_n2", std::to_string(d2));
  RecordProperty("distributed_n4", std::to_string(d4));
  RecordProperty("point_n2", std::to_string(p2));
  RecordProperty("point_n4", std::to_string(p4));
  std::printf("FV5 f1: RBE3 %.4f -> %.4f Hz, point %.4f -> %.4f Hz\n", d2, d4, p2, p4);
  EXPECT_LT(change_distributed, kConvergedChange);
  EXPECT_GT(change_point, kPointSofteningFactor * change_distributed);
  EXPECT_LT(p4, p2);  // softer with refinement
}

SupportSpecs Fv52Supports(bool whole_side_faces) {
  SupportSpecs s;
  // R0015: u_z = 0 along the bottom edges (a line support). The 3-D elasticity form of a
  // simple support (Srinivas' exact solution): u_z and the tangential u held on the side faces.
  for (const char* t : whole_side_faces
                           ? std::vector<const char*>{"x0:y,z", "x1:y,z", "y0:x,z", "y1:x,z"}
                           : std::vector<const char*>{"z0&x0:z", "z0&x1:z", "z0&y0:z", "z0&y1:z"})
    s.fixed.push_back(ComponentSupport::Parse(t));
  return s;
}

Mesh PlateMesh(int n) { return MakeBoxMesh({10.0, 10.0, 1.0}, {4 * n, 4 * n, n}, CellType::kHex20); }

// On R0015's own Hex20 mesh (4 × 4 × 1) with its edge supports, the frequencies over the
// targets that OptiStruct publishes for this test (Altair OS-V 0455, four digits): 0.9760,
// 1.0101, 1.0072, 1.0017, 1.0022. The same discrete problem must give the same ratios, to
// their rounding (5e-5) plus the eigen-solver's accuracy.
constexpr double kPublishedRatioTol = 1e-4;

TEST(NafemsFv52, EdgeSupportedPlateOnTheBenchmarkMeshEqualsThePublishedHex20Results) {
  Supports sup;
  const ModalResult r = Solve(PlateMesh(1), Fv52Supports(false), 10, &sup);
  EXPECT_EQ(sup.expected_rigid_modes, 3);  // in-plane translations and the turn about z
  ASSERT_EQ(r.num_rigid_modes, 3);
  const Eigen::VectorXd& f = r.frequencies_hz;
  EXPECT_NEAR(f[3] / 45.897, 0.9760, kPublishedRatioTol);
  EXPECT_NEAR(f[4] / 109.44, 1.0101, kPublishedRatioTol);
  EXPECT_NEAR(f[5] / 109.44, 1.0101, kPublishedRatioTol);
  EXPECT_NEAR(f[6] / 167.89, 1.0072, kPublishedRatioTol);
  EXPECT_NEAR(f[7] / 193.59, 1.0017, kPublishedRatioTol);
  EXPECT_NEAR(f[8] / 206.19, 1.0022, kPublishedRatioTol);
  EXPECT_NEAR(f[9] / 206.19, 1.0022, kPublishedRatioTol);
}

// The line support is a singularity: refined (n = 1 → 2) its first frequency falls by 2.4 %
// (measured 44.796 → 43.716 Hz, and 43.241 at n = 4), away from the target. Held over the side
// faces the plate converges to it: measured 46.349, 45.997, 45.973 Hz (target 45.897: the
// remaining +0.17 % is 3-D elasticity against thick-plate theory). Checked: the face-supported
// plate within 1 % of the targets it shares with the edge-supported one at n = 2 (measured
// +0.22 %, +0.63 %, +0.80 %, +0.57 %), and changing from n = 2 to 4 at least ten times less
// than the line-supported plate (measured 0.05 % against 1.1 %).
constexpr double kFv52FaceTol = 0.01;

TEST(NafemsFv52, FaceSupportedPlateConvergesWhereTheLineSupportDoesNot) {
  const ModalResult f2 = Solve(PlateMesh(2), Fv52Supports(true), 10);
  const ModalResult f4 = Solve(PlateMesh(4), Fv52Supports(true), 1);
  const ModalResult e2 = Solve(PlateMesh(2), Fv52Supports(false), 4);
  const ModalResult e4 = Solve(PlateMesh(4), Fv52Supports(false), 4);
  ASSERT_EQ(f2.num_rigid_modes, 0);
  const Eigen::VectorXd& f = f2.frequencies_hz;
  // Nearest mode to each bending target (the face support adds in-plane modes between them).
  for (double target : {45.897, 109.44, 167.89, 206.19}) {
    double nearest = 0.0;
    for (int k = 0; k < f.size(); ++k)
      if (std::abs(f[k] - target) < std::abs(nearest - target)) nearest = f[k];
    EXPECT_NEAR(nearest / target, 1.0, kFv52FaceTol) << target;
  }
  const double face_change = std::abs(f4.frequencies_hz[0] / f2.frequencies_hz[0] - 1.0);
  const double edge_change = std::abs(e4.frequencies_hz[3] / e2.frequencies_hz[3] - 1.0);
  EXPECT_GT(edge_change, 10.0 * face_change);
  EXPECT_LT(e4.frequencies_hz[3], e2.frequencies_hz[3]);
}

}  // namespace
}  // namespace emb
