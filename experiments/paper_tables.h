// The paper's simulation results as data (models/experiments/ros2009_tables.json): Tables 1-5 of
// Ros, Arcos, Lopez de Mantaras and Veloso, "A case-based approach for coordinated action
// selection in robot soccer", Artificial Intelligence 173 (2009) 1014-1039, sec. 5.2, each cell
// as printed, with its source; and the paper's claims for CBR against the reactive team, each
// naming the columns it compares per configuration. A claim's expected direction per scenario is
// not stored: it is the sign of the paper's CBR minus reactive (PaperClaimValue), so the file
// holds every figure once. The reproduction scorecard (experiments/passing_scorecard.h) sets our
// runs beside it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace foresight {

// A cell's statistic: a share in %, a mean per trial, or a standard deviation per trial.
enum class PaperStat { kPct, kAvg, kSd };
std::string PaperStatName(PaperStat stat);

// One column. Measures: the outcome classes "goal", "close", "block", "out", "to_goal",
// "timeout" (pct); "touches" and "touches_without_timeouts" of an opponent `robot` (avg, sd);
// "backups" of attacker `robot` A or B (avg; pct: its share of the team's backing-ups);
// "cases_individual", "cases_cooperative" (avg; pct: share of the two); "time_s" and
// "time_without_timeouts_s" (avg).
struct PaperColumn {
  std::string measure;
  std::string robot;  // empty unless the measure is per robot
  PaperStat stat = PaperStat::kAvg;

  std::string Label() const;  // "touches D avg", "to_goal %"
};

struct PaperRow {
  int scenario = 0;  // 1-based
  std::string team;  // "cbr" or "reactive"
  std::vector<double> values;  // one per column
};

struct PaperTable {
  int table = 0;  // the paper's table number
  std::string config;  // the match configuration it reports, MatchConfig::name ("dg", "2d")
  std::string source;
  std::string caption;
  std::vector<PaperColumn> columns;
  std::vector<PaperRow> rows;

  const PaperRow* Row(int scenario, const std::string& team) const;
  // The column of `measure` (and `robot`) that is a share or a mean, not an sd.
  std::optional<std::size_t> ValueColumn(const std::string& measure,
                                         const std::string& robot) const;
};

// One compared quantity of a claim: a column of a table, by measure and robot.
struct PaperTerm {
  int table = 0;
  std::string measure;
  std::string robot;
};

// CBR against reactive on the sum of `terms` of a configuration's tables.
struct PaperClaim {
  std::string name;
  std::string statement;
  std::string source;
  std::vector<std::pair<std::string, std::vector<PaperTerm>>> terms;  // per config

  const std::vector<PaperTerm>* Terms(const std::string& config) const;  // null if none
};

// The world check (experiments/world_check.h): one team's rows of the paper's tables test the
// simulated world without the method under test. Per configuration, the outcome shares
// (`measures`, pct columns) whose agreement judges a scenario: the paper's value inside our
// interval, or within `within_points` percentage points of ours.
struct WorldCheckSpec {
  std::string team;
  double within_points = 0.0;
  std::vector<std::pair<std::string, std::vector<std::string>>> measures;  // per config

  const std::vector<std::string>* Measures(const std::string& config) const;  // null if none
};

struct PaperTables {
  std::filesystem::path file;
  std::string article;
  std::vector<PaperTable> tables;
  std::vector<PaperClaim> claims;
  WorldCheckSpec world_check;

  const PaperTable* Table(int number) const;
  // Every row's values match its columns and lie in range (shares in [0, 100], means and sds
  // >= 0), a table holds a (scenario, team) once, and every claim term names a value column of a
  // table of its configuration; every world-check measure names a share column of a table of its
  // configuration with rows of the check's team.
  void Validate() const;
};

// `reference`: a bare name in MODELS/experiments ("ros2009_tables") or a path to a .json file.
PaperTables LoadPaperTables(const std::string& reference, const std::filesystem::path& models_dir);

// The paper's value of a claim for `team` in `scenario`: the sum of its terms' cells; nothing
// when the configuration has no terms or a cell is missing.
std::optional<double> PaperClaimValue(const PaperTables& paper, const PaperClaim& claim,
                                      const std::string& config, int scenario,
                                      const std::string& team);

}  // namespace foresight
