#include "experiments/passing_scorecard_report.h"

#include "experiments/passing_report.h"
#include "report/html_report.h"
#include "report/report_format.h"

namespace foresight {

namespace {

using Json = nlohmann::ordered_json;

constexpr double kPercentOf = 100.0;

int Decimals(const std::string& column) {
  return !column.empty() && column.back() == '%' ? 1 : 2;
}

std::string Value(const std::optional<double>& v, int decimals) {
  return v ? Fixed(*v, decimals) : std::string("-");
}

std::string IntervalText(const std::optional<Interval>& ci, int decimals) {
  if (!ci) return "-";
  return Format("[%s, %s]", Fixed(ci->low, decimals).c_str(), Fixed(ci->high, decimals).c_str());
}

std::string InsideText(const std::optional<bool>& inside) {
  return inside ? (*inside ? "inside" : "outside") : std::string("not judged");
}

std::string Direction(int sign) {
  return sign > 0 ? "cbr higher" : sign < 0 ? "cbr lower" : "equal";
}

// A paper's figure as printed: no trailing zeros ("25", "1.34", "49.5").
std::string PaperValue(double value) {
  return Format("%g", value);
}

std::string TableNumbers(const PassingScorecard& card) {
  std::string numbers;
  for (const ScorecardTable& t : card.tables) {
    numbers += (numbers.empty() ? "" : ", ") + std::to_string(t.table);
  }
  return numbers;
}

std::string Percent(double confidence) {
  return Fixed(kPercentOf * confidence, 0) + " %";
}

Json CellJson(const std::string& column, const ScorecardCell& c) {
  Json j = {{"column", column}, {"paper", c.paper}};
  j["ours"] = c.ours ? Json(*c.ours) : Json(nullptr);
  j["ours_ci"] = c.ci ? Json::array({c.ci->low, c.ci->high}) : Json(nullptr);
  j["paper_inside"] = c.inside ? Json(*c.inside) : Json(nullptr);
  return j;
}

Json TableJson(const ScorecardTable& t) {
  Json rows = Json::array();
  for (const ScorecardRow& r : t.rows) {
    Json cells = Json::array();
    for (std::size_t c = 0; c < r.cells.size(); ++c) cells.push_back(CellJson(t.columns[c], r.cells[c]));
    rows.push_back({{"scenario", r.scenario}, {"team", r.team}, {"trials", r.trials},
                    {"cells", cells}});
  }
  return {{"table", t.table},         {"source", t.source},
          {"caption", t.caption},     {"cells_judged", t.judged},
          {"paper_inside_ours", t.inside}, {"rows", rows}};
}

Json ClaimJson(const ClaimTally& c) {
  Json scenarios = Json::array();
  for (const ClaimScenario& s : c.scenarios) {
    scenarios.push_back(
        {{"scenario", s.scenario},
         {"paper_cbr", s.paper_cbr},
         {"paper_reactive", s.paper_reactive},
         {"paper_direction", Direction(s.paper_direction)},
         {"pairs", s.difference.n},
         {"difference", s.difference.n > 0 ? Json(s.difference.mean) : Json(nullptr)},
         {"difference_ci", s.difference.n > 1
                               ? Json::array({s.difference.ci.low, s.difference.ci.high})
                               : Json(nullptr)},
         {"verdict", ClaimVerdictName(s.verdict)}});
  }
  return {{"name", c.name},
          {"statement", c.statement},
          {"compared", c.compared},
          {"timeouts_left_out", c.without_timeouts},
          {"holds", c.holds},
          {"opposite", c.opposite},
          {"no_clear_difference", c.unclear},
          {"scenarios", scenarios}};
}

std::string ClaimLine(const ClaimTally& c) {
  std::string line = Format("  %-27s holds in %d of %zu:", c.name.c_str(), c.holds,
                            c.scenarios.size());
  for (const ClaimScenario& s : c.scenarios) {
    line += Format(" s%d %s", s.scenario, ClaimVerdictName(s.verdict).c_str());
    if (s.difference.n > 1) {
      line += Format(" (%+.2f [%+.2f, %+.2f])", s.difference.mean, s.difference.ci.low,
                     s.difference.ci.high);
    }
    line += ";";
  }
  return line + "\n";
}

std::vector<std::pair<std::string, std::string>> Header(const PassingScorecard& card) {
  return {{"configuration", card.config},
          {"paper", card.article},
          {"paper's figures", card.paper_file},
          {"kick model", card.kicks},
          {"executor", card.executor},
          {"goalie", card.goalie},
          {"trials per scenario and team", std::to_string(card.trials)},
          {"our intervals", Percent(card.confidence) + " (shares Wilson, means Student t)"},
          {"seed", std::to_string(card.seed)},
          {"version", card.version}};
}

void ClaimsHtml(HtmlReport& html, const PassingScorecard& card) {
  html.Heading(2, "The paper's claims, CBR against reactive");
  html.Paragraph(
      "A claim holds in a scenario when our paired " + Percent(card.confidence) +
      " interval of CBR minus reactive excludes 0 on the side of the paper's own difference in "
      "that scenario; opposite when it excludes 0 on the other side. Shares are in percentage "
      "points, touches per trial, times in s.");
  std::vector<std::string> header = {"claim", "compared", "holds"};
  std::vector<std::vector<std::string>> rows;
  for (const ClaimTally& c : card.claims) {
    std::vector<std::string> row = {c.name, c.compared + (c.without_timeouts ? " (timeouts left out)" : ""),
                                    std::to_string(c.holds) + " of " +
                                        std::to_string(c.scenarios.size())};
    for (const ClaimScenario& s : c.scenarios) {
      if (&c == &card.claims.front()) header.push_back("scenario " + std::to_string(s.scenario));
      row.push_back(ClaimVerdictName(s.verdict) + ": paper " + PaperValue(s.paper_cbr) + " vs " +
                    PaperValue(s.paper_reactive) + ", ours " +
                    (s.difference.n > 1 ? Format("%+.2f [%+.2f, %+.2f]", s.difference.mean,
                                                 s.difference.ci.low, s.difference.ci.high)
                                        : std::string("-")));
    }
    rows.push_back(std::move(row));
  }
  html.Table(header, rows);
}

void WorldCheckHtml(HtmlReport& html, const PassingScorecard& card) {
  const WorldCheck& w = card.world_check;
  html.Heading(2, "The world against the paper's " + w.team + " rows");
  std::string measures;
  for (const std::string& m : w.measures) measures += (measures.empty() ? "" : ", ") + m;
  html.Paragraph(
      "The " + w.team + " team is built from the paper's description of it, not from the method "
      "under test, so its rows test the simulated world. A scenario agrees when each of " +
      measures + " lies inside our " + Percent(card.confidence) + " interval or within " +
      Format("%g", w.within_points) + " percentage points of ours; " +
      std::to_string(w.agreeing) + " of " + std::to_string(w.scenarios.size()) +
      " scenarios agree. Goalie: " + card.goalie + ".");
  html.Table({"scenario", "trials", "verdict"}, WorldCheckScenarioRows(w));
  html.Table({"scenario", "table", "measure", "paper", "ours", "our interval", "verdict"},
             WorldCheckCellRows(w));
}

void TableHtml(HtmlReport& html, const ScorecardTable& t) {
  html.Heading(2, "Table " + std::to_string(t.table) + ": " + t.caption);
  html.Paragraph(t.source + ". The paper's value lies inside our interval in " +
                 std::to_string(t.inside) + " of " + std::to_string(t.judged) +
                 " judged cells (sds and shares of a team's total have no interval).");
  std::vector<std::vector<std::string>> rows;
  for (const ScorecardRow& r : t.rows) {
    for (std::size_t c = 0; c < r.cells.size(); ++c) {
      const ScorecardCell& cell = r.cells[c];
      const int d = Decimals(t.columns[c]);
      rows.push_back({std::to_string(r.scenario), r.team, t.columns[c], PaperValue(cell.paper),
                      Value(cell.ours, d), IntervalText(cell.ci, d), InsideText(cell.inside)});
    }
  }
  html.Table({"scenario", "team", "measure", "paper", "ours", "our interval", "paper's value"},
             rows);
}

std::string ScenarioName(int scenario) {
  return scenario == 0 ? std::string("all") : Format("s%d", scenario);
}

std::string ShareText(int count, int of, const Interval& ci) {
  if (of == 0) return "-";
  return Format("%.1f %% [%.1f, %.1f]", kPercentOf * count / of, kPercentOf * ci.low,
                kPercentOf * ci.high);
}

// "saved S of N", or "no goalie, N on target" where the opponents have none to save them.
std::string SavedText(const PassingScorecard& card, const ScenarioCauses& c) {
  if (!card.has_goalie) return Format("no goalie, %d on target", c.shots_on_target);
  return Format("saved %d of %d", c.shots_saved, c.shots_on_target);
}

Json WorldJson(const PassingScorecard& card) {
  Json rows = Json::array();
  for (const ScorecardWorldRow& w : card.world) {
    Json row = {{"team", w.team},
                {"scenario", w.causes.scenario},
                {"trials", w.causes.trials},
                {"to_goal", w.to_goal}};
    row.update(PassingCausesJson(w.causes));
    rows.push_back(row);
  }
  return {{"kick_moved_min_m", card.kick_moved_min_m},
          {"opponents_have_goalie", card.has_goalie},
          {"rows", rows}};
}

const char* kWorldDefinitions =
    "to goal by the attackers: a to-goal trial whose last kick was an attacker's with no "
    "opponent touching the ball after it. Saved: an attacker's shot on target (its unobstructed "
    "roll would have entered the goal) that the goalie touched before its travel ended, the "
    "paper's block (sec. 5.1.4). Opponents' long kicks: kicks that moved the ball at least the "
    "stated distance before it rested, met a body, was grabbed or the trial ended; towards their "
    "own goal when the displacement has any component towards it. Contests the referee ended: a "
    "ball robots of both teams fought over within grabbing reach for longer than the "
    "ball-holding rule allows, set down clear of every robot. Local game stuck: the league's "
    "call on the robot closest to a ball that did not move for the rule's time, penalised at "
    "the touchline (match/match.h).";

std::string WorldText(const PassingScorecard& card) {
  std::string text = Format(
      "the world (to goal by the attackers; on-target shots saved; opponents' kicks >= %.2g m "
      "towards their own goal; safety cap; contests the referee ended; local game stuck):\n",
      card.kick_moved_min_m);
  for (const ScorecardWorldRow& w : card.world) {
    const ScenarioCauses& c = w.causes;
    text += Format("  %-3s %-8s to goal %d, by the attackers %s | %s | %d of %d, %s | %d | %d | %d\n",
                   ScenarioName(c.scenario).c_str(), w.team.c_str(), w.to_goal,
                   ShareText(c.to_goal_by_attackers, c.trials, c.to_goal_by_attackers_ci).c_str(),
                   SavedText(card, c).c_str(), c.opponent_kicks_own_goal,
                   c.opponent_kicks_moved,
                   ShareText(c.opponent_kicks_own_goal, c.opponent_kicks_moved,
                             c.opponent_kicks_own_goal_ci)
                       .c_str(),
                   c.safety_cap_ended, c.contests_resolved, c.stuck_penalties);
  }
  return text;
}

void WorldHtml(HtmlReport& html, const PassingScorecard& card) {
  html.Heading(2, "What the world did");
  html.Paragraph(std::string(kWorldDefinitions) + " Long kicks here: at least " +
                 Format("%.2g", card.kick_moved_min_m) + " m; intervals " +
                 Percent(card.confidence) + " Wilson; \"all\" pools the scenarios.");
  std::vector<std::vector<std::string>> rows;
  for (const ScorecardWorldRow& w : card.world) {
    const ScenarioCauses& c = w.causes;
    rows.push_back(
        {ScenarioName(c.scenario), w.team, std::to_string(c.trials), std::to_string(w.to_goal),
         ShareText(c.to_goal_by_attackers, c.trials, c.to_goal_by_attackers_ci),
         SavedText(card, c),
         std::to_string(c.opponent_kicks_own_goal) + " of " +
             std::to_string(c.opponent_kicks_moved) + ": " +
             ShareText(c.opponent_kicks_own_goal, c.opponent_kicks_moved,
                       c.opponent_kicks_own_goal_ci),
         std::to_string(c.safety_cap_ended),
         Format("%d (%.2f per trial)", c.contests_resolved,
                c.trials > 0 ? static_cast<double>(c.contests_resolved) / c.trials : 0.0),
         std::to_string(c.stuck_penalties)});
  }
  html.Table({"scenario", "team", "trials", "to goal", "to goal by the attackers (share of trials)",
              "on-target shots saved", "opponents' long kicks towards their own goal",
              "ended by the safety cap", "contests the referee ended", "local game stuck"},
             rows);
}

}  // namespace

Json PassingScorecardJson(const PassingScorecard& card) {
  Json tables = Json::array();
  for (const ScorecardTable& t : card.tables) tables.push_back(TableJson(t));
  Json claims = Json::array();
  for (const ClaimTally& c : card.claims) claims.push_back(ClaimJson(c));
  return {{"experiment", "passing_scorecard"},
          {"version", card.version},
          {"seed", card.seed},
          {"config", card.config},
          {"paper", {{"file", card.paper_file}, {"article", card.article}}},
          {"kicks", card.kicks},
          {"executor", card.executor},
          {"goalie", card.goalie},
          {"trials_per_scenario", card.trials},
          {"confidence", card.confidence},
          {"tables", tables},
          {"claims", claims},
          {"world", WorldJson(card)},
          {"world_check", WorldCheckJson(card.world_check)},
          {"cbr_play", CbrPlayJson(card.cbr_play)}};
}

std::string PassingScorecardText(const PassingScorecard& card) {
  std::string text = Format(
      "scorecard against Ros et al. 2009 (%s), %s, kicks %s, %s executor, %d trials per "
      "scenario and team, %s intervals:\n",
      card.paper_file.c_str(), card.config.c_str(), card.kicks.c_str(), card.executor.c_str(),
      card.trials, Percent(card.confidence).c_str());
  for (const ScorecardTable& t : card.tables) {
    text += Format("Table %d: paper inside our interval in %d of %d judged cells\n", t.table,
                   t.inside, t.judged);
    for (const ScorecardRow& r : t.rows) {
      text += Format("  s%d %-8s", r.scenario, r.team.c_str());
      for (std::size_t c = 0; c < r.cells.size(); ++c) {
        const ScorecardCell& cell = r.cells[c];
        const int d = Decimals(t.columns[c]);
        text += Format(" | %s %s: %s %s", t.columns[c].c_str(), PaperValue(cell.paper).c_str(),
                       Value(cell.ours, d).c_str(), IntervalText(cell.ci, d).c_str());
        if (cell.inside && !*cell.inside) text += " out";
      }
      text += "\n";
    }
  }
  text += "claims (CBR - reactive, paired):\n";
  for (const ClaimTally& c : card.claims) text += ClaimLine(c);
  return text + CbrPlayText(card.cbr_play) + WorldCheckText(card.world_check) + WorldText(card);
}

std::string PassingScorecardHtml(const PassingScorecard& card) {
  HtmlReport html("Reproduction scorecard: passing, " + card.config + " (Ros et al. 2009, Tables " +
                  TableNumbers(card) + ")");
  html.KeyValues(Header(card));
  WorldCheckHtml(html, card);
  ClaimsHtml(html, card);
  if (!card.cbr_play.empty()) {
    html.Heading(2, "How the CBR team played");
    html.Paragraph(
        "From the team's own counters: the robots' time in the default behaviour (idle and "
        "waiting for a case; the paper calls it not significant, sec. 5.4) and of it the time "
        "the ball rolled faster than the robots walk and an opponent touched it, the cases whose "
        "robots kick twice or more between them that were played until every robot finished "
        "(sec. 4.2; " + Percent(card.confidence) + " Wilson interval), the wait-end safety net "
        "(a robot that stopped waiting for a teammate still executing), aborts by reason and why "
        "a retrieval found no case, per trial.");
    html.Table(CbrPlayColumns(), CbrPlayRows(card.cbr_play));
  }
  WorldHtml(html, card);
  for (const ScorecardTable& t : card.tables) TableHtml(html, t);
  return html.Finish();
}

}  // namespace foresight
