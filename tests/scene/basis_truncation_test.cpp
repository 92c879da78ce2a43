// The truncation error indicator (issue 12, mbs/analysis/basis_truncation.h): a root-clamped
// cantilever from a body file with root and tip interfaces (14 elastic modes), loaded at its
// tip. Keeping the lowest 8 free-free modes loses the static completeness at the interfaces
// and silently stiffens the clamped beam; the indicator must flag it (and the run warn,
// naming the part and the fix), and must not flag the full basis. Cross-check that the flag
// means something: the static tip deflection of the truncated basis is off, that of the full
// basis is Euler-Bernoulli's F L^3 / (3 E I).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/scene/scene.h"
#include "tests/support/flexible_bar.h"

namespace emb {
namespace {

constexpr double kTipForce = 100.0;  // [N] along z

struct Outcome {
  mbs::PreparedRun run;
  double tip_deflection{0.0};  // static, along z [m]
};

// `modes_key`: e.g. ", modes: 8", or "" for all.
Outcome ClampedBar(const std::string& modes_key) {
  testing::BarSpec bar;  // 0.6 x 0.04 x 0.03 m steel, Hex20 12 x 1 x 1
  bar.interfaces = {"x0:rbe2", "x1:rbe3"};
  bar.modes = 8;  // fixed-interface modes: 8 + 12 - 6 = 14 elastic modes in the body file
  std::ostringstream yaml;
  yaml << "bodies:\n  - {name: bar, model: cms, body_file: " << testing::FlexibleBarFile(bar)
       << modes_key << "}\n"
       << "markers:\n"
       << "  - {name: root, body: bar, interface: x0}\n"
       << "  - {name: tip, body: bar, interface: x1}\n"
       << "  - {name: base, body: ground, frame: world, position: [0, 0.02, 0.015]}\n"
       << "joints:\n  - {name: clamp, type: fixed, i: root, j: base}\n"
       << "forces:\n  - {name: load, type: force, marker: tip, direction: [0, 0, 1], "
          "function: {constant: "
       << kTipForce << "}}\n"
       << "sensors:\n  - {name: tip_in_base, i: tip, j: base}\n";
  scene::Scene sc = scene::ParseScene(yaml.str(), "clamped_bar.yaml");
  mbs::AnalysisSettings settings = sc.analysis;
  settings.type = mbs::AnalysisType::kStatic;
  Outcome out;
  out.run = mbs::PrepareRun(sc.system, settings);
  mbs::Sample last;
  const mbs::RunResult r =
      mbs::RunAnalysis(out.run, settings, [&](const mbs::Sample& s) { last = s; });
  EXPECT_TRUE(r.ok()) << r.message;
  out.tip_deflection = last.sensors(0, 2);
  return out;
}

bool Warned(const mbs::PreparedRun& run) {
  for (const auto& w : run.warnings)
    if (w.find("part 'bar'") != std::string::npos &&
        w.find("basis: installed") != std::string::npos &&
        w.find("Keep more modes") != std::string::npos)
      return true;
  return false;
}

TEST(BasisTruncation, FlagsTheTruncatedFreeFreeBasisOfAClampedBeam) {
  const Outcome full = ClampedBar("");
  const Outcome truncated = ClampedBar(", modes: 8");
  ASSERT_EQ(full.run.truncations.size(), 1u);
  ASSERT_EQ(truncated.run.truncations.size(), 1u);
  const mbs::TruncationReport& f = full.run.truncations[0];
  const mbs::TruncationReport& t = truncated.run.truncations[0];
  EXPECT_EQ(f.num_kept, 14);
  EXPECT_EQ(t.num_kept, 8);
  EXPECT_EQ(t.num_available, 14);
  // Both markers carry loads: the clamp (forces and moments) and the tip force.
  EXPECT_EQ(t.loaded_markers.size(), 2u);
  RecordProperty("full_error", ::testing::PrintToString(f.static_compliance_error));
  RecordProperty("truncated_error", ::testing::PrintToString(t.static_compliance_error));

  // The full basis has the same compliance by construction: round-off of the solves
  // (condition of diag(lambda) ~ 1e6 here, times 1e-16).
  constexpr double kRoundOff = 1e-8;
  EXPECT_LT(f.static_compliance_error, kRoundOff);
  EXPECT_FALSE(Warned(full.run));
  // The truncated one is flagged above the default threshold, with a warning.
  EXPECT_GT(t.static_compliance_error, mbs::AnalysisSettings{}.truncation_warning_threshold);
  EXPECT_TRUE(Warned(truncated.run));

  // Cross-check: the full basis (static completeness at both interfaces) gives the clamped
  // tip deflection of beam theory, F L^3 / (3 E I), within the coarse solid's and the
  // shear's share (L/h = 20; measured within 1 %); the truncated one is far stiffer.
  const double I = 0.04 * std::pow(0.03, 3) / 12.0;
  const double beam = kTipForce * std::pow(0.6, 3) / (3.0 * 210e9 * I);
  constexpr double kBeamTolerance = 0.03;
  EXPECT_NEAR(full.tip_deflection / beam, 1.0, kBeamTolerance);
  RecordProperty("tip_ratio_truncated", ::testing::PrintToString(truncated.tip_deflection / beam));
  // What the indicator warns about is real: more than the threshold off in the response.
  EXPECT_LT(truncated.tip_deflection / full.tip_deflection,
            1.0 - mbs::AnalysisSettings{}.truncation_warning_threshold);
}

}  // namespace
}  // namespace emb
