#include "planner/decision.h"

#include <cmath>

#include "planner/naoth_rule.h"

namespace foresight {

namespace {

struct Context {
  ActionEvaluator& evaluator;
  const RotationSearchParams& search;
  ActionEvaluation none;

  RotationObjective ObjectiveFor(int kick) const {
    return [this, kick](double rotation_rad) {
      return evaluator.EvaluateForSearch(kick, rotation_rad);
    };
  }
  bool Acceptable(const ActionEvaluation& e) const { return !e.too_risky; }
  bool Improves(const ActionEvaluation& e) const {
    return Acceptable(e) && e.trimmed_utility > none.trimmed_utility;
  }
};

// The sign of the turn that brings the robot's heading towards the opponent goal's centre.
double TurnTowardsGoal(const Situation& situation) {
  return FaceGoalRotation(situation) >= 0.0 ? 1.0 : -1.0;
}

// The kick whose mean direction is closest to straight ahead.
int ForwardKick(const KickModel& kicks) {
  int best = 0;
  for (std::size_t i = 1; i < kicks.kicks.size(); ++i) {
    if (std::abs(kicks.kicks[i].direction_rad) < std::abs(kicks.kicks[best].direction_rad)) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

// Step 2 for strategies that prefer the least rotation: among `options`, those that improve the
// ball if any, else those that are acceptable; least |rho| first, then the higher utility.
int LeastRotationChoice(const Context& ctx, const std::vector<KickOption>& options) {
  for (bool need_improvement : {true, false}) {
    int best = -1;
    for (std::size_t i = 0; i < options.size(); ++i) {
      const KickOption& o = options[i];
      const ActionEvaluation& e = o.choice.evaluation;
      if (!o.considered || !(need_improvement ? ctx.Improves(e) : ctx.Acceptable(e))) continue;
      if (best < 0) { best = static_cast<int>(i); continue; }
      const RotationChoice& b = options[static_cast<std::size_t>(best)].choice;
      const double da = std::abs(o.choice.rotation_rad), db = std::abs(b.rotation_rad);
      if (da < db || (da == db && e.trimmed_utility > b.evaluation.trimmed_utility)) {
        best = static_cast<int>(i);
      }
    }
    if (best >= 0) return best;
  }
  return -1;
}

int BestUtilityChoice(const std::vector<KickOption>& options) {
  int best = -1;
  for (std::size_t i = 0; i < options.size(); ++i) {
    if (!options[i].considered) continue;
    if (best < 0 || BetterRotation(options[i].choice, options[static_cast<std::size_t>(best)].choice)) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

// When nothing is acceptable: every considered kick at the rotation of its best untrimmed
// utility, and the best of those.
void FallBack(Context& ctx, Decision& decision) {
  const KickOption* best = nullptr;
  for (KickOption& option : decision.kicks) {
    if (!option.considered) continue;
    const RotationChoice untrimmed = BestRotation(
        [&](double rho) {
          ActionEvaluation e = ctx.evaluator.Evaluate(option.kick_index, rho);
          e.trimmed_utility = e.utility;  // let the search see the untrimmed utility
          return e;
        },
        ctx.search);
    option.choice = {untrimmed.rotation_rad,
                     ctx.evaluator.Evaluate(option.kick_index, untrimmed.rotation_rad)};
    if (best == nullptr || option.choice.evaluation.utility > best->choice.evaluation.utility) {
      best = &option;
    }
  }
  if (best != nullptr) {
    decision.kick_index = best->kick_index;
    decision.rotation_rad = best->choice.rotation_rad;
  }
  decision.note = "no kick is acceptable at any rotation; took the best untrimmed utility";
}

void OptimiseEveryKick(Context& ctx, Decision& decision, int only_kick) {
  for (KickOption& option : decision.kicks) {
    option.considered = only_kick < 0 || option.kick_index == only_kick;
    if (option.considered) option.choice = BestRotation(ctx.ObjectiveFor(option.kick_index), ctx.search);
  }
}

void DecideFast(Context& ctx, Decision& decision) {
  const double towards_goal = TurnTowardsGoal(ctx.evaluator.situation());
  auto improves = [&ctx](const ActionEvaluation& e) { return ctx.Improves(e); };
  for (KickOption& option : decision.kicks) {
    // The least turn either way; at equal turns the one towards the goal.
    std::optional<RotationChoice> found = LeastAcceptableRotation(
        ctx.ObjectiveFor(option.kick_index), improves, towards_goal, ctx.search);
    if (!found || found->rotation_rad != 0.0) {
      std::optional<RotationChoice> away = LeastAcceptableRotation(
          ctx.ObjectiveFor(option.kick_index), improves, -towards_goal, ctx.search);
      if (away && (!found || std::abs(away->rotation_rad) < std::abs(found->rotation_rad))) {
        found = away;
      }
    }
    option.considered = found.has_value();
    if (found) option.choice = *found;
  }
  const int chosen = LeastRotationChoice(ctx, decision.kicks);
  if (chosen >= 0) {
    decision.kick_index = decision.kicks[static_cast<std::size_t>(chosen)].kick_index;
    decision.rotation_rad = decision.kicks[static_cast<std::size_t>(chosen)].choice.rotation_rad;
    return;
  }
  // No kick improves on the ball anywhere: report every kick's best rotation and fall back.
  OptimiseEveryKick(ctx, decision, -1);
  const int best = BestUtilityChoice(decision.kicks);
  if (best >= 0 && ctx.Acceptable(decision.kicks[static_cast<std::size_t>(best)].choice.evaluation)) {
    decision.kick_index = decision.kicks[static_cast<std::size_t>(best)].kick_index;
    decision.rotation_rad = decision.kicks[static_cast<std::size_t>(best)].choice.rotation_rad;
    decision.note = "no kick improves on the ball; took the best acceptable kick";
    return;
  }
  FallBack(ctx, decision);
}

void DecideOptimal(Context& ctx, Decision& decision, bool least_rotation, int only_kick) {
  OptimiseEveryKick(ctx, decision, only_kick);
  const int chosen = least_rotation ? LeastRotationChoice(ctx, decision.kicks)
                                    : BestUtilityChoice(decision.kicks);
  const bool usable = chosen >= 0 &&
      ctx.Acceptable(decision.kicks[static_cast<std::size_t>(chosen)].choice.evaluation);
  if (!usable) {
    FallBack(ctx, decision);
    return;
  }
  decision.kick_index = decision.kicks[static_cast<std::size_t>(chosen)].kick_index;
  decision.rotation_rad = decision.kicks[static_cast<std::size_t>(chosen)].choice.rotation_rad;
}

}  // namespace

Decision Decide(ActionEvaluator& evaluator, Strategy strategy) {
  const long long evaluations_before = evaluator.evaluations();
  const Situation& situation = evaluator.situation();
  Context ctx{evaluator, situation.evaluation.rotation_search, evaluator.Evaluate(-1, 0.0)};
  Decision decision;
  decision.strategy = strategy;
  decision.none = ctx.none;
  for (int k = 0; k < evaluator.kick_count(); ++k) decision.kicks.push_back({k, true, {}});

  switch (strategy) {
    case Strategy::kFast: DecideFast(ctx, decision); break;
    case Strategy::kOptimalValue: DecideOptimal(ctx, decision, false, -1); break;
    case Strategy::kOptimalAll: DecideOptimal(ctx, decision, true, -1); break;
    case Strategy::kOptimalOne:
      DecideOptimal(ctx, decision, false, ForwardKick(situation.kicks));
      break;
    case Strategy::kNaoth: {
      for (KickOption& option : decision.kicks) {
        option.choice = {0.0, evaluator.Evaluate(option.kick_index, 0.0)};
      }
      const NaothChoice choice = ApplyNaothRule(situation.evaluation.naoth_rule, decision.kicks, ctx.none);
      decision.kick_index = choice.kick_index;
      decision.rotation_rad = choice.kick_index < 0 ? FaceGoalRotation(situation) : 0.0;
      break;
    }
  }
  // Searches may stop simulating a candidate once it is certainly trimmed; report full ones.
  for (KickOption& option : decision.kicks) {
    if (option.considered && strategy != Strategy::kNaoth) {
      option.choice.evaluation = evaluator.Evaluate(option.kick_index, option.choice.rotation_rad);
    }
  }
  decision.evaluations = evaluator.evaluations() - evaluations_before;
  return decision;
}

}  // namespace foresight
