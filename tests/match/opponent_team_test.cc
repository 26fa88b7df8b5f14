// The opponents never leave their home regions (Ros et al. 2009, sec. 5.1.2), checked at every
// control step of many trials of both configurations against the reactive team, and the
// defender does go for the ball (it touches it in some trials).
#include "match/opponent_team.h"

#include <gtest/gtest.h>

#include "common/random.h"
#include "match/match.h"
#include "match/reactive_team.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

TEST(OpponentTeamTest, OpponentsNeverLeaveTheirRegions) {
  const auto models = testing::ModelsDir();
  const FieldSpec field = LoadFieldSpec(models / "fields" / "four_legged.json");
  const SimulationParams sim = LoadSimulationParams("simulation", models);
  const RobotParams robot = LoadRobotParams("aibo_ers7", models);
  const KickModel kicks = LoadKickModel(models / "kicks" / "aibo_ers7.json");
  const ReactiveParams reactive = LoadReactiveParams("reactive", models);
  const CoarseKickExecutor executor(field, kicks.rolling_deceleration_mps2);
  int frames = 0, touches = 0;
  for (const char* name : {"dg", "2d"}) {
    for (bool mirrored : {false, true}) {
      MatchConfig config = LoadMatchConfig(name, models, field, sim, robot);
      if (mirrored) config = config.Mirrored();
      MatchSetup setup{&field, &kicks, &robot, &sim, &config, &executor,
                       mirrored ? -1.0 : 1.0, sim.control_step_s};
      for (std::size_t s = 0; s < config.scenarios.size(); ++s) {
        for (int trial = 0; trial < 10; ++trial) {
          ReactiveTeam attackers(reactive, field, kicks, robot, sim.control_step_s, 2);
          OpponentTeam opponents(config, kicks, robot, field.ball.radius_m, sim.control_step_s);
          const MatchTrialResult r = RunTrial(setup, config.scenarios[s], attackers, opponents,
                                              StreamKey(5, s * 100 + trial));
          for (int t : r.counters.opponent_touches) touches += t;
          for (const TraceFrame& f : r.trace) {
            ++frames;
            for (std::size_t o = 0; o < config.opponents.size(); ++o) {
              const Vec2& p = f.robots[2 + o].p_F;
              ASSERT_TRUE(config.opponents[o].region.Contains(p))
                  << name << (mirrored ? " mirrored" : "") << " scenario " << s + 1 << " trial "
                  << trial << " t " << f.time_s << ": " << config.opponents[o].name << " at ("
                  << p.x() << ", " << p.y() << ")";
            }
          }
        }
      }
    }
  }
  EXPECT_GT(frames, 10000);
  EXPECT_GT(touches, 50);  // they do play the ball
}

}  // namespace
}  // namespace foresight
