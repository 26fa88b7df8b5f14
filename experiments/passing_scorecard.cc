#include "experiments/passing_scorecard.h"

#include <algorithm>

#include "experiments/passing_comparison.h"

namespace foresight {

namespace {

constexpr double kPercent = 100.0;

bool WithoutTimeouts(const std::string& measure) {
  return measure.find("without_timeouts") != std::string::npos;
}

std::optional<std::size_t> IndexOf(const std::vector<std::string>& names,
                                   const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<std::size_t>(it - names.begin());
}

std::optional<TrialOutcome> OutcomeNamed(const std::string& name) {
  for (int k = 0; k < kTrialOutcomeCount; ++k) {
    const auto o = static_cast<TrialOutcome>(k);
    if (TrialOutcomeName(o) == name) return o;
  }
  return std::nullopt;
}

const std::vector<std::string> kAttackers = {"A", "B"};

const MeanStat* TeamCounter(const ScenarioSummary& s, const std::string& name) {
  for (const auto& [counter, stat] : s.team_counters) {
    if (counter == name) return &stat;
  }
  return nullptr;
}

ScorecardCell MeanCell(double paper, const MeanStat& m, PaperStat stat) {
  ScorecardCell cell{paper, {}, {}, {}};
  if (m.n == 0) return cell;
  cell.ours = stat == PaperStat::kSd ? m.sd : m.mean;
  if (stat == PaperStat::kAvg && m.n >= 2) cell.ci = m.ci;
  return cell;
}

ScorecardCell ShareCell(double paper, int count, int trials, const Interval& ci) {
  ScorecardCell cell{paper, {}, {}, {}};
  if (trials == 0) return cell;
  cell.ours = kPercent * count / trials;
  cell.ci = Interval{kPercent * ci.low, kPercent * ci.high};
  return cell;
}

// Our value of one paper cell from a team's summary of the row's scenario.
ScorecardCell OurCell(const PaperColumn& col, double paper, const ScenarioSummary& s,
                      const PassingSetup& setup) {
  ScorecardCell none{paper, {}, {}, {}};
  if (const std::optional<TrialOutcome> o = OutcomeNamed(col.measure)) {
    const auto k = static_cast<std::size_t>(*o);
    return ShareCell(paper, s.counts[k], s.trials, s.shares_ci[k]);
  }
  if (col.measure == "to_goal") return ShareCell(paper, s.to_goal, s.trials, s.to_goal_ci);
  if (col.measure == "time_s") return MeanCell(paper, s.time_s, col.stat);
  if (col.measure == "time_without_timeouts_s") return MeanCell(paper, s.time_ended_s, col.stat);
  if (col.measure == "touches" || col.measure == "touches_without_timeouts") {
    const auto o = IndexOf(setup.config.OpponentNames(), col.robot);
    const auto& stats = col.measure == "touches" ? s.possession : s.possession_ended;
    if (!o || *o >= stats.size()) return none;
    return MeanCell(paper, stats[*o], col.stat);
  }
  if (col.measure == "backups") {
    const auto a = IndexOf(kAttackers, col.robot);
    if (!a || *a >= s.backups.size()) return none;
    if (col.stat == PaperStat::kAvg) return MeanCell(paper, s.backups[*a], col.stat);
    none.ours = kPercent * s.backup_share[*a];
    return none;
  }
  const MeanStat* individual = TeamCounter(s, "cases_individual");
  const MeanStat* cooperative = TeamCounter(s, "cases_cooperative");
  if (individual == nullptr || cooperative == nullptr) return none;
  const MeanStat& own = col.measure == "cases_individual" ? *individual : *cooperative;
  if (col.stat == PaperStat::kAvg) return MeanCell(paper, own, col.stat);
  const double total = individual->mean + cooperative->mean;
  if (total > 0.0) none.ours = kPercent * own.mean / total;
  return none;
}

const ScenarioSummary* SummaryOf(const PassingRun& run, int scenario) {
  for (const ScenarioSummary& s : run.summaries) {
    if (s.scenario == scenario) return &s;
  }
  return nullptr;
}

ScorecardTable BuildTable(const PaperTable& t, const PassingRun& cbr, const PassingRun& reactive) {
  ScorecardTable out{t.table, t.source, t.caption, {}, {}, 0, 0};
  for (const PaperColumn& c : t.columns) out.columns.push_back(c.Label());
  for (const PaperRow& r : t.rows) {
    const PassingRun& run = r.team == "cbr" ? cbr : reactive;
    const ScenarioSummary* s = SummaryOf(run, r.scenario);
    ScorecardRow row{r.scenario, r.team, s ? s->trials : 0, {}};
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      ScorecardCell cell = s ? OurCell(t.columns[c], r.values[c], *s, *run.setup)
                             : ScorecardCell{r.values[c], {}, {}, {}};
      if (cell.ci) {
        cell.inside = cell.ci->low <= cell.paper && cell.paper <= cell.ci->high;
        ++out.judged;
        out.inside += *cell.inside;
      }
      row.cells.push_back(cell);
    }
    out.rows.push_back(std::move(row));
  }
  return out;
}

// One trial's value of a claim term, in the paper's units (a share in %: 100 or 0 per trial).
double TermValue(const PaperTerm& term, const std::vector<std::string>& opponents,
                 const MatchTrialResult& t) {
  if (const std::optional<TrialOutcome> o = OutcomeNamed(term.measure)) {
    return t.outcome == *o ? kPercent : 0.0;
  }
  if (term.measure == "to_goal") return IsToGoal(t.outcome) ? kPercent : 0.0;
  if (term.measure == "time_s" || term.measure == "time_without_timeouts_s") {
    return t.counters.time_s;
  }
  if (term.measure == "touches" || term.measure == "touches_without_timeouts") {
    const auto o = IndexOf(opponents, term.robot);
    return o ? t.counters.opponent_touches[*o] : 0.0;
  }
  return 0.0;  // Validate admits no other claim measure the tally uses (see paper_tables.h)
}

ClaimTally BuildClaim(const PaperTables& paper, const PaperClaim& claim, const PassingRun& cbr,
                      const PassingRun& reactive) {
  const PassingSetup& setup = *cbr.setup;
  const std::vector<PaperTerm>& terms = *claim.Terms(setup.config.name);
  ClaimTally tally{claim.name, claim.statement, "", false, {}, 0, 0, 0};
  for (const PaperTerm& term : terms) {
    if (!tally.compared.empty()) tally.compared += " + ";
    tally.compared += term.measure + (term.robot.empty() ? "" : " " + term.robot);
    tally.without_timeouts = tally.without_timeouts || WithoutTimeouts(term.measure);
  }
  const std::vector<std::string> opponents = setup.config.OpponentNames();
  const auto value = [&](const MatchTrialResult& t) {
    double sum = 0.0;
    for (const PaperTerm& term : terms) sum += TermValue(term, opponents, t);
    return sum;
  };
  for (const PaperTable& t : paper.tables) {
    if (t.table != terms.front().table) continue;
    for (const PaperRow& row : t.rows) {
      if (row.team != "cbr") continue;
      const auto paper_cbr = PaperClaimValue(paper, claim, setup.config.name, row.scenario, "cbr");
      const auto paper_reactive =
          PaperClaimValue(paper, claim, setup.config.name, row.scenario, "reactive");
      if (!paper_cbr || !paper_reactive) continue;
      ClaimScenario cs;
      cs.scenario = row.scenario;
      cs.paper_cbr = *paper_cbr;
      cs.paper_reactive = *paper_reactive;
      cs.paper_direction = (cs.paper_cbr > cs.paper_reactive) - (cs.paper_cbr < cs.paper_reactive);
      for (std::size_t s = 0; s < cbr.result.scenarios.size(); ++s) {
        if (cbr.result.scenarios[s].scenario != row.scenario) continue;
        cs.difference = PairTrials(cbr.result.scenarios[s], reactive.result.scenarios[s], value,
                                   tally.without_timeouts, setup.params.confidence);
        cs.verdict = JudgeClaim(cs.paper_direction, cs.difference);
      }
      tally.holds += cs.verdict == ClaimVerdict::kHolds;
      tally.opposite += cs.verdict == ClaimVerdict::kOpposite;
      tally.unclear += cs.verdict == ClaimVerdict::kNoClearDifference;
      tally.scenarios.push_back(cs);
    }
  }
  return tally;
}

// The team's rows of the world section: each scenario, then all of them pooled.
void AddWorldRows(const PassingRun& run, std::vector<ScorecardWorldRow>& rows) {
  const PassingSetup& setup = *run.setup;
  const std::vector<ScenarioCauses> causes =
      SummariseCauses(run.result, setup, setup.params.confidence);
  ScorecardWorldRow all{run.team, 0, PoolCauses(causes, setup.params.confidence)};
  for (std::size_t i = 0; i < causes.size(); ++i) {
    rows.push_back({run.team, run.summaries[i].to_goal, causes[i]});
    all.to_goal += run.summaries[i].to_goal;
  }
  rows.push_back(all);
}

}  // namespace

std::string ClaimVerdictName(ClaimVerdict verdict) {
  switch (verdict) {
    case ClaimVerdict::kHolds:
      return "holds";
    case ClaimVerdict::kOpposite:
      return "opposite";
    case ClaimVerdict::kNoClearDifference:
      return "no clear difference";
    case ClaimVerdict::kNotPlayed:
      return "not played";
  }
  return "";
}

ClaimVerdict JudgeClaim(int paper_direction, const MeanStat& difference) {
  if (difference.n < 2 || paper_direction == 0) return ClaimVerdict::kNoClearDifference;
  const Interval& ci = difference.ci;
  const int ours = (ci.low > 0.0) - (ci.high < 0.0);
  if (ours == 0) return ClaimVerdict::kNoClearDifference;
  return ours == paper_direction ? ClaimVerdict::kHolds : ClaimVerdict::kOpposite;
}

PassingScorecard BuildPassingScorecard(const PaperTables& paper, const std::string& paper_file,
                                       const PassingRun& cbr, const PassingRun& reactive) {
  const PassingSetup& setup = *cbr.setup;
  PassingScorecard card;
  card.config = setup.config.name;
  card.paper_file = paper_file;
  card.article = paper.article;
  card.kicks = cbr.provenance.Input("kicks");
  card.executor = cbr.provenance.Input("executor");
  card.version = cbr.provenance.version;
  card.seed = cbr.provenance.seed;
  card.confidence = setup.params.confidence;
  card.trials = setup.trials;
  for (const PaperTable& t : paper.tables) {
    if (t.config == card.config) card.tables.push_back(BuildTable(t, cbr, reactive));
  }
  for (const PaperClaim& c : paper.claims) {
    const std::vector<PaperTerm>* terms = c.Terms(card.config);
    if (terms != nullptr && !terms->empty()) {
      card.claims.push_back(BuildClaim(paper, c, cbr, reactive));
    }
  }
  card.kick_moved_min_m = setup.params.kick_moved_min_m;
  card.has_goalie = setup.config.HasGoalie();
  card.goalie = card.has_goalie ? std::string(GoalieModelName(setup.config.goalie.model)) : "none";
  card.world_check = BuildWorldCheck(paper, card.tables, card.config);
  card.cbr_play = BuildCbrPlay(cbr);
  AddWorldRows(cbr, card.world);
  AddWorldRows(reactive, card.world);
  return card;
}

}  // namespace foresight
