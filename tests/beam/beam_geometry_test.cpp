// Beam models generated from the geometry files of the 3-D models: the inline-4 crankshaft
// (journals, necks and pins as beams, webs as rigid parts hung on the pins through offsets)
// and the driveshaft tube (a chain of tube beams). Their mass and inertia against the meshed
// 3-D solid (within its meshing error), the consistent mass carrying exactly the geometry's
// rigid-body inertia, the full TMM against the lumped FE on the generated crankshaft, the tube
// against Timoshenko theory, and bad geometry named.

#include "libemb/beam/beam_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "libemb/beam/beam_assembly.h"
#include "libemb/beam/beam_modal.h"
#include "libemb/beam/tmm_solver.h"
#include "libemb/common/error.h"
#include "tests/support/beam_models.h"
#include "libemb/fe/mass_properties.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tests/support/temp_dir.h"
#include "tests/support/timoshenko_beam.h"

namespace emb {
namespace {

const std::string kCrank = std::string(EMB_SOURCE_DIR) + "/meshes/crankshaft_i4.geo";
const std::string kTube = std::string(EMB_SOURCE_DIR) + "/meshes/tube.geo";

// Sums of exact integrals rearranged (parallel-axis shifts, section fits): round-off only.
constexpr double kRoundOff = 1e-10;

struct Errors {
  double mass, com, inertia;  // relative; CM relative to the part's length
};

Errors Compare(const MassProperties& a, const MassProperties& ref, double length) {
  return {std::abs(a.mass - ref.mass) / ref.mass,
          (a.center_of_mass - ref.center_of_mass).norm() / length,
          (a.inertia_about_com - ref.inertia_about_com).cwiseAbs().maxCoeff() /
              ref.inertia_about_com.cwiseAbs().maxCoeff()};
}

void Print(const char* what, const Errors& e) {
  std::printf("%s: mass %.2e, centre of mass %.2e (of length), inertia %.2e\n", what, e.mass,
              e.com, e.inertia);
}

// The generated beams against the meshed 3-D solid of the same geometry.
void ExpectMatches3D(const MassProperties& beams, const std::string& geo,
                     const MeshingOptions& mo, double length, double tol, const char* what) {
  const MassProperties solid = CalcMassProperties(ReadMesh(geo, mo), IsotropicMaterial{}.density);
  const Errors e = Compare(beams, solid, length);
  Print(what, e);
  EXPECT_LE(e.mass, tol) << what;
  EXPECT_LE(e.com, tol) << what;
  EXPECT_LE(e.inertia, tol) << what;
}

TEST(BeamGeometry, CrankshaftHasTheMassAndInertiaOfThe3DModel) {
  const GeneratedBeamModel g = MakeBeamModelFromGeometry(kCrank);
  const BeamModel& m = g.model;
  // 1 nose, 5 journals, 8 necks, 4 pins, 1 flange; 8 webs.
  int segments = 0, rigid = 0;
  for (const GeometryPart& p : g.parts) (p.kind == GeometryPart::Kind::kSegment ? segments : rigid)++;
  EXPECT_EQ(segments, 19);
  EXPECT_EQ(rigid, 8);
  for (const char* node : {"main_journal_1", "main_journal_5", "crankpin_1", "crankpin_4",
                           "web_1_front", "web_4_rear", "nose:start", "flange:end"})
    EXPECT_NO_THROW(m.FindNode(node)) << node;
  // Journal centres and pins where the .geo puts them: xj = 52 + 90(k−1) mm; pin 1 at z = r.
  EXPECT_NEAR(m.nodes()[m.FindNode("main_journal_3")].p_W.x(), 0.232, 1e-9);
  const Eigen::Vector3d pin1 = m.nodes()[m.FindNode("crankpin_1")].p_W;
  EXPECT_LE((pin1 - Eigen::Vector3d(0.097, 0.0, 0.043)).norm(), 1e-9);
  EXPECT_LE((m.nodes()[m.FindNode("crankpin_2")].p_W - Eigen::Vector3d(0.187, 0.0, -0.043)).norm(),
            1e-9);
  for (const GeometryPart& p : g.parts)
    if (p.name.rfind("main_journal", 0) == 0) {
      EXPECT_NEAR(p.section.outer_diameter, 0.055, 1e-9) << p.name;
      EXPECT_EQ(p.section.inner_diameter, 0.0) << p.name;
    }

  // The beams and rigid parts are the geometry's parts exactly.
  const MassProperties beams = CalcBeamModelMassProperties(m);
  const Errors exact = Compare(beams, g.geometry, 0.439);
  EXPECT_LE(exact.mass, kRoundOff);
  EXPECT_LE(exact.com, kRoundOff);
  EXPECT_LE(exact.inertia, kRoundOff);
  // The documented default: volume 1.9249e-3 m³, 15.1 kg, centre (0.2388, 0, 0) m.
  EXPECT_NEAR(g.geometry.volume, 1.9249e-3, 1e-7);
  EXPECT_NEAR(g.geometry.center_of_mass.x(), 0.2388, 1e-4);

  // The consistent mass matrix carries that rigid-body inertia exactly; the lumped one the
  // mass exactly and the inertia to O(h²).
  const Errors consistent = Compare(
      CalcRigidBodyMassProperties(m, AssembleBeamSystem(m, BeamMassType::kConsistent).M),
      beams, 0.439);
  EXPECT_LE(consistent.mass, kRoundOff);
  EXPECT_LE(consistent.com, kRoundOff);
  EXPECT_LE(consistent.inertia, kRoundOff);
  const Errors lumped = Compare(
      CalcRigidBodyMassProperties(m, AssembleBeamSystem(m, BeamMassType::kLumped).M), beams,
      0.439);
  Print("crankshaft beam (lumped M) vs exact geometry", lumped);
  EXPECT_LE(lumped.mass, kRoundOff);
  // Seen: 4.7e-4 — point masses at nodes ≤ 12 mm apart on a 0.44 m shaft.
  EXPECT_LE(lumped.inertia, 2e-3);

  // Against the meshed 3-D solid (coarse curved Tet10, h = 20 mm): meshing error only. Curved
  // Tet10 faces approximate the cylinders and web arcs (seen: mass 3.3e-5, inertia 3.7e-5,
  // centre 5.8e-7 of the length).
  MeshingOptions mo;
  mo.size = 0.02;
  ExpectMatches3D(beams, kCrank, mo, 0.439, 2e-4, "crankshaft beam vs 3-D Tet10 mesh (h = 20 mm)");
}

TEST(BeamGeometry, CrankshaftTmmEqualsLumpedFe) {
  const GeneratedBeamModel g = MakeBeamModelFromGeometry(kCrank);
  TmmOptions o;
  o.max_hz = 4000.0;
  const TmmResult r = CalcTmmModes(g.model, o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.num_zero_frequency_modes, 6);
  const BeamModes fe =
      CalcBeamModes(AssembleBeamSystem(g.model, BeamMassType::kLumped), BeamModalOptions{});
  ASSERT_TRUE(fe.ok()) << fe.message;
  ASSERT_GE(r.modes.size(), 4u);
  double worst = 0.0;
  for (const TmmMode& mode : r.modes) {
    const double f_fe = fe.frequencies_hz[mode.index - 1];
    worst = std::max(worst, std::abs(mode.frequency_hz - f_fe) / f_fe);
  }
  const BeamModes consistent =
      CalcBeamModes(AssembleBeamSystem(g.model, BeamMassType::kConsistent), BeamModalOptions{});
  std::printf("generated crankshaft (%d nodes): %zu TMM modes up to %.0f Hz, max |TMM - FE|/FE = "
              "%.2e; free-free f7..f10 [Hz] lumped %.1f %.1f %.1f %.1f, consistent %.1f %.1f "
              "%.1f %.1f\n",
              g.model.num_nodes(), r.modes.size(), o.max_hz, worst, fe.frequencies_hz[6],
              fe.frequencies_hz[7], fe.frequencies_hz[8], fe.frequencies_hz[9],
              consistent.frequencies_hz[6], consistent.frequencies_hz[7],
              consistent.frequencies_hz[8], consistent.frequencies_hz[9]);
  // As in tmm_solver_test: the same equations, round-off apart.
  EXPECT_LE(worst, 1e-9);
}

TEST(BeamGeometry, TubeIsAChainOfTubeBeams) {
  const GeneratedBeamModel g = MakeBeamModelFromGeometry(kTube);
  ASSERT_EQ(g.parts.size(), 1u);
  const GeometryPart& tube = g.parts[0];
  // Fitted from the exact integrals: Ø90 × 2 mm, L = 1.5 m.
  EXPECT_NEAR(tube.section.outer_diameter, 0.09, 1e-9);
  EXPECT_NEAR(tube.section.inner_diameter, 0.086, 1e-9);
  EXPECT_NEAR(tube.length, 1.5, 1e-9);
  EXPECT_EQ(tube.elements.size(), 76u);  // ⌈1.5 / 0.02⌉ = 75, made even
  EXPECT_NO_THROW(g.model.FindNode("tube"));

  const MassProperties beams = CalcBeamModelMassProperties(g.model);
  // The default swept Hex20 mesh: quadratic faces on 32 arcs per circumference (seen: mass
  // and inertia 3.1e-6).
  ExpectMatches3D(beams, kTube, MeshingOptions{}, 1.5, 1e-4, "tube beam vs 3-D Hex20 mesh");

  // First free-free bending pair against Timoshenko theory (Cowper κ for the tube).
  const BeamModes m =
      CalcBeamModes(AssembleBeamSystem(g.model, BeamMassType::kConsistent), BeamModalOptions{});
  ASSERT_TRUE(m.ok()) << m.message;
  EXPECT_EQ(m.num_rigid_modes, 6);
  const BeamSection& s = tube.section;
  const IsotropicMaterial steel;
  const test::BeamSection ts{steel.youngs_modulus, steel.mu(), steel.density, s.area,
                             s.second_moment_z, s.shear_coefficient};
  const double f_ref = test::Hz(
      test::TimoshenkoFrequencies(ts, 1.5, test::BeamEnd::kFree, test::BeamEnd::kFree, 1).at(0));
  std::printf("tube beam: first bending pair %.4f / %.4f Hz, Timoshenko %.4f Hz\n",
              m.frequencies_hz[6], m.frequencies_hz[7], f_ref);
  // 76 elements, h² convergence of the Timoshenko consistent mass (beam_modal_test); seen 7e-6.
  EXPECT_NEAR(m.frequencies_hz[6], f_ref, 1e-4 * f_ref);
  EXPECT_NEAR(m.frequencies_hz[7], f_ref, 1e-4 * f_ref);
}

// Writes a small OpenCASCADE .geo next to the test binary.
std::string WriteGeo(const std::string& name, const std::string& body) {
  static const testing::ScopedTempDir dir("emb_beam_geometry");
  const std::string path = dir.File(name);
  std::ofstream(path) << "SetFactory(\"OpenCASCADE\");\n" << body;
  return path;
}

using test::InputErrorMessage;

TEST(BeamGeometry, BadGeometryIsNamed) {
  // No beam groups: the solid-only geometry of the single-cylinder crank.
  std::string m = InputErrorMessage([] {
    MakeBeamModelFromGeometry(std::string(EMB_SOURCE_DIR) + "/meshes/crankshaft_1cyl.geo");
  });
  EXPECT_NE(m.find("expected physical volumes named 'beam_segment_*'"), std::string::npos) << m;
  EXPECT_NE(m.find("'crankshaft'"), std::string::npos) << m;

  // A parameter the file does not have.
  BeamGenerationOptions o;
  o.parameters = {{"strok", 0.09}};
  m = InputErrorMessage([&] { MakeBeamModelFromGeometry(kCrank, o); });
  EXPECT_NE(m.find("has no parameter 'strok'"), std::string::npos) << m;

  // Two shafts with a gap between them.
  const std::string gap = WriteGeo("beam_gap.geo",
                                   "Cylinder(1) = {0, 0, 0, 0.1, 0, 0, 0.02};\n"
                                   "Cylinder(2) = {0.12, 0, 0, 0.1, 0, 0, 0.02};\n"
                                   "Physical Volume(\"beam_segment_a\") = {1};\n"
                                   "Physical Volume(\"beam_segment_b\") = {2};\n");
  m = InputErrorMessage([&] { MakeBeamModelFromGeometry(gap); });
  EXPECT_NE(m.find("parts 'a' and 'b' do not touch"), std::string::npos) << m;

  // A square bar is not a circular beam segment.
  const std::string box = WriteGeo("beam_box.geo",
                                   "Box(1) = {0, 0, 0, 0.2, 0.03, 0.02};\n"
                                   "Physical Volume(\"beam_segment_bar\") = {1};\n");
  m = InputErrorMessage([&] { MakeBeamModelFromGeometry(box); });
  EXPECT_NE(m.find("segment 'bar': expected a circular prism along x"), std::string::npos) << m;

  // The beam-parts geometry is not a solid to mesh.
  MeshingOptions mo;
  mo.parameters = {{"beam_parts", 1.0}};
  m = InputErrorMessage([&] { ReadMesh(kCrank, mo); });
  EXPECT_NE(m.find("beam_parts = 1 is for the beam generator"), std::string::npos) << m;
}

// The default damping of a generated model: ζ = 1 % at its first elastic free-free mode
// (β = 2ζ/ω₁), not the seed's literal β = 0.01 s; an explicit β is kept.
TEST(BeamGeometry, DefaultDampingIsOnePercentAtTheFirstMode) {
  const GeneratedBeamModel g = MakeBeamModelFromGeometry(kCrank);
  const BeamModes m = CalcBeamModes(AssembleBeamSystem(g.model, BeamMassType::kConsistent));
  ASSERT_TRUE(m.ok()) << m.message;
  const double w1 = 2 * M_PI * m.frequencies_hz[m.num_rigid_modes];
  EXPECT_NEAR(g.model.stiffness_damping() * w1 / 2, 0.01, kRoundOff);
  BeamGenerationOptions o;
  o.stiffness_damping = 2e-5;
  EXPECT_EQ(MakeBeamModelFromGeometry(kCrank, o).model.stiffness_damping(), 2e-5);
}

// Elastic webs: one arm per web from the crank axis to the pin axis, radial, with the
// web's thickness; the mass unchanged (the arm is nearly massless: its mass stays in the
// web's rigid part); softer than rigid webs; TMM still the lumped FE.
TEST(BeamGeometry, ElasticWebsAreRadialArms) {
  BeamGenerationOptions rigid_o, elastic_o;
  elastic_o.webs = WebModel::kElastic;
  const GeneratedBeamModel rigid = MakeBeamModelFromGeometry(kCrank, rigid_o);
  const GeneratedBeamModel elastic = MakeBeamModelFromGeometry(kCrank, elastic_o);
  constexpr int kWebs = 8;
  EXPECT_EQ(elastic.model.num_nodes(), rigid.model.num_nodes() + kWebs);
  EXPECT_EQ(elastic.model.num_elements(), rigid.model.num_elements() + kWebs);
  const int arm = [&] {
    for (int e = 0; e < elastic.model.num_elements(); ++e)
      if (elastic.model.elements()[e].name == "web_1_front#web") return e;
    return -1;
  }();
  ASSERT_GE(arm, 0);
  const auto [pa, pb] = elastic.model.ElasticEnds(arm);
  constexpr double kCrankRadius = 0.043;  // stroke / 2 of the default geometry [m]
  EXPECT_NEAR((pb - pa).norm(), kCrankRadius, kRoundOff);
  EXPECT_NEAR(pb.x() - pa.x(), 0.0, kRoundOff);  // radial: in the plane x = const
  constexpr double kWebThickness = 0.018, kWebWidth = 0.035 + 0.030;  // web_t, r_main + r_pin
  const BeamSection& s = elastic.model.elements()[arm].section;
  // t comes from the web's OpenCASCADE bounding box, padded by its tolerance (~1e-7 m).
  constexpr double kBoxPadding = 1e-4;
  EXPECT_NEAR(s.area, kWebThickness * kWebWidth, kBoxPadding * kWebThickness * kWebWidth);
  // The arm's mass: kWebArmDensityFraction of a real one, a relative 1e-6 of the total at most.
  const double m_rigid = CalcBeamModelMassProperties(rigid.model).mass;
  const double m_elastic = CalcBeamModelMassProperties(elastic.model).mass;
  EXPECT_NEAR(m_elastic, m_rigid, 1e-6 * m_rigid);
  const BeamModes fr = CalcBeamModes(AssembleBeamSystem(rigid.model, BeamMassType::kLumped));
  const BeamModes fe = CalcBeamModes(AssembleBeamSystem(elastic.model, BeamMassType::kLumped));
  ASSERT_TRUE(fr.ok() && fe.ok());
  constexpr int kFirstElastic = 6;
  EXPECT_LT(fe.frequencies_hz[kFirstElastic], fr.frequencies_hz[kFirstElastic]);
  TmmOptions o;
  o.max_hz = 1.2 * fe.frequencies_hz[kFirstElastic + 3];
  const TmmResult t = CalcTmmModes(elastic.model, o);
  ASSERT_TRUE(t.ok()) << t.message;
  for (const TmmMode& m : t.modes)
    EXPECT_NEAR(m.frequency_hz, fe.frequencies_hz[m.index - 1], 1e-9 * m.frequency_hz);
  BeamGenerationOptions bad = elastic_o;
  bad.web_width = -0.01;
  EXPECT_THROW(MakeBeamModelFromGeometry(kCrank, bad), InputError);
}

// The geometry's surface groups (the interfaces of the 3-D model) name beam nodes: each at the
// node nearest to the group's area centroid, which for these parts is the node itself (the
// centroid of a full cylindrical surface is on its axis at mid-length, that of an end face on
// the axis at the end).
TEST(BeamGeometry, SurfaceGroupsNameTheirInterfaceNodes) {
  // OpenCASCADE's surface integrals are exact to ~1e-12 of the part's size.
  constexpr double kCentroidTolerance = 1e-9;  // [m]
  auto expect = [&](const GeneratedBeamModel& g, const std::map<std::string, std::string>& want) {
    std::map<std::string, std::string> got;
    for (const BeamInterface& i : g.interfaces) {
      got[i.name] = g.model.nodes()[i.node].name;
      EXPECT_LT(i.offset_W.norm(), kCentroidTolerance) << i.name;
      EXPECT_LT((g.model.nodes()[i.node].p_W + i.offset_W - i.centroid_W).norm(), 1e-15) << i.name;
    }
    EXPECT_EQ(got, want);
  };
  std::map<std::string, std::string> crank{{"nose", "nose"}, {"flange", "flange:end"}};
  for (int k = 1; k <= 5; ++k) crank["main_journal_" + std::to_string(k)] = "main_journal_" + std::to_string(k);
  for (int i = 1; i <= 4; ++i) crank["crankpin_" + std::to_string(i)] = "crankpin_" + std::to_string(i);
  expect(MakeBeamModelFromGeometry(kCrank), crank);
  BeamGenerationOptions elastic;
  elastic.webs = WebModel::kElastic;
  expect(MakeBeamModelFromGeometry(kCrank, elastic), crank);
  expect(MakeBeamModelFromGeometry(kTube), {{"end_a", "tube:start"},
                                            {"end_b", "tube:end"},
                                            {"outer", "tube"},
                                            {"inner", "tube"}});
  // A geometry without surface groups has no interfaces.
  const std::string bare = WriteGeo("beam_bare.geo",
                                    "Cylinder(1) = {0, 0, 0, 0.1, 0, 0, 0.02};\n"
                                    "Physical Volume(\"beam_segment_a\") = {1};\n");
  EXPECT_TRUE(MakeBeamModelFromGeometry(bare).interfaces.empty());
}

}  // namespace
}  // namespace emb
