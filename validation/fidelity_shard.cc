#include "validation/fidelity_shard.h"

#include <cmath>

#include "common/checks.h"
#include "common/geometry.h"
#include "planner/hypothesis.h"
#include "planner/strategy_names.h"
#include "report/scene_trace_shard.h"

namespace foresight {

namespace {

nlohmann::json EvaluationJson(const ActionEvaluation& e) {
  nlohmann::json counts = nlohmann::json::array();
  for (int c : e.counts) counts.push_back(c);
  return {{"samples", e.samples},
          {"counts", counts},
          {"p", {ExactJson(e.p_infield), ExactJson(e.p_opp_goal), ExactJson(e.p_own_goal),
                 ExactJson(e.p_out)}},
          {"value_avg", ExactJson(e.value_avg)},
          {"potential_avg", ExactJson(e.potential_avg)},
          {"potential_all_avg", ExactJson(e.potential_all_avg)},
          {"utility", ExactJson(e.utility)},
          {"trimmed_utility", ExactJson(e.trimmed_utility)},
          {"too_risky", e.too_risky}};
}

// An evaluation as HypothesisAccumulator::Finish makes it (planner/hypothesis.h): counts that
// add up to the samples, the shares computed from them, values in [0, 1], the utility (eq. 5)
// and the trimming of `params`. Anything else is damage or tampering (a share of -5 reached the
// report).
ActionEvaluation ReadEvaluation(const ShardValue& v, const EvaluationParams& params) {
  ActionEvaluation e;
  e.samples = v["samples"].Count();
  const ShardValue counts = v["counts"], p = v["p"];
  if (counts.Size() != e.counts.size()) counts.Fail("must have one count per category");
  long long total = 0;
  for (std::size_t c = 0; c < e.counts.size(); ++c) total += e.counts[c] = counts.At(c).Count();
  if (total != e.samples) counts.Fail("must add up to the samples, " + std::to_string(e.samples));
  if (p.Size() != 4) p.Fail("must be [p_infield, p_opp_goal, p_own_goal, p_out]");
  const double n = e.samples;
  const auto share = [&](std::size_t at, Category c) {
    const double expected = e.samples == 0 ? 0.0 : e.Count(c) / n;
    const double stored = p.At(at).Double();
    if (stored != expected) {
      p.At(at).Fail("must be its count / samples, " + FormatNumber(expected) + ", got " +
                    FormatNumber(stored));
    }
    return stored;
  };
  e.p_infield = share(0, Category::kInfield);
  e.p_opp_goal = share(1, Category::kOppGoal);
  e.p_own_goal = share(2, Category::kOwnGoal);
  e.p_out = share(3, Category::kOut);
  e.value_avg = v["value_avg"].InRange(0.0, 1.0);
  e.potential_avg = v["potential_avg"].Finite();
  e.potential_all_avg = v["potential_all_avg"].Finite();
  e.utility = v["utility"].Double();
  const double utility = e.samples == 0 ? 0.0 : Utility(e.value_avg, e.p_infield, e.p_opp_goal, params);
  if (e.utility != utility) {
    v["utility"].Fail("must be eq. 5 of the shares, " + FormatNumber(utility) + ", got " +
                      FormatNumber(e.utility));
  }
  e.too_risky = v["too_risky"].Bool();
  if (e.samples > 0 &&
      e.too_risky != Trimmed(e.Count(Category::kOut), e.Count(Category::kOwnGoal),
                             MaxOuts(params, e.samples))) {
    v["too_risky"].Fail(std::string("must follow from p_out and the own goals, ") +
                        (e.too_risky ? "false, got true" : "true, got false"));
  }
  e.trimmed_utility = v["trimmed_utility"].Double();
  if (const double trimmed = e.too_risky ? 0.0 : e.utility; e.trimmed_utility != trimmed) {
    v["trimmed_utility"].Fail("must be the utility, or 0 when too risky, " +
                              FormatNumber(trimmed) + ", got " + FormatNumber(e.trimmed_utility));
  }
  return e;
}

nlohmann::json StatusJson(const StatusCounts& s) {
  return {s.missed, s.not_settled, s.fell, s.blocked};
}

StatusCounts ReadStatus(const ShardValue& v) {
  if (v.Size() != 4) v.Fail("must be [missed, not_settled, fell, blocked]");
  return {v.At(0).Count(), v.At(1).Count(), v.At(2).Count(), v.At(3).Count()};
}

// A number that is finite or, where a statistic is undefined (tau-b of ties), NaN.
double FiniteOrNan(const ShardValue& v) {
  const double x = v.Double();
  if (std::isinf(x)) v.Fail("must be a finite number or nan");
  return x;
}

nlohmann::json MetricsJson(const ChoiceMetrics& m) {
  return {m.choice, ExactJson(m.tau_b), m.top1, ExactJson(m.regret)};
}

ChoiceMetrics ReadMetrics(const ShardValue& v, int candidates) {
  if (v.Size() != 4) v.Fail("must be [choice, tau_b, top1, regret]");
  ChoiceMetrics m{v.At(0).Int(), FiniteOrNan(v.At(1)), v.At(2).Bool(), FiniteOrNan(v.At(3))};
  if (m.choice < 0 || m.choice >= candidates) v.At(0).Fail("not a candidate");
  if (!std::isnan(m.tau_b) && std::abs(m.tau_b) > 1.0) v.At(1).Fail("must be in [-1, 1] or nan");
  return m;
}

nlohmann::json SituationJson(const SituationFidelity& s) {
  nlohmann::json candidates = nlohmann::json::array();
  for (const CandidateScore& c : s.candidates) {
    candidates.push_back({{"kick", c.kick_index},
                          {"rotation_rad", ExactJson(c.rotation_rad)},
                          {"coarse", EvaluationJson(c.coarse)},
                          {"converged", EvaluationJson(c.converged)},
                          {"physics", EvaluationJson(c.physics)},
                          {"physics_ci", {ExactJson(c.physics_ci.low), ExactJson(c.physics_ci.high)}},
                          {"physics_status", StatusJson(c.physics_status)}});
  }
  nlohmann::json decisions = nlohmann::json::array();
  for (const StrategyAgreement& a : s.decisions) {
    decisions.push_back({std::string(StrategyName(a.strategy)), a.coarse_kick, a.physics_kick,
                         ExactJson(a.coarse_rotation_rad), ExactJson(a.physics_rotation_rad),
                         a.agree, ExactJson(a.regret)});
  }
  nlohmann::json views = nlohmann::json::array();
  for (const ViewerTrial& t : s.views) views.push_back(ViewerTrialShardJson(t));
  return {{"file", std::filesystem::path(s.file).filename().string()},
          {"candidates", candidates},
          {"physics_best", s.physics_best},
          {"coarse", MetricsJson(s.coarse)},
          {"converged", MetricsJson(s.converged)},
          {"decisions", decisions},
          {"coarse_outcomes", OutcomesShardJson(s.coarse_outcomes)},
          {"physics_outcomes", OutcomesShardJson(s.physics_outcomes)},
          {"physics_trials_run", s.physics_trials_run},
          {"physics_status", StatusJson(s.physics_status)},
          {"views", views}};
}

StrategyAgreement ReadAgreement(const ShardValue& v, int kicks) {
  if (v.Size() != 7) v.Fail("must be [strategy, kicks, rotations, agree, regret]");
  StrategyAgreement a;
  const std::optional<Strategy> strategy = ParseStrategy(v.At(0).String());
  if (!strategy) v.At(0).Fail("not a strategy");
  a.strategy = *strategy;
  a.coarse_kick = v.At(1).IntInRange(kNoKick, kicks - 1);
  a.physics_kick = v.At(2).IntInRange(kNoKick, kicks - 1);
  a.coarse_rotation_rad = v.At(3).InRange(-2.0 * kPi, 2.0 * kPi);
  a.physics_rotation_rad = v.At(4).InRange(-2.0 * kPi, 2.0 * kPi);
  a.agree = v.At(5).Bool();
  a.regret = FiniteOrNan(v.At(6));
  return a;
}

// Situation `fc` of the set with the results of `v`.
SituationFidelity ReadSituation(const ShardValue& v, const FidelityCase& fc) {
  SituationFidelity s;
  s.situation_class = fc.situation_class;
  s.file = fc.shown_file;
  s.situation = fc.situation;
  const std::string name = fc.file.filename().string();
  if (v["file"].String() != name) v["file"].Fail("must be " + name + " (another set?)");
  const int kicks = static_cast<int>(fc.situation.kicks.kicks.size());
  const ShardValue candidates = v["candidates"];
  for (std::size_t i = 0; i < candidates.Size(); ++i) {
    const ShardValue c = candidates.At(i);
    CandidateScore score;
    score.kick_index = c["kick"].Int();
    if (score.kick_index < 0 || score.kick_index >= kicks) c["kick"].Fail("not a kick");
    score.rotation_rad = c["rotation_rad"].InRange(-2.0 * kPi, 2.0 * kPi);
    const EvaluationParams& params = fc.situation.evaluation;
    score.coarse = ReadEvaluation(c["coarse"], params);
    score.converged = ReadEvaluation(c["converged"], params);
    score.physics = ReadEvaluation(c["physics"], params);
    const ShardValue ci = c["physics_ci"];
    if (ci.Size() != 2) ci.Fail("must be [low, high]");
    score.physics_ci = {FiniteOrNan(ci.At(0)), FiniteOrNan(ci.At(1))};
    if (score.physics_ci.low > score.physics_ci.high) ci.Fail("must have low <= high");
    score.physics_status = ReadStatus(c["physics_status"]);
    s.candidates.push_back(score);
  }
  const int n = static_cast<int>(s.candidates.size());
  if (n == 0) candidates.Fail("must not be empty");
  s.physics_best = v["physics_best"].Int();
  if (s.physics_best < 0 || s.physics_best >= n) v["physics_best"].Fail("not a candidate");
  s.coarse = ReadMetrics(v["coarse"], n);
  s.converged = ReadMetrics(v["converged"], n);
  const ShardValue decisions = v["decisions"];
  for (std::size_t i = 0; i < decisions.Size(); ++i)
    s.decisions.push_back(ReadAgreement(decisions.At(i), kicks));
  if (s.decisions.size() != AllStrategies().size())
    decisions.Fail("must have one decision per strategy");
  s.coarse_outcomes = ReadShardOutcomes(v["coarse_outcomes"]);
  s.physics_outcomes = ReadShardOutcomes(v["physics_outcomes"]);
  s.physics_trials_run = v["physics_trials_run"].Integer();
  if (s.physics_trials_run < 0) v["physics_trials_run"].Fail("must be 0 or more");
  s.physics_status = ReadStatus(v["physics_status"]);
  const ShardValue views = v["views"];
  for (std::size_t i = 0; i < views.Size(); ++i)
    s.views.push_back(ReadShardViewerTrial(views.At(i)));
  return s;
}

}  // namespace

nlohmann::json FidelityShardResults(const FidelityResult& result) {
  nlohmann::json items = nlohmann::json::array();
  for (const SituationFidelity& s : result.situations) items.push_back(SituationJson(s));
  return items;
}

FidelityResult MergeFidelityShards(const FidelitySet& set, const FidelitySettings& settings,
                                   const std::vector<ShardPart>& parts) {
  const int total = static_cast<int>(set.cases.size());
  std::vector<SituationFidelity> situations(static_cast<std::size_t>(total));
  for (const ShardPart& part : parts) {
    const Shard& shard = part.header.shard;
    const ShardValue items = ResultsOf(part);
    for (int k = 0; k < shard.OwnedCount(total); ++k) {
      const int i = shard.Item(k);
      situations[i] = ReadSituation(items.At(k), set.cases[i]);
    }
  }
  FidelityResult result;
  result.coarse_samples = FidelityCoarseSamples(set, settings);
  result.situations = std::move(situations);
  FinishFidelity(result, settings.confidence);
  return result;
}

}  // namespace foresight
