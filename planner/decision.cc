#include "planner/decision.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string_view>

#include "planner/naoth_rule.h"

namespace foresight {

namespace {

constexpr std::string_view kNoAcceptableNote =
    "no kick is acceptable at any rotation; took the fewest own goals, then outs, then utility";
constexpr std::string_view kNoImprovementNote =
    "no kick improves on leaving the ball; took the least turn to an acceptable kick";

struct Context {
  ActionEvaluator& evaluator;
  const RotationSearchParams& search;
  ActionEvaluation none;

  RotationObjective ObjectiveFor(int kick) const {
    return [this, kick](double rotation_rad) {
      return evaluator.EvaluateForSearch(kick, rotation_rad, evaluator.sample_count());
    };
  }
  SampledObjective SampledObjectiveFor(int kick) const {
    return [this, kick](double rotation_rad, int samples) {
      return evaluator.EvaluateForSearch(kick, rotation_rad, samples);
    };
  }
  bool Acceptable(const ActionEvaluation& e) const { return !e.too_risky; }
  bool Improves(const ActionEvaluation& e) const {
    return Acceptable(e) && e.trimmed_utility > none.trimmed_utility;
  }
};

// The sign of the turn that brings the robot's heading towards the opponent goal's centre.
double TurnTowardsGoal(const ActionEvaluator& evaluator) {
  return FaceGoalRotation(evaluator.situation().field, evaluator.state()) >= 0.0 ? 1.0 : -1.0;
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
      if (best < 0) {
        best = static_cast<int>(i);
        continue;
      }
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
    if (best < 0 ||
        BetterRotation(options[i].choice, options[static_cast<std::size_t>(best)].choice)) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

// Lexicographic score for the fallback: fewest own goals, then fewest outs, then utility.
// One sample less out is worth more than any utility difference (utility <= goal_value).
double FallbackScore(const ActionEvaluation& e, double goal_value) {
  const double step = goal_value + 1.0;
  return e.utility -
         step * (e.Count(Category::kOut) + (e.samples + 1.0) * e.Count(Category::kOwnGoal));
}

// When nothing is acceptable: every considered kick at the rotation of its best fallback
// score, and the best of those.
void FallBack(Context& ctx, Decision& decision) {
  const double goal_value = ctx.evaluator.situation().evaluation.goal_value;
  const KickOption* best = nullptr;
  double best_score = 0.0;
  for (KickOption& option : decision.kicks) {
    if (!option.considered) continue;
    // One pointer captured, so std::function keeps it without a heap allocation.
    struct {
      ActionEvaluator* evaluator;
      int kick;
      double goal_value;
    } objective{&ctx.evaluator, option.kick_index, goal_value};
    const RotationChoice found = BestRotation(
        [o = &objective](double rho, int samples) {
          ActionEvaluation e = o->evaluator->EvaluateFirst(o->kick, rho, samples);
          e.trimmed_utility = FallbackScore(e, o->goal_value);  // what the search maximises
          return e;
        },
        ctx.evaluator.sample_count(), ctx.search, ctx.evaluator.search_scratch());
    option.choice = {found.rotation_rad,
                     ctx.evaluator.Evaluate(option.kick_index, found.rotation_rad)};
    const double score = FallbackScore(option.choice.evaluation, goal_value);
    if (best == nullptr || score > best_score) best = &option, best_score = score;
  }
  if (best != nullptr) {
    decision.kick_index = best->kick_index;
    decision.rotation_rad = best->choice.rotation_rad;
  }
  decision.note.assign(kNoAcceptableNote);
}

void OptimiseEveryKick(Context& ctx, Decision& decision, int only_kick) {
  for (KickOption& option : decision.kicks) {
    option.considered = only_kick < 0 || option.kick_index == only_kick;
    if (option.considered)
      option.choice = BestRotation(ctx.SampledObjectiveFor(option.kick_index),
                                   ctx.evaluator.sample_count(), ctx.search,
                                   ctx.evaluator.search_scratch());
  }
}

// Per kick, the least turn either way for which `wanted` holds; at equal turns the one towards
// the goal. Kicks without one are marked.
void FindLeastTurns(Context& ctx, Decision& decision,
                    const std::function<bool(const ActionEvaluation&)>& wanted) {
  const double towards_goal = TurnTowardsGoal(ctx.evaluator);
  for (KickOption& option : decision.kicks) {
    std::optional<RotationChoice> found = LeastAcceptableRotation(
        ctx.ObjectiveFor(option.kick_index), wanted, towards_goal, ctx.search);
    if (!found || found->rotation_rad != 0.0) {
      std::optional<RotationChoice> away = LeastAcceptableRotation(
          ctx.ObjectiveFor(option.kick_index), wanted, -towards_goal, ctx.search);
      if (away && (!found || std::abs(away->rotation_rad) < std::abs(found->rotation_rad))) {
        found = away;
      }
    }
    option.considered = found.has_value();
    option.no_acceptable_rotation = !found.has_value();
    if (found) option.choice = *found;
  }
}

void DecideFast(Context& ctx, Decision& decision) {
  FindLeastTurns(ctx, decision, [&ctx](const ActionEvaluation& e) { return ctx.Improves(e); });
  int chosen = LeastRotationChoice(ctx, decision.kicks);
  if (chosen < 0) {
    // Nothing improves on leaving the ball: the least turn that makes some kick acceptable.
    FindLeastTurns(ctx, decision, [&ctx](const ActionEvaluation& e) { return ctx.Acceptable(e); });
    chosen = LeastRotationChoice(ctx, decision.kicks);
    if (chosen >= 0) decision.note.assign(kNoImprovementNote);
  }
  if (chosen >= 0) {
    decision.kick_index = decision.kicks[static_cast<std::size_t>(chosen)].kick_index;
    decision.rotation_rad = decision.kicks[static_cast<std::size_t>(chosen)].choice.rotation_rad;
    return;
  }
  for (KickOption& option : decision.kicks) option.considered = true;
  FallBack(ctx, decision);
}

void DecideOptimal(Context& ctx, Decision& decision, bool least_rotation, int only_kick) {
  OptimiseEveryKick(ctx, decision, only_kick);
  const int chosen =
      least_rotation ? LeastRotationChoice(ctx, decision.kicks) : BestUtilityChoice(decision.kicks);
  const bool usable =
      chosen >= 0 &&
      ctx.Acceptable(decision.kicks[static_cast<std::size_t>(chosen)].choice.evaluation);
  if (!usable) {
    FallBack(ctx, decision);
    return;
  }
  decision.kick_index = decision.kicks[static_cast<std::size_t>(chosen)].kick_index;
  decision.rotation_rad = decision.kicks[static_cast<std::size_t>(chosen)].choice.rotation_rad;
}

}  // namespace

void ReserveDecision(Decision& decision, int kick_count) {
  decision.kicks.reserve(static_cast<std::size_t>(kick_count));
  decision.note.reserve(std::max(kNoAcceptableNote.size(), kNoImprovementNote.size()));
}

Decision Decide(ActionEvaluator& evaluator, Strategy strategy) {
  Decision decision;
  Decide(evaluator, strategy, decision);
  return decision;
}

void Decide(ActionEvaluator& evaluator, Strategy strategy, Decision& decision) {
  const long long evaluations_before = evaluator.evaluations();
  const Situation& situation = evaluator.situation();
  Context ctx{evaluator, situation.evaluation.rotation_search, evaluator.Evaluate(-1, 0.0)};
  decision.strategy = strategy;
  decision.kick_index = kNoKick;
  decision.rotation_rad = 0.0;
  decision.none = ctx.none;
  decision.note.clear();  // keeps its capacity
  decision.kicks.clear();
  for (int k = 0; k < evaluator.kick_count(); ++k) {
    KickOption option;
    option.kick_index = k;
    decision.kicks.push_back(option);
  }

  switch (strategy) {
    case Strategy::kFast:
      DecideFast(ctx, decision);
      break;
    case Strategy::kOptimalValue:
      DecideOptimal(ctx, decision, false, -1);
      break;
    case Strategy::kOptimalAll:
      DecideOptimal(ctx, decision, true, -1);
      break;
    case Strategy::kOptimalOne:
      DecideOptimal(ctx, decision, false, ForwardKick(situation.kicks));
      break;
    case Strategy::kNaoth: {
      for (KickOption& option : decision.kicks) {
        option.choice = {0.0, evaluator.Evaluate(option.kick_index, 0.0)};
      }
      const NaothChoice choice =
          ApplyNaothRule(situation.evaluation.naoth_rule, decision.kicks, ctx.none);
      decision.kick_index = choice.kick_index;
      decision.rotation_rad =
          choice.kick_index == kNoKick ? FaceGoalRotation(situation.field, evaluator.state()) : 0.0;
      break;
    }
  }
  // Searches may stop simulating a candidate once it is certainly trimmed; report full ones
  // (an evaluation of all N samples is already the full one).
  for (KickOption& option : decision.kicks) {
    if (option.considered && strategy != Strategy::kNaoth &&
        option.choice.evaluation.samples != evaluator.sample_count()) {
      option.choice.evaluation = evaluator.Evaluate(option.kick_index, option.choice.rotation_rad);
    }
  }
  decision.evaluations = evaluator.evaluations() - evaluations_before;
}

}  // namespace foresight
