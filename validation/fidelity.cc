#include "validation/fidelity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "common/error.h"
#include "physics/physics_setup.h"
#include "planner/coarse_planner.h"
#include "validation/candidate_grid.h"
#include "validation/fidelity_views.h"
#include "validation/physics_evaluator.h"

namespace foresight {

namespace {

int ArgMax(const std::vector<CandidateScore>& c, ActionEvaluation CandidateScore::*which) {
  int best = 0;
  for (int i = 1; i < static_cast<int>(c.size()); ++i) {
    if ((c[i].*which).utility > (c[best].*which).utility) best = i;
  }
  return best;
}

ChoiceMetrics Compare(const SituationFidelity& s, ActionEvaluation CandidateScore::*model) {
  std::vector<double> model_u, physics_u;
  for (const CandidateScore& c : s.candidates) {
    model_u.push_back((c.*model).utility);
    physics_u.push_back(c.physics.utility);
  }
  ChoiceMetrics m;
  m.choice = ArgMax(s.candidates, model);
  m.tau_b = KendallTauB(model_u, physics_u);
  const CandidateScore& best = s.candidates[s.physics_best];
  const double chosen = s.candidates[m.choice].physics.utility;
  m.top1 = chosen >= best.physics_ci.low;
  m.regret = best.physics.utility - chosen;
  return m;
}

std::vector<StrategyAgreement> CompareDecisions(ActionEvaluator& coarse,
                                                PhysicsActionEvaluator& physics,
                                                const std::vector<double>& rotations) {
  CandidateGridEvaluator coarse_grid(coarse, rotations);
  CandidateGridEvaluator physics_grid(physics, rotations);
  std::vector<StrategyAgreement> out;
  for (Strategy strategy : AllStrategies()) {
    const Decision c = Decide(coarse_grid, strategy);
    const Decision p = Decide(physics_grid, strategy);
    StrategyAgreement a;
    a.strategy = strategy;
    a.coarse_kick = c.kick_index;
    a.physics_kick = p.kick_index;
    a.coarse_rotation_rad = c.kick_index == kNoKick ? 0.0 : coarse_grid.Snap(c.rotation_rad);
    a.physics_rotation_rad = p.kick_index == kNoKick ? 0.0 : physics_grid.Snap(p.rotation_rad);
    a.agree = a.coarse_kick == a.physics_kick &&
              std::abs(a.coarse_rotation_rad - a.physics_rotation_rad) < 1e-9;
    a.regret = physics_grid.Evaluate(a.physics_kick, a.physics_rotation_rad).utility -
               physics_grid.Evaluate(a.coarse_kick, a.coarse_rotation_rad).utility;
    out.push_back(a);
  }
  return out;
}

// Settled stances (floating base) per robot and field: the situations of a set share them, so
// each robot settles its kicks' weight shifts once per run, not once per situation.
using SettledByWorld = std::map<std::string, SettledStances>;

SituationFidelity RunOne(const FidelityCase& fc, const std::vector<double>& rotations,
                         const std::filesystem::path& models, const FidelitySettings& settings,
                         int coarse_samples, SettledByWorld& settled,
                         const std::vector<SituationFidelity>& before) {
  const std::string world = fc.situation.kicks.robot + "|" + fc.situation.field.name;
  const auto known = settled.find(world);
  auto setup = LoadPhysicsSetup(fc.situation, models, settings.physics_file, settings.base,
                                known == settled.end() ? nullptr : &known->second);
  if (known == settled.end()) settled.emplace(world, setup->simulator->scene().settled_stances);
  const Situation& situation = setup->situation;
  RequireAllKickMotions(*setup, fc.file.string());
  const CoarsePlanner planner(situation);
  CoarseActionEvaluator coarse = planner.MakeEvaluator(coarse_samples, settings.seed);
  CoarseActionEvaluator converged =
      planner.MakeEvaluator(settings.converged_samples, settings.seed);
  PhysicsActionEvaluator physics(situation, *setup->simulator, planner.value(),
                                 settings.physics_trials, settings.seed, settings.threads);
  SituationFidelity s;
  s.situation_class = fc.situation_class;
  s.file = fc.shown_file;
  s.situation = situation;
  for (int k = 0; k < static_cast<int>(situation.kicks.kicks.size()); ++k) {
    for (double rotation : rotations) {
      CandidateScore c;
      c.kick_index = k;
      c.rotation_rad = rotation;
      c.coarse = coarse.Evaluate(k, rotation);
      c.converged = converged.Evaluate(k, rotation);
      const PhysicsHypothesis& h = physics.Hypothesis(k, rotation);
      c.physics = h.evaluation;
      c.physics_ci = MeanTInterval(h.utilities, settings.confidence);
      c.physics_status = CountStatuses(h.outcomes);
      s.physics_status.Add(c.physics_status);
      s.candidates.push_back(c);
    }
  }
  s.physics_best = ArgMax(s.candidates, &CandidateScore::physics);
  s.coarse = Compare(s, &CandidateScore::coarse);
  s.converged = Compare(s, &CandidateScore::converged);
  const CandidateScore& choice = s.candidates[s.coarse.choice];
  s.coarse_outcomes = coarse.Outcomes(choice.kick_index, choice.rotation_rad);
  s.physics_outcomes = physics.Hypothesis(choice.kick_index, choice.rotation_rad).outcomes;
  s.decisions = CompareDecisions(coarse, physics, rotations);
  s.physics_trials_run = physics.trials_run();
  // Recorded now, while the evaluator that scored the trials is here (merge runs no physics).
  if (MayBeShown(before, s)) s.views = RecordFidelityViews(s, physics);
  return s;
}

// The mean with a t interval, clipped to the range the quantity can take.
MeanWithInterval MeanOf(const std::vector<double>& values, double confidence, double lo,
                        double hi) {
  MeanWithInterval m;
  m.n = static_cast<int>(values.size());
  if (values.empty()) return m;
  m.mean = std::accumulate(values.begin(), values.end(), 0.0) / m.n;
  m.ci = values.size() >= 2 ? MeanTInterval(values, confidence) : Interval{m.mean, m.mean};
  m.ci = {std::clamp(m.ci.low, lo, hi), std::clamp(m.ci.high, lo, hi)};
  return m;
}

MeanWithInterval ShareOf(const std::vector<bool>& hits, double confidence) {
  MeanWithInterval m;
  m.n = static_cast<int>(hits.size());
  if (hits.empty()) return m;
  const int k = static_cast<int>(std::count(hits.begin(), hits.end(), true));
  m.mean = static_cast<double>(k) / m.n;
  m.ci = WilsonInterval(k, m.n, confidence);
  return m;
}

ClassSummary Summarize(const std::string& name, const std::vector<const SituationFidelity*>& in,
                       double confidence) {
  std::vector<double> tau_c, tau_v, reg_c, reg_v;
  std::vector<bool> top_c, top_v;
  for (const SituationFidelity* s : in) {
    tau_c.push_back(s->coarse.tau_b);
    tau_v.push_back(s->converged.tau_b);
    reg_c.push_back(s->coarse.regret);
    reg_v.push_back(s->converged.regret);
    top_c.push_back(s->coarse.top1);
    top_v.push_back(s->converged.top1);
  }
  ClassSummary c;
  c.situation_class = name;
  c.situations = static_cast<int>(in.size());
  constexpr double kHuge = std::numeric_limits<double>::max();
  c.tau_coarse = MeanOf(tau_c, confidence, -1.0, 1.0);
  c.tau_converged = MeanOf(tau_v, confidence, -1.0, 1.0);
  c.regret_coarse = MeanOf(reg_c, confidence, 0.0, kHuge);  // >= 0 by construction
  c.regret_converged = MeanOf(reg_v, confidence, 0.0, kHuge);
  c.top1_coarse = ShareOf(top_c, confidence);
  c.top1_converged = ShareOf(top_v, confidence);
  return c;
}

void Aggregate(FidelityResult& r, double confidence) {
  std::vector<std::string> classes;
  std::vector<const SituationFidelity*> all;
  for (const SituationFidelity& s : r.situations) {
    all.push_back(&s);
    if (std::find(classes.begin(), classes.end(), s.situation_class) == classes.end()) {
      classes.push_back(s.situation_class);
    }
  }
  r.classes.push_back(Summarize("all", all, confidence));
  for (const std::string& name : classes) {
    std::vector<const SituationFidelity*> of;
    for (const SituationFidelity* s : all) {
      if (s->situation_class == name) of.push_back(s);
    }
    r.classes.push_back(Summarize(name, of, confidence));
  }
  const std::vector<Strategy> strategies = AllStrategies();
  for (std::size_t i = 0; i < strategies.size(); ++i) {
    std::vector<bool> agree;
    std::vector<double> regret;
    for (const SituationFidelity& s : r.situations) {
      agree.push_back(s.decisions[i].agree);
      regret.push_back(s.decisions[i].regret);
    }
    // A strategy's physics decision need not have the best utility, so this may be negative.
    r.strategies.push_back({strategies[i], ShareOf(agree, confidence),
                            MeanOf(regret, confidence, -std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::max())});
  }
}

}  // namespace

int FidelityCoarseSamples(const FidelitySet& set, const FidelitySettings& settings) {
  if (settings.coarse_samples > 0 || set.cases.empty()) return settings.coarse_samples;
  return set.cases.front().situation.evaluation.samples;
}

FidelityResult RunFidelity(const FidelitySet& set, const std::filesystem::path& models_dir,
                           const FidelitySettings& settings) {
  FidelityResult result;
  result.coarse_samples = FidelityCoarseSamples(set, settings);
  const Shard& shard = settings.shard;
  const int owned = shard.OwnedCount(static_cast<int>(set.cases.size()));
  SettledByWorld settled;
  for (int k = 0; k < owned; ++k) {
    const FidelityCase& fc = set.cases[shard.Item(k)];
    const int n =
        settings.coarse_samples > 0 ? settings.coarse_samples : fc.situation.evaluation.samples;
    result.situations.push_back(
        RunOne(fc, set.rotations_rad, models_dir, settings, n, settled, result.situations));
    KeepShownViews(result.situations);
    if (settings.progress) settings.progress(k + 1, owned);
  }
  if (shard.IsWhole()) FinishFidelity(result, settings.confidence);
  return result;
}

void FinishFidelity(FidelityResult& result, double confidence) {
  result.physics_trials_run = 0;
  result.physics_status = {};
  for (const SituationFidelity& s : result.situations) {
    result.physics_trials_run += s.physics_trials_run;
    result.physics_status.Add(s.physics_status);
  }
  Aggregate(result, confidence);
}

bool WorseSituation(const SituationFidelity& a, const SituationFidelity& b) {
  const ChoiceMetrics& x = a.coarse;
  const ChoiceMetrics& y = b.coarse;
  if (x.regret != y.regret) return x.regret > y.regret;
  if (std::isnan(x.tau_b) || std::isnan(y.tau_b))
    return !std::isnan(x.tau_b) && std::isnan(y.tau_b);
  return x.tau_b < y.tau_b;
}

std::vector<int> WorstFirst(const std::vector<SituationFidelity>& situations) {
  std::vector<int> order(situations.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return WorseSituation(situations[a], situations[b]); });
  return order;
}

std::vector<int> WorstFirst(const FidelityResult& result) {
  return WorstFirst(result.situations);
}

}  // namespace foresight
