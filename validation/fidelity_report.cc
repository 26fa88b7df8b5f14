#include "validation/fidelity_report.h"

#include "common/geometry.h"
#include "common/one_line.h"
#include "report/report_format.h"

namespace foresight {

namespace {

using Json = nlohmann::ordered_json;

Json MeanJson(const MeanWithInterval& m) {
  return Json{{"n", m.n}, {"mean", m.mean}, {"ci", Json::array({m.ci.low, m.ci.high})}};
}

Json EvaluationJson(const ActionEvaluation& e) {
  return Json{{"utility", e.utility},       {"trimmed_utility", e.trimmed_utility},
              {"p_opp_goal", e.p_opp_goal}, {"p_own_goal", e.p_own_goal},
              {"p_out", e.p_out},           {"p_infield", e.p_infield}};
}

Json ChoiceJson(const SituationFidelity& s, const ChoiceMetrics& m) {
  const CandidateScore& c = s.candidates[m.choice];
  return Json{{"kick", s.situation.kicks.NameOf(c.kick_index)},
              {"rotation_deg", c.rotation_rad * kRadToDeg},
              {"tau_b", m.tau_b},
              {"top1", m.top1},
              {"regret", m.regret}};
}

Json SituationJson(const SituationFidelity& s) {
  const CandidateScore& best = s.candidates[s.physics_best];
  Json j{{"name", s.situation.name},
         {"class", s.situation_class},
         {"file", s.file},
         {"physics_best", Json{{"kick", s.situation.kicks.NameOf(best.kick_index)},
                               {"rotation_deg", best.rotation_rad * kRadToDeg},
                               {"utility", best.physics.utility},
                               {"ci", Json::array({best.physics_ci.low, best.physics_ci.high})}}},
         {"coarse", ChoiceJson(s, s.coarse)},
         {"converged", ChoiceJson(s, s.converged)},
         {"physics_missed", s.physics_status.missed},
         {"physics_not_settled", s.physics_status.not_settled},
         {"physics_fell", s.physics_status.fell},
         {"physics_blocked", s.physics_status.blocked}};
  j["decisions"] = Json::array();
  for (const StrategyAgreement& a : s.decisions) {
    j["decisions"].push_back(Json{{"strategy", StrategyName(a.strategy)},
                                  {"coarse_kick", s.situation.kicks.NameOf(a.coarse_kick)},
                                  {"coarse_rotation_deg", a.coarse_rotation_rad * kRadToDeg},
                                  {"physics_kick", s.situation.kicks.NameOf(a.physics_kick)},
                                  {"physics_rotation_deg", a.physics_rotation_rad * kRadToDeg},
                                  {"agree", a.agree},
                                  {"regret", a.regret}});
  }
  j["candidates"] = Json::array();
  for (const CandidateScore& c : s.candidates) {
    j["candidates"].push_back(
        Json{{"kick", s.situation.kicks.NameOf(c.kick_index)},
             {"rotation_deg", c.rotation_rad * kRadToDeg},
             {"coarse", EvaluationJson(c.coarse)},
             {"converged", EvaluationJson(c.converged)},
             {"physics", EvaluationJson(c.physics)},
             {"physics_ci", Json::array({c.physics_ci.low, c.physics_ci.high})},
             {"physics_missed", c.physics_status.missed},
             {"physics_not_settled", c.physics_status.not_settled},
             {"physics_fell", c.physics_status.fell},
             {"physics_blocked", c.physics_status.blocked}});
  }
  return j;
}

}  // namespace

std::string FidelityText(const FidelityRun& run) {
  const FidelityResult& r = run.result;
  std::string out = "fidelity on '" + PrintableName(run.provenance.Input("situations_set")) +
                    "': " + std::to_string(r.situations.size()) +
                    " situations, coarse N = " + std::to_string(r.coarse_samples) +
                    ", converged N = " + std::to_string(run.settings.converged_samples) +
                    ", physics M = " + std::to_string(run.settings.physics_trials) + " (" +
                    std::to_string(r.physics_trials_run) + " trials, " +
                    StatusCountsText(r.physics_status) + ")\n";
  out +=
      "  class              n   tau_b coarse  tau_b conv.  top-1 coarse  top-1 conv.  regret "
      "coarse  regret conv.\n";
  for (const ClassSummary& c : r.classes) {
    char line[256];
    std::snprintf(
        line, sizeof line, "  %-18s %2d   %+11.3f  %+11.3f  %12.2f  %11.2f  %13.3f  %12.3f\n",
        PrintableName(c.situation_class).c_str(), c.situations, c.tau_coarse.mean, c.tau_converged.mean,
        c.top1_coarse.mean, c.top1_converged.mean, c.regret_coarse.mean, c.regret_converged.mean);
    out += line;
  }
  out += "  decisions over the candidates, coarse = physics:";
  for (const StrategyAgreementSummary& s : r.strategies) {
    out += ' ';
    out += StrategyName(s.strategy);
    out += ' ' + Fixed(s.agreement.mean * 100.0, 0) + " %";
  }
  return out + "\n";
}

Json FidelityJson(const FidelityRun& run) {
  const FidelityResult& r = run.result;
  std::vector<double> rotations_deg;
  for (double rot : run.rotations_rad) rotations_deg.push_back(rot * kRadToDeg);
  const RunProvenance& p = run.provenance;
  Json j{{"tool", "foresight fidelity"}, {"version", p.version}};
  AddInputsJson(j, p);
  j.update({{"seed", p.seed},
            {"coarse_samples", r.coarse_samples},
            {"converged_samples", run.settings.converged_samples},
            {"physics_trials", run.settings.physics_trials},
            {"confidence", run.settings.confidence},
            {"rotations_deg", rotations_deg},
            {"physics_trials_run", r.physics_trials_run},
            {"physics_missed", r.physics_status.missed},
            {"physics_not_settled", r.physics_status.not_settled},
            {"physics_fell", r.physics_status.fell},
            {"physics_blocked", r.physics_status.blocked},
            {"run_time_s", p.run_time_s}});
  j["classes"] = Json::array();
  for (const ClassSummary& c : r.classes) {
    j["classes"].push_back(Json{{"class", c.situation_class},
                                {"situations", c.situations},
                                {"tau_b_coarse", MeanJson(c.tau_coarse)},
                                {"tau_b_converged", MeanJson(c.tau_converged)},
                                {"top1_coarse", MeanJson(c.top1_coarse)},
                                {"top1_converged", MeanJson(c.top1_converged)},
                                {"regret_coarse", MeanJson(c.regret_coarse)},
                                {"regret_converged", MeanJson(c.regret_converged)}});
  }
  j["strategies"] = Json::array();
  for (const StrategyAgreementSummary& s : r.strategies) {
    j["strategies"].push_back(Json{{"strategy", StrategyName(s.strategy)},
                                   {"agreement", MeanJson(s.agreement)},
                                   {"regret", MeanJson(s.regret)}});
  }
  j["situations"] = Json::array();
  for (const SituationFidelity& s : r.situations) j["situations"].push_back(SituationJson(s));
  return j;
}

std::string FidelityCandidatesCsv(const FidelityRun& run) {
  std::string out =
      "situation,class,kick,rotation_deg,coarse_utility,converged_utility,physics_utility,"
      "physics_ci_low,physics_ci_high,coarse_p_goal,physics_p_goal,coarse_p_out,physics_p_out,"
      "physics_missed,physics_not_settled,physics_fell,physics_blocked\n";
  for (const SituationFidelity& s : run.result.situations) {
    for (const CandidateScore& c : s.candidates) {
      out += s.situation.name + "," + s.situation_class + "," +
             s.situation.kicks.NameOf(c.kick_index) + "," + Fixed(c.rotation_rad * kRadToDeg, 2) +
             "," + Fixed(c.coarse.utility, 6) + "," + Fixed(c.converged.utility, 6) + "," +
             Fixed(c.physics.utility, 6) + "," + Fixed(c.physics_ci.low, 6) + "," +
             Fixed(c.physics_ci.high, 6) + "," + Fixed(c.coarse.p_opp_goal, 4) + "," +
             Fixed(c.physics.p_opp_goal, 4) + "," + Fixed(c.coarse.p_out, 4) + "," +
             Fixed(c.physics.p_out, 4) + "," + std::to_string(c.physics_status.missed) + "," +
             std::to_string(c.physics_status.not_settled) + "," +
             std::to_string(c.physics_status.fell) + "," +
             std::to_string(c.physics_status.blocked) + "\n";
    }
  }
  return out;
}

std::string FidelitySituationsCsv(const FidelityRun& run) {
  std::string out =
      "situation,class,tau_b_coarse,tau_b_converged,top1_coarse,top1_converged,regret_coarse,"
      "regret_converged\n";
  for (const SituationFidelity& s : run.result.situations) {
    out += s.situation.name + "," + s.situation_class + "," + Fixed(s.coarse.tau_b, 6) + "," +
           Fixed(s.converged.tau_b, 6) + "," + (s.coarse.top1 ? "1" : "0") + "," +
           (s.converged.top1 ? "1" : "0") + "," + Fixed(s.coarse.regret, 6) + "," +
           Fixed(s.converged.regret, 6) + "\n";
  }
  return out;
}

}  // namespace foresight
