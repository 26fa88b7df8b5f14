// The strategies experiment (experiments/) with kicks executed in physics (physics/) through the
// outcome-simulator seam: the two libraries meet only here and in the command line.
#include <gtest/gtest.h>

#include "experiments/strategies.h"
#include "physics/physics_setup.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

StrategiesParams Params(Situation situation, int starts) {
  StrategiesParams p;
  p.situation = std::move(situation);
  p.strategies = {Strategy::kFast};
  p.starts = starts;
  p.max_steps = 2;
  p.walk_speed_mps = 0.2;
  p.turn_speed_radps = 60.0 * kDegToRad;
  p.turn_around_ball_speed_radps = 30.0 * kDegToRad;
  p.Validate();
  return p;
}

// The physics executor goes through the same seam: a few kicks of the real NAO.
TEST(StrategiesPhysicsTest, PhysicsExecutesTheKicks) {
  StrategiesParams p = Params(testing::MakeSituation(testing::Uncertain({})), 2);
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
