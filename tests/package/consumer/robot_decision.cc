// The minimal robot program of docs/COMMANDS.md ("Use it from your robot code"): load a
// situation, build the planner once, then decide every cycle without touching the heap. Prints the
// decision of the given seed as JSON, in the names of `foresight decide --json`, so the test
// can compare the two.
//
// Usage: robot_decision SITUATION_FILE SEED
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "common/error.h"
#include "models/situation.h"
#include "planner/coarse_planner.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: robot_decision SITUATION_FILE SEED\n";
    return 2;
  }
  try {
    // Once, at start-up.
    const foresight::Situation situation = foresight::LoadSituation(argv[1], MODELS_DIR);
    const foresight::CoarsePlanner planner(situation);
    const int samples = situation.evaluation.samples;
    foresight::CoarseActionEvaluator evaluator = planner.MakeEvaluator(samples, 0);
    foresight::Decision decision;
    foresight::ReserveDecision(decision, static_cast<int>(situation.kicks.kicks.size()));

    // Every cycle: the robot's current belief (here the situation's) and a new seed.
    const std::uint64_t seed = std::stoull(argv[2]);
    planner.Decide(situation.state, foresight::Strategy::kOptimalAll, samples, seed, evaluator,
                   decision);

    nlohmann::ordered_json out;
    out["kick"] = situation.kicks.NameOf(decision.kick_index);
    out["rotation_deg"] = decision.rotation_rad * foresight::kRadToDeg;
    for (const foresight::KickOption& k : decision.kicks) {
      out["kicks"].push_back({{"name", situation.kicks.NameOf(k.kick_index)},
                              {"rotation_deg", k.choice.rotation_rad * foresight::kRadToDeg},
                              {"utility", k.choice.evaluation.utility},
                              {"p_opp_goal", k.choice.evaluation.p_opp_goal}});
    }
    std::cout << out.dump(2) << "\n";
  } catch (const foresight::InputError& e) {
    std::cerr << "robot_decision: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
