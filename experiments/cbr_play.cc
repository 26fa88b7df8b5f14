#include "experiments/cbr_play.h"

#include <cmath>

#include "cbr/team_counters.h"
#include "cbr/team_messages.h"
#include "report/report_format.h"

namespace foresight {

namespace {

const MeanStat* Find(const ScenarioSummary& s, const std::string& name) {
  for (const auto& [counter, stat] : s.team_counters) {
    if (counter == name) return &stat;
  }
  return nullptr;
}

// A counter's total over the scenario's trials (the summary keeps its mean per trial).
int Total(const ScenarioSummary& s, const std::string& name) {
  const MeanStat* m = Find(s, name);
  return m ? static_cast<int>(std::lround(m->mean * m->n)) : 0;
}

double Mean(const ScenarioSummary& s, const std::string& name) {
  const MeanStat* m = Find(s, name);
  return m ? m->mean : 0.0;
}

bool HasCbrCounters(const ScenarioSummary& s) { return Find(s, "cases_multi_kick") != nullptr; }

std::string PhaseCounter(CbrPhase phase) {
  return "robot_time_" + std::string(CbrPhaseName(phase)) + "_s";
}

CbrPlayRow Row(const ScenarioSummary& s, double confidence) {
  CbrPlayRow r;
  r.scenario = s.scenario;
  r.trials = s.trials;
  double all_s = 0.0;
  for (int k = 0; k < kCbrPhaseCount; ++k) all_s += Mean(s, PhaseCounter(static_cast<CbrPhase>(k)));
  const double default_s =
      Mean(s, PhaseCounter(CbrPhase::kIdle)) + Mean(s, PhaseCounter(CbrPhase::kAwaitCase));
  const auto of_all = [&](double s_robot) { return all_s > 0.0 ? s_robot / all_s : 0.0; };
  r.default_share = of_all(default_s);
  r.default_rolling_share = of_all(Mean(s, "robot_time_idle_ball_rolling_s"));
  r.default_opponent_share = of_all(Mean(s, "robot_time_idle_opponent_on_ball_s"));
  r.retrieved = Total(s, "cases_retrieved");
  r.completed = Total(s, "cases_completed");
  r.multi_kick = Total(s, "cases_multi_kick");
  r.multi_kick_completed = Total(s, "cases_multi_kick_completed");
  if (r.multi_kick > 0) {
    r.multi_kick_completed_ci = WilsonInterval(r.multi_kick_completed, r.multi_kick, confidence);
  }
  r.wait_end_timeouts = Total(s, "wait_end_timeouts");
  r.no_case = Total(s, "no_case");
  for (int k = 0; k < kAbortReasonCount; ++k) {
    const std::string reason(AbortReasonName(static_cast<AbortReason>(k)));
    r.aborts.emplace_back(reason, Total(s, "aborts_" + reason));
  }
  for (const char* why : {"path_blocked", "too_far", "out_of_scope", "candidates_refused"}) {
    r.no_case_why.emplace_back(why, Total(s, std::string("no_case_") + why));
  }
  return r;
}

double Share(int count, int of) { return of > 0 ? static_cast<double>(count) / of : 0.0; }

std::string PerTrial(int count, int trials) {
  return Format("%.2f", trials > 0 ? static_cast<double>(count) / trials : 0.0);
}

std::string DefaultPlay(const CbrPlayRow& r) {
  return Format("%.1f %% (rolling %.1f, opponent %.1f)", 100.0 * r.default_share,
                100.0 * r.default_rolling_share, 100.0 * r.default_opponent_share);
}

std::string Completion(const CbrPlayRow& r) {
  if (r.multi_kick == 0) return "none retrieved";
  return Format("%d of %d, %.1f %% [%.1f, %.1f]", r.multi_kick_completed, r.multi_kick,
                100.0 * Share(r.multi_kick_completed, r.multi_kick),
                100.0 * r.multi_kick_completed_ci.low, 100.0 * r.multi_kick_completed_ci.high);
}

std::string Pairs(const std::vector<std::pair<std::string, int>>& pairs, int trials) {
  std::string text;
  for (const auto& [name, count] : pairs) {
    text += (text.empty() ? "" : ", ") + name + " " + PerTrial(count, trials);
  }
  return text;
}

}  // namespace

std::vector<CbrPlayRow> BuildCbrPlay(const PassingRun& cbr) {
  std::vector<CbrPlayRow> rows;
  for (const ScenarioSummary& s : cbr.summaries) {
    if (HasCbrCounters(s)) rows.push_back(Row(s, cbr.setup->params.confidence));
  }
  return rows;
}

nlohmann::ordered_json CbrPlayJson(const std::vector<CbrPlayRow>& rows) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const CbrPlayRow& r : rows) {
    nlohmann::ordered_json aborts = nlohmann::ordered_json::object();
    for (const auto& [name, count] : r.aborts) aborts[name] = count;
    nlohmann::ordered_json why = nlohmann::ordered_json::object();
    for (const auto& [name, count] : r.no_case_why) why[name] = count;
    list.push_back({{"scenario", r.scenario},
                    {"trials", r.trials},
                    {"default_time_share", r.default_share},
                    {"default_time_share_ball_rolling", r.default_rolling_share},
                    {"default_time_share_opponent_on_ball", r.default_opponent_share},
                    {"cases_retrieved", r.retrieved},
                    {"cases_completed", r.completed},
                    {"cases_multi_kick", r.multi_kick},
                    {"cases_multi_kick_completed", r.multi_kick_completed},
                    {"multi_kick_completed_share", Share(r.multi_kick_completed, r.multi_kick)},
                    {"multi_kick_completed_share_ci",
                     {r.multi_kick_completed_ci.low, r.multi_kick_completed_ci.high}},
                    {"wait_end_timeouts", r.wait_end_timeouts},
                    {"aborts", aborts},
                    {"no_case", r.no_case},
                    {"no_case_why", why}});
  }
  return list;
}

std::string CbrPlayText(const std::vector<CbrPlayRow>& rows) {
  if (rows.empty()) return "";
  std::string text =
      "how the CBR team played (robot time in the default behaviour, of it while the ball "
      "rolled and while an opponent had it; cases with two kicks or more played to the end; "
      "aborts and no case per trial):\n";
  for (const CbrPlayRow& r : rows) {
    text += Format("  s%d default %s | multi-kick %s | completed %d of %d | wait-end "
                   "timeouts %d | aborts %s | no case %s (%s)\n",
                   r.scenario, DefaultPlay(r).c_str(), Completion(r).c_str(), r.completed,
                   r.retrieved, r.wait_end_timeouts, Pairs(r.aborts, r.trials).c_str(),
                   PerTrial(r.no_case, r.trials).c_str(), Pairs(r.no_case_why, r.trials).c_str());
  }
  return text;
}

std::vector<std::string> CbrPlayColumns() {
  return {"scenario", "robot time in the default behaviour (of it: ball rolling, opponent on it)",
          "cases with two kicks or more played to the end", "all cases played to the end",
          "wait-end safety net", "aborts per trial", "no case per trial (why)"};
}

std::vector<std::vector<std::string>> CbrPlayRows(const std::vector<CbrPlayRow>& rows) {
  std::vector<std::vector<std::string>> out;
  for (const CbrPlayRow& r : rows) {
    out.push_back({std::to_string(r.scenario), DefaultPlay(r),
                   Completion(r), Format("%d of %d", r.completed, r.retrieved),
                   std::to_string(r.wait_end_timeouts), Pairs(r.aborts, r.trials),
                   PerTrial(r.no_case, r.trials) + " (" + Pairs(r.no_case_why, r.trials) + ")"});
  }
  return out;
}

}  // namespace foresight
