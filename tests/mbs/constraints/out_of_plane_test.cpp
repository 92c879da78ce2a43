// Planar mechanisms: the redundant equations of a planar closed loop act only out of its
// plane, so `planar` drops them without a warning (and the run is the one remove_redundant
// gives); a redundant equation with an in-plane part is still an error, named.

#include "libemb/mbs/constraints/out_of_plane.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/constraints/dof_analysis.h"
#include "libemb/mbs/core/system.h"
#include "libemb/scene/scene.h"
#include "tests/support/test_models.h"

namespace emb::mbs {
namespace {

const std::string kFourBar = std::string(EMB_SOURCE_DIR) + "/tools/scenes/four_bar.yaml";

struct Assembled {
  DofReport dof;
  Eigen::VectorXd q;
};
Assembled Assemble(const System& sys, ConstraintWorkspace* ws) {
  const AssemblyResult a = AssemblePositions(sys, sys.InitialPositions(), 0.0, ws);
  EXPECT_TRUE(a.converged) << a.message;
  return {AnalyzeDof(sys, a.q, 0.0, ws), a.q};
}

std::vector<std::string> Names(const System& sys, const std::vector<int>& equations) {
  std::vector<std::string> n;
  for (int k : equations) n.push_back(sys.EquationName(k));
  return n;
}

TEST(OutOfPlane, FourBarRedundancyIsOutOfItsPlaneOnly) {
  const scene::Scene sc = scene::LoadScene(kFourBar);
  ConstraintWorkspace ws(sc.system);
  const Assembled a = Assemble(sc.system, &ws);
  ASSERT_EQ(a.dof.redundant.size(), 3u);  // Gruebler -2, true DOF 1
  EXPECT_TRUE(EquationsWithInPlaneTerms(sc.system, a.q, 0.0, a.dof.redundant,
                                        Eigen::Vector3d::UnitZ(), &ws)
                  .empty());
  // About another plane the same equations do act in it (z translation, tilts).
  EXPECT_FALSE(EquationsWithInPlaneTerms(sc.system, a.q, 0.0, a.dof.redundant,
                                         Eigen::Vector3d::UnitX(), &ws)
                   .empty());
}

TEST(OutOfPlane, RepeatedHingeHasInPlaneRepeats) {
  // A second revolute on the same hinge repeats all 5 equations; its at-point x and y act in
  // the xy-plane, the other three out of it.
  const System s = testing::RepeatedHinge(Eigen::Vector3d(0.3, 0.2, 0.0));
  ConstraintWorkspace ws(s);
  const Assembled a = Assemble(s, &ws);
  ASSERT_EQ(a.dof.redundant.size(), 5u);
  EXPECT_EQ(Names(s, EquationsWithInPlaneTerms(s, a.q, 0.0, a.dof.redundant,
                                               Eigen::Vector3d::UnitZ(), &ws)),
            (std::vector<std::string>{"revolute 'lower': at-point x",
                                      "revolute 'lower': at-point y"}));
  AnalysisSettings st;
  st.plane_normal = Eigen::Vector3d::UnitZ();
  try {
    PrepareRun(s, st);
    ADD_FAILURE() << "a repeated hinge passed as planar";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("revolute 'lower': at-point x"), std::string::npos)
        << e.what();
  }
}

TEST(OutOfPlane, PlanarRunIsTheRemoveRedundantRunWithoutWarnings) {
  const scene::Scene sc = scene::LoadScene(kFourBar);
  AnalysisSettings removing = sc.analysis;  // the scene says remove_redundant: true
  removing.t_end = 0.2;
  AnalysisSettings planar = removing;
  planar.remove_redundant = false;
  planar.plane_normal = Eigen::Vector3d::UnitZ();
  const PreparedRun a = PrepareRun(sc.system, removing);
  const PreparedRun b = PrepareRun(sc.system, planar);
  EXPECT_EQ(a.warnings.size(), 1u);  // "removed 3 redundant equation(s): ..."
  EXPECT_TRUE(b.warnings.empty());
  EXPECT_EQ(b.planar_removed.size(), 3u);
  EXPECT_EQ(b.system.removed_equations(), a.system.removed_equations());
  std::vector<Eigen::VectorXd> qa, qb;
  const RunResult ra = RunAnalysis(a, removing, [&](const Sample& s) { qa.push_back(s.q); });
  const RunResult rb = RunAnalysis(b, planar, [&](const Sample& s) { qb.push_back(s.q); });
  ASSERT_TRUE(ra.ok() && rb.ok()) << ra.message << rb.message;
  ASSERT_EQ(qa.size(), qb.size());
  for (std::size_t k = 0; k < qa.size(); ++k) EXPECT_EQ(qa[k], qb[k]) << "sample " << k;
  // The wrong plane: an error naming the equations that act in it.
  planar.plane_normal = Eigen::Vector3d::UnitX();
  try {
    PrepareRun(sc.system, planar);
    ADD_FAILURE() << "the four-bar passed as planar about x";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("act in the plane"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb::mbs
