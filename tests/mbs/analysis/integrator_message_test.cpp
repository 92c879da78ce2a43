// An integrator's failure message quotes each step size once, with what it is: IDA's own
// "At t = .. and h = .., " prefix is split off (the analysis says t itself and names h as
// the last step tried, next to the last step accepted).

#include <gtest/gtest.h>

#include "libemb/mbs/analysis/analysis_internal.h"

namespace emb::mbs::internal {
namespace {

TEST(IntegratorMessage, SplitsTimeAndTriedStep) {
  const IntegratorMessage m = SplitIntegratorMessage(
      "IDA/IDASolve: At t = 0.0123 and h = 1.25e-15, the corrector convergence failed "
      "repeatedly or with |h| = hmin.");
  ASSERT_TRUE(m.step_tried.has_value());
  EXPECT_DOUBLE_EQ(*m.step_tried, 1.25e-15);
  EXPECT_EQ(m.text,
            "IDA/IDASolve: the corrector convergence failed repeatedly or with |h| = hmin.");
}

TEST(IntegratorMessage, TooMuchWorkHasNoStep) {
  // SUNDIALS 6 writes a second comma after the time in this one.
  const IntegratorMessage m =
      SplitIntegratorMessage("IDA/IDASolve: At t = 0.25006, , mxstep steps taken before reaching tout.");
  EXPECT_FALSE(m.step_tried.has_value());
  EXPECT_EQ(m.text, "IDA/IDASolve: mxstep steps taken before reaching tout.");
}

TEST(IntegratorMessage, OtherMessagesAreKeptWhole) {
  const IntegratorMessage m = SplitIntegratorMessage("generalized-alpha: the step size fell "
                                                     "below the round-off of t");
  EXPECT_FALSE(m.step_tried.has_value());
  EXPECT_EQ(m.text, "generalized-alpha: the step size fell below the round-off of t");
}

}  // namespace
}  // namespace emb::mbs::internal
