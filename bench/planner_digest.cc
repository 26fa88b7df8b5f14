// The bits of many decisions, printed: the check that two builds of the planner (e.g. one for the
// NAO's Atom, -march=silvermont, with 2 SIMD lanes, and one for this machine, -march=native,
// with 4) decide exactly alike (scripts/same_bytes.sh compares their output).
// Scenes are the benchmark's (random poses over the field, one obstacle) plus poses near the
// goals and lines; every strategy, several sample counts and seeds. Every double is printed in
// hexadecimal (%a), so any difference in a last bit shows.
#include <cstdio>

#include "common/random.h"
#include "planner/lanes.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

void Print(const char* what, const ActionEvaluation& e) {
  std::printf(" %s[%d %d %d %d %a %a %a %a]", what, e.Count(Category::kInfield),
              e.Count(Category::kOppGoal), e.Count(Category::kOwnGoal), e.Count(Category::kOut),
              e.value_avg, e.potential_avg, e.potential_all_avg, e.utility);
}

int Run() {
  std::fprintf(stderr, "planner_digest: %d lanes\n", kLanes);  // not in the digest: builds differ
  RandomStream rng(StreamKey(18, 0));
  for (int scene = 0; scene < 48; ++scene) {
    const double half_x = scene % 2 == 0 ? 4.2 : 4.7, half_y = scene % 2 == 0 ? 2.8 : 3.1;
    testing::StateSpec pose;
    do {  // a ball clear of the obstacle
      pose = testing::RandomPose(rng, half_x, half_y);
    } while ((Vec2(pose.x_m, pose.y_m) - Vec2(3.8, 0.4)).norm() < 0.6);
    const Situation s = testing::MakeSituation(pose, {{Vec2(3.8, 0.4), 0.15}});
    const CoarsePlanner planner(s);
    for (Strategy strategy : AllStrategies()) {
      for (int samples : {7, 30}) {
        const std::uint64_t seed = static_cast<std::uint64_t>(scene) * 31 + samples;
        const Decision d = planner.Decide(strategy, samples, seed);
        std::printf("%d %d %d kick %d rot %a hyp %lld", scene, static_cast<int>(strategy), samples,
                    d.kick_index, d.rotation_rad, d.evaluations);
        Print("none", d.none);
        for (const KickOption& k : d.kicks) Print("k", k.choice.evaluation);
        std::printf("\n");
      }
    }
  }
  return 0;
}

}  // namespace
}  // namespace foresight

int main() {
  return foresight::Run();
}
