#include "experiments/passing_report.h"

#include <algorithm>
#include <optional>
#include <string_view>

#include "experiments/passing_causes.h"
#include "report/report_format.h"

namespace foresight {

namespace {

using Json = nlohmann::ordered_json;

Json IntervalJson(const Interval& i) {
  return Json::array({i.low, i.high});
}

Json StatJson(const MeanStat& s) {
  if (s.n == 0) return nullptr;
  return {{"n", s.n}, {"mean", s.mean}, {"sd", s.sd}, {"mean_ci", IntervalJson(s.ci)}};
}

Json StatsJson(const std::vector<MeanStat>& stats, const std::vector<std::string>& names) {
  Json j = Json::object();
  for (std::size_t i = 0; i < stats.size(); ++i) j[names[i]] = StatJson(stats[i]);
  return j;
}

const std::vector<std::string> kAttackerNames = {"A", "B"};

Json TeamCountersJson(const ScenarioSummary& s) {
  Json j = Json::object();
  for (const auto& [name, stat] : s.team_counters) j[name] = StatJson(stat);
  return j;
}

Json SummaryJson(const ScenarioSummary& s, const PassingSetup& setup) {
  Json outcomes = Json::object();
  for (int k = 0; k < kTrialOutcomeCount; ++k) {
    const auto i = static_cast<std::size_t>(k);
    outcomes[std::string(TrialOutcomeName(static_cast<TrialOutcome>(k)))] = {
        {"count", s.counts[i]},
        {"share", static_cast<double>(s.counts[i]) / s.trials},
        {"share_ci", IntervalJson(s.shares_ci[i])}};
  }
  Json backups = Json::object();
  for (std::size_t i = 0; i < s.backups.size(); ++i) {
    backups[kAttackerNames[i]] = StatJson(s.backups[i]);
    backups[kAttackerNames[i]]["share"] = s.backup_share[i];
  }
  const std::vector<std::string> opponents = setup.config.OpponentNames();
  return {{"scenario", s.scenario},
          {"name", s.name},
          {"trials", s.trials},
          {"outcomes", outcomes},
          {"to_goal",
           {{"count", s.to_goal},
            {"share", static_cast<double>(s.to_goal) / s.trials},
            {"share_ci", IntervalJson(s.to_goal_ci)}}},
          {"possession", StatsJson(s.possession, opponents)},
          {"possession_without_timeouts", StatsJson(s.possession_ended, opponents)},
          {"opponent_kicks", StatsJson(s.opponent_kicks, opponents)},
          {"backups", backups},
          {"kicks_missed", s.kicks_missed},
          {"kicks_not_settled", s.kicks_not_settled},
          {"kicks_fell", s.kicks_fell},
          {"kicks_blocked", s.kicks_blocked},
          {"time_s", StatJson(s.time_s)},
          {"time_without_timeouts_s", StatJson(s.time_ended_s)},
          {"team_counters", TeamCountersJson(s)}};
}

}  // namespace

Json PassingCausesJson(const ScenarioCauses& c) {
  return {{"to_goal_by_attackers",
           {{"count", c.to_goal_by_attackers},
            {"share", c.trials > 0 ? static_cast<double>(c.to_goal_by_attackers) / c.trials : 0.0},
            {"share_ci", IntervalJson(c.to_goal_by_attackers_ci)}}},
          {"shots_on_target", c.shots_on_target},
          {"shots_saved", c.shots_saved},
          {"opponent_kicks_moved", c.opponent_kicks_moved},
          {"opponent_kicks_towards_own_goal", c.opponent_kicks_own_goal},
          {"opponent_kicks_towards_own_goal_share",
           {{"share", c.opponent_kicks_moved > 0
                          ? static_cast<double>(c.opponent_kicks_own_goal) / c.opponent_kicks_moved
                          : 0.0},
            {"share_ci", IntervalJson(c.opponent_kicks_own_goal_ci)}}},
          {"safety_cap_ended", c.safety_cap_ended},
          {"contests_resolved", c.contests_resolved},
          {"contests_resolved_per_trial",
           c.trials > 0 ? static_cast<double>(c.contests_resolved) / c.trials : 0.0},
          {"stuck_penalties", c.stuck_penalties}};
}

Json PassingJson(const PassingRun& run) {
  const PassingSetup& setup = *run.setup;
  Json inputs = InputsJson(run.provenance);
  Json scenarios = Json::array();
  for (int n : setup.scenarios) scenarios.push_back(n);
  inputs.update({{"scenarios", scenarios},
                 {"trials_per_scenario", setup.trials},
                 {"confidence", setup.params.confidence},
                 {"control_step_s", setup.sim.control_step_s},
                 {"time_limit_s", setup.config.time_limit_s},
                 {"time_limit_kind", setup.config.time_limit_is_safety_cap ? "safety_cap" : "timeout"},
                 {"kick_moved_min_m", setup.params.kick_moved_min_m}});
  const std::vector<ScenarioCauses> causes =
      SummariseCauses(run.result, setup, setup.params.confidence);
  Json summaries = Json::array();
  for (std::size_t i = 0; i < run.summaries.size(); ++i) {
    summaries.push_back(SummaryJson(run.summaries[i], setup));
    summaries.back()["causes"] = PassingCausesJson(causes[i]);
  }
  const RunProvenance& p = run.provenance;
  const ScenarioCauses pooled = PoolCauses(causes, setup.params.confidence);
  Json all_causes = PassingCausesJson(pooled);
  all_causes["trials"] = pooled.trials;
  return {{"experiment", "passing"}, {"version", p.version},   {"seed", p.seed},
          {"params", inputs},        {"scenarios", summaries}, {"causes_all_scenarios", all_causes},
          {"run_time_s", p.run_time_s}};
}

std::string PassingTrialsCsv(const PassingRun& run) {
  const std::vector<std::string> opponents = run.setup->config.OpponentNames();
  std::string csv = "scenario,trial,outcome,to_goal,time_s";
  for (const std::string& o : opponents) csv += ",touches_" + o + ",kicks_" + o;
  for (const std::string& a : kAttackerNames) csv += ",backups_" + a + ",kicks_" + a;
  csv +=
      ",grabs_failed,kicks_missed,kicks_not_settled,kicks_fell,kicks_blocked,last_touch,"
      "attacker_kick_sent,shots_on_target,shots_saved,contests_resolved,stuck_penalties\n";
  for (const ScenarioTrials& st : run.result.scenarios) {
    for (std::size_t i = 0; i < st.trials.size(); ++i) {
      const TrialCounters& c = st.trials[i].counters;
      csv += Format("%d,%zu,%s,%d,%.2f", st.scenario, i,
                    std::string(TrialOutcomeName(st.trials[i].outcome)).c_str(),
                    IsToGoal(st.trials[i].outcome) ? 1 : 0, c.time_s);
      for (std::size_t o = 0; o < c.opponent_touches.size(); ++o) {
        csv += Format(",%d,%d", c.opponent_touches[o], c.opponent_kicks[o]);
      }
      for (std::size_t a = 0; a < c.attacker_backups.size(); ++a) {
        csv += Format(",%d,%d", c.attacker_backups[a], c.attacker_kicks[a]);
      }
      const std::string last =
          c.last_touch_side < 0 ? ""
          : c.last_touch_side == static_cast<int>(Side::kAttackers)
              ? kAttackerNames[static_cast<std::size_t>(c.last_touch_robot)]
              : opponents[static_cast<std::size_t>(c.last_touch_robot)];
      csv += Format(",%d,%d,%d,%d,%d,%s,%d,%d,%d,%d,%d\n", c.grabs_failed, c.kicks_missed,
                    c.kicks_not_settled, c.kicks_fell, c.kicks_blocked, last.c_str(),
                    c.attacker_kick_sent ? 1 : 0, c.shots_on_target, c.shots_saved,
                    c.contests_resolved, c.stuck_penalties);
    }
  }
  return csv;
}

std::string PassingEventsCsv(const PassingRun& run) {
  const std::vector<std::string> opponents = run.setup->config.OpponentNames();
  std::string csv = "scenario,trial,time_s,event,robot,ball_x_m,ball_y_m,detail\n";
  for (const ScenarioTrials& st : run.result.scenarios) {
    for (std::size_t i = 0; i < st.trials.size(); ++i) {
      for (const MatchEvent& e : st.trials[i].events) {
        const std::string robot = e.kind == EventKind::kEnd ? ""
                                  : e.side == Side::kAttackers
                                      ? kAttackerNames[static_cast<std::size_t>(e.robot)]
                                      : opponents[static_cast<std::size_t>(e.robot)];
        csv += Format("%d,%zu,%.2f,%s,%s,%.3f,%.3f,%s\n", st.scenario, i, e.time_s,
                      std::string(EventKindName(e.kind)).c_str(), robot.c_str(), e.p_F_ball.x(),
                      e.p_F_ball.y(), e.detail.c_str());
      }
    }
  }
  return csv;
}

namespace {

// The mean per trial of the team's counter `name`, or nullopt if the team does not count it.
std::optional<double> CounterMean(const ScenarioSummary& s, std::string_view name) {
  for (const auto& [counter, stat] : s.team_counters) {
    if (counter == name) return stat.mean;
  }
  return std::nullopt;
}

}  // namespace

std::string TeamCountersText(const std::vector<ScenarioSummary>& summaries) {
  // Ros et al. 2009, Table 3 (cases per trial, individualistic and cooperative) and what the
  // paper calls "not significant" (sec. 5.4: the default behaviour, i.e. no case), with the
  // aborts by reason and the seconds of trial per case retrieved.
  const char* const kColumns[] = {"cases_individual", "cases_cooperative", "no_case", "race_lost",
                                  "aborts_ball_lost", "aborts_ball_moved", "aborts_path_blocked",
                                  "aborts_timeout"};
  if (summaries.empty() || !CounterMean(summaries.front(), "cases_retrieved")) return "";
  std::string text =
      "per trial    indiv.  coop. | no case race lost | aborts: ball lost, moved, path blocked, "
      "timeout | s per case\n";
  for (const ScenarioSummary& s : summaries) {
    std::vector<double> v;
    for (const char* name : kColumns) v.push_back(CounterMean(s, name).value_or(0.0));
    const double cases = CounterMean(s, "cases_retrieved").value_or(0.0);
    text += Format("%-10s %7.2f %6.2f | %7.2f %9.2f | %16.2f %6.2f %13.2f %8.2f | %s\n",
                   s.name.c_str(), v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7],
                   cases > 0.0 ? Format("%.2f", s.time_s.mean / cases).c_str() : "-");
  }
  return text;
}

std::string PassingText(const PassingRun& run) {
  const PassingSetup& setup = *run.setup;
  std::string text = Format("passing: %s team against %s, %d trials per scenario%s\n",
                            run.team.c_str(), setup.config.name.c_str(), setup.trials,
                            setup.mirrored ? " (mirrored: attacking -x)" : "");
  text +=
      "scenario  goal close block  out  p.area timeout | to goal | possession (per opp.) | time "
      "s\n";
  for (const ScenarioSummary& s : run.summaries) {
    auto pct = [&](TrialOutcome o) {
      return 100.0 * s.counts[static_cast<std::size_t>(o)] / s.trials;
    };
    text += Format("%-8s %5.1f %5.1f %5.1f %5.1f %5.1f %5.1f   | %5.1f   |", s.name.c_str(),
                   pct(TrialOutcome::kGoal), pct(TrialOutcome::kClose), pct(TrialOutcome::kBlock),
                   pct(TrialOutcome::kOut), pct(TrialOutcome::kPenaltyArea),
                   pct(TrialOutcome::kTimeout), 100.0 * s.to_goal / s.trials);
    for (const MeanStat& m : s.possession) text += Format(" %.2f (%.2f)", m.mean, m.sd);
    text += Format(" | %.2f\n", s.time_s.mean);
  }
  text += Format(
      "scenario  to goal by attackers | shots on target, saved | opponents' kicks >= %.2g m, "
      "towards own goal%s\n",
      setup.params.kick_moved_min_m, setup.config.time_limit_is_safety_cap ? " | safety cap" : "");
  const std::vector<ScenarioCauses> causes =
      SummariseCauses(run.result, setup, setup.params.confidence);
  auto row = [&](const std::string& name, const ScenarioCauses& c) {
    const double own_pct =
        c.opponent_kicks_moved > 0 ? 100.0 * c.opponent_kicks_own_goal / c.opponent_kicks_moved : 0.0;
    text += Format("%-8s %5.1f %%              | %4d, %4d             | %5d, %4d (%.1f %%, %.1f-%.1f)",
                   name.c_str(), c.trials > 0 ? 100.0 * c.to_goal_by_attackers / c.trials : 0.0,
                   c.shots_on_target, c.shots_saved, c.opponent_kicks_moved,
                   c.opponent_kicks_own_goal, own_pct, 100.0 * c.opponent_kicks_own_goal_ci.low,
                   100.0 * c.opponent_kicks_own_goal_ci.high);
    if (setup.config.time_limit_is_safety_cap) text += Format(" | %d", c.safety_cap_ended);
    text += "\n";
  };
  for (std::size_t i = 0; i < causes.size(); ++i) row(run.result.scenarios[i].name, causes[i]);
  if (causes.size() > 1) row("all", PoolCauses(causes, setup.params.confidence));
  text += TeamCountersText(run.summaries);
  return text;
}

}  // namespace foresight
