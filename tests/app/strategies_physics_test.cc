// The strategies experiment (experiments/) with kicks executed in physics (physics/) through the
// outcome-simulator seam: the two libraries meet only here and in the command line.
#include <gtest/gtest.h>

#include "experiments/strategies.h"
#include "physics/physics_setup.h"
#include "tests/experiments/strategies_test_params.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

// The physics executor goes through the same seam: a few kicks of the real NAO.
TEST(StrategiesPhysicsTest, PhysicsExecutesTheKicks) {
  StrategiesParams p =
      testing::TestStrategiesParams(testing::MakeSituation(testing::Uncertain({})), 2);
  p.strategies = {Strategy::kFast};
  p.max_steps = 2;
  const auto setup = LoadPhysicsSetup(p.situation, testing::ModelsDir());
  const StrategiesResult r = RunStrategies(p, &*setup->simulator, 3, 2);
  const StrategyRun& run = r.strategies[0].example;
  ASSERT_FALSE(run.steps_taken.empty());
  const StrategyStep& first = run.steps_taken[0];
  ASSERT_GE(first.kick_index, 0);
  // Physics launches the ball (about 0.5-0.8 m/s for the NAO's kicks): it moves a few dm at least.
  EXPECT_GT((first.outcome.p_F_rest - first.p_F_ball).norm(), 0.2);
}

}  // namespace
}  // namespace foresight
