#include "app/decision_json.h"
#include "models/model_paths.h"

#include <string>


namespace foresight {

namespace {

nlohmann::ordered_json EvaluationJson(const ActionEvaluation& e) {
  nlohmann::ordered_json j;
  j["p_opp_goal"] = e.p_opp_goal;
  j["p_own_goal"] = e.p_own_goal;
  j["p_out"] = e.p_out;
  j["p_infield"] = e.p_infield;
  j["value_avg"] = e.value_avg;
  j["potential_avg"] = e.potential_avg;
  j["utility"] = e.utility;
  j["trimmed_utility"] = e.trimmed_utility;
  j["too_risky"] = e.too_risky;
  return j;
}

}  // namespace

nlohmann::ordered_json DecisionJson(const DecisionRun& run) {
  const Decision& d = run.decision;
  const Situation& s = run.planner->situation();
  nlohmann::ordered_json j;
  j["foresight_version"] = FORESIGHT_VERSION;
  j["command"] = "decide";
  j["situation"] = {{"name", s.name},
                    {"file", run.situation_file.string()},
                    {"field", DisplayPath(s.field_file, run.models_dir)},
                    {"kicks", DisplayPath(s.kicks_file, run.models_dir)},
                    {"evaluation", DisplayPath(s.evaluation_file, run.models_dir)}};
  j["strategy"] = StrategyName(d.strategy);
  j["samples"] = run.samples;
  j["seed"] = run.seed;
  j["decision"] = {{"kick", KickName(run, d.kick_index)},
                   {"rotation_deg", d.rotation_rad * kRadToDeg},
                   {"note", d.note}};
  nlohmann::ordered_json kicks = nlohmann::ordered_json::array();
  for (const KickOption& k : d.kicks) {
    nlohmann::ordered_json item;
    item["name"] = KickName(run, k.kick_index);
    item["considered"] = k.considered;
    item["no_acceptable_rotation"] = k.no_acceptable_rotation;
    item["chosen"] = k.kick_index == d.kick_index;
    item["rotation_deg"] = k.choice.rotation_rad * kRadToDeg;
    item.update(EvaluationJson(k.choice.evaluation));
    kicks.push_back(item);
  }
  j["kicks"] = kicks;
  j["none"] = EvaluationJson(d.none);
  j["hypotheses_simulated"] = d.evaluations;
  return j;
}

}  // namespace foresight
