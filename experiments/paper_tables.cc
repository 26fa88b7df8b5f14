#include "experiments/paper_tables.h"

#include <algorithm>
#include <set>

#include "common/checks.h"
#include "common/error.h"
#include "common/json_reader.h"
#include "models/model_paths.h"

namespace foresight {

namespace {

struct MeasureRule {
  const char* measure;
  bool per_robot;
  std::vector<PaperStat> stats;
};

// The measures the scorecard can set beside a cell (PaperColumn's comment).
const std::vector<MeasureRule>& MeasureRules() {
  using S = PaperStat;
  static const std::vector<MeasureRule> rules = {
      {"goal", false, {S::kPct}},
      {"close", false, {S::kPct}},
      {"block", false, {S::kPct}},
      {"out", false, {S::kPct}},
      {"to_goal", false, {S::kPct}},
      {"timeout", false, {S::kPct}},
      {"touches", true, {S::kAvg, S::kSd}},
      {"touches_without_timeouts", true, {S::kAvg, S::kSd}},
      {"backups", true, {S::kAvg, S::kPct}},
      {"cases_individual", false, {S::kAvg, S::kPct}},
      {"cases_cooperative", false, {S::kAvg, S::kPct}},
      {"time_s", false, {S::kAvg}},
      {"time_without_timeouts_s", false, {S::kAvg}},
  };
  return rules;
}

PaperStat ParseStat(const JsonObject& o) {
  const std::string s = o.String("stat");
  if (s == "pct") return PaperStat::kPct;
  if (s == "avg") return PaperStat::kAvg;
  if (s == "sd") return PaperStat::kSd;
  o.Fail("stat", "must be pct, avg or sd, not '" + s + "'");
}

PaperColumn ParseColumn(const JsonObject& o) {
  o.RejectUnknownKeys({"measure", "robot", "stat"});
  PaperColumn c{o.String("measure"), o.StringOr("robot", ""), ParseStat(o)};
  const auto& rules = MeasureRules();
  const auto rule = std::find_if(rules.begin(), rules.end(), [&](const MeasureRule& r) {
    return c.measure == r.measure;
  });
  if (rule == rules.end()) o.Fail("measure", "no measure '" + c.measure + "'");
  if (rule->per_robot == c.robot.empty()) {
    o.Fail("robot", rule->per_robot ? "'" + c.measure + "' needs a robot"
                                    : "'" + c.measure + "' is not per robot");
  }
  if (std::find(rule->stats.begin(), rule->stats.end(), c.stat) == rule->stats.end()) {
    o.Fail("stat", "'" + c.measure + "' has no " + PaperStatName(c.stat));
  }
  return c;
}

PaperTable ParseTable(const JsonObject& o) {
  o.RejectUnknownKeys({"table", "config", "source", "caption", "columns", "rows"});
  PaperTable t;
  t.table = o.Integer("table");
  t.config = o.String("config");
  t.source = o.String("source");
  t.caption = o.String("caption");
  for (const JsonObject& c : o.ObjectArray("columns")) t.columns.push_back(ParseColumn(c));
  for (const JsonObject& r : o.ObjectArray("rows")) {
    r.RejectUnknownKeys({"scenario", "team", "values"});
    PaperRow row{r.Integer("scenario"), r.String("team"), r.NumberArray("values")};
    if (row.values.size() != t.columns.size()) {
      r.Fail("values", "has " + std::to_string(row.values.size()) + " numbers, the table " +
                           std::to_string(t.columns.size()) + " columns");
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

PaperClaim ParseClaim(const JsonObject& o) {
  o.RejectUnknownKeys({"name", "statement", "source", "terms"});
  PaperClaim c{o.String("name"), o.String("statement"), o.String("source"), {}};
  const JsonObject terms = o.Object("terms");
  for (const std::string& config : terms.Keys()) {
    if (config == "notes") continue;
    std::vector<PaperTerm> list;
    for (const JsonObject& t : terms.ObjectArray(config)) {
      t.RejectUnknownKeys({"table", "measure", "robot"});
      list.push_back({t.Integer("table"), t.String("measure"), t.StringOr("robot", "")});
    }
    c.terms.emplace_back(config, std::move(list));
  }
  return c;
}

// The measures a claim may compare: those every trial has a value of (TermValue in
// experiments/passing_scorecard.cc).
bool PerTrialMeasure(const std::string& measure) {
  for (const char* m : {"goal", "close", "block", "out", "to_goal", "timeout", "touches",
                        "touches_without_timeouts", "time_s", "time_without_timeouts_s"}) {
    if (measure == m) return true;
  }
  return false;
}

std::string At(const std::string& key, std::size_t i) {
  return key + "[" + std::to_string(i) + "]";
}

void ValidateTable(const PaperTable& t, const std::string& path) {
  RequireInRange(path + ".table", t.table, 1, 99);
  if (t.config.empty()) throw InputError(path + ".config: must not be empty");
  if (t.source.empty()) throw InputError(path + ".source: must name where the figures come from");
  std::set<std::pair<int, std::string>> seen;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const PaperRow& row = t.rows[r];
    const std::string rp = path + "." + At("rows", r);
    RequireInRange(rp + ".scenario", row.scenario, 1, 99);
    if (row.team != "cbr" && row.team != "reactive") {
      throw InputError(rp + ".team: must be cbr or reactive, not '" + row.team + "'");
    }
    if (!seen.insert({row.scenario, row.team}).second) {
      throw InputError(rp + ": scenario " + std::to_string(row.scenario) + " " + row.team +
                       " twice in table " + std::to_string(t.table));
    }
    for (std::size_t c = 0; c < row.values.size() && c < t.columns.size(); ++c) {
      const std::string vp = rp + "." + At("values", c);
      if (t.columns[c].stat == PaperStat::kPct) {
        RequireInRange(vp, row.values[c], 0.0, 100.0);
      } else {
        RequireNonNegative(vp, row.values[c]);
      }
    }
  }
}

}  // namespace

std::string PaperStatName(PaperStat stat) {
  switch (stat) {
    case PaperStat::kPct:
      return "pct";
    case PaperStat::kAvg:
      return "avg";
    case PaperStat::kSd:
      return "sd";
  }
  return "";
}

std::string PaperColumn::Label() const {
  const std::string stat_label = stat == PaperStat::kPct ? "%" : PaperStatName(stat);
  return measure + (robot.empty() ? "" : " " + robot) + " " + stat_label;
}

const PaperRow* PaperTable::Row(int scenario, const std::string& team) const {
  for (const PaperRow& r : rows) {
    if (r.scenario == scenario && r.team == team) return &r;
  }
  return nullptr;
}

std::optional<std::size_t> PaperTable::ValueColumn(const std::string& measure,
                                                   const std::string& robot) const {
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const PaperColumn& col = columns[c];
    if (col.measure == measure && col.robot == robot && col.stat != PaperStat::kSd) return c;
  }
  return std::nullopt;
}

const std::vector<PaperTerm>* PaperClaim::Terms(const std::string& config) const {
  for (const auto& [name, list] : terms) {
    if (name == config) return &list;
  }
  return nullptr;
}

namespace {

WorldCheckSpec ParseWorldCheck(const JsonObject& o) {
  o.RejectUnknownKeys({"notes", "team", "within_points", "measures"});
  WorldCheckSpec w;
  w.team = o.String("team");
  w.within_points = o.Number("within_points");
  WithFile(o.file(), [&] { RequireInRange(o.PathOf("within_points"), w.within_points, 0.0, 100.0); });
  const JsonObject m = o.Object("measures");
  for (const std::string& config : m.Keys()) w.measures.emplace_back(config, m.StringArray(config));
  return w;
}

void ValidateWorldCheck(const PaperTables& p) {
  const WorldCheckSpec& w = p.world_check;
  if (w.team != "cbr" && w.team != "reactive") {
    throw InputError("world_check.team: must be cbr or reactive, got '" + w.team + "'");
  }
  for (const auto& measure : w.measures) {
    // Named copies, not structured bindings: C++17 lambdas cannot capture bindings (Clang).
    const std::string& config = measure.first;
    const std::vector<std::string>& list = measure.second;
    for (std::size_t k = 0; k < list.size(); ++k) {
      const bool found = std::any_of(p.tables.begin(), p.tables.end(), [&](const PaperTable& t) {
        const bool has_rows = std::any_of(t.rows.begin(), t.rows.end(),
                                          [&](const PaperRow& r) { return r.team == w.team; });
        return t.config == config && has_rows &&
               std::any_of(t.columns.begin(), t.columns.end(), [&](const PaperColumn& c) {
                 return c.measure == list[k] && c.stat == PaperStat::kPct && c.robot.empty();
               });
      });
      if (!found) {
        throw InputError("world_check.measures." + At(config, k) + ": no table of " + config +
                         " has a share column '" + list[k] + "' with rows of " + w.team);
      }
    }
  }
}

}  // namespace

const std::vector<std::string>* WorldCheckSpec::Measures(const std::string& config) const {
  for (const auto& [name, list] : measures) {
    if (name == config) return &list;
  }
  return nullptr;
}

const PaperTable* PaperTables::Table(int number) const {
  for (const PaperTable& t : tables) {
    if (t.table == number) return &t;
  }
  return nullptr;
}

void PaperTables::Validate() const {
  if (tables.empty()) throw InputError("tables: must hold at least one table");
  std::set<int> numbers;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    ValidateTable(tables[i], At("tables", i));
    if (!numbers.insert(tables[i].table).second) {
      throw InputError(At("tables", i) + ".table: table " + std::to_string(tables[i].table) +
                       " twice");
    }
  }
  ValidateWorldCheck(*this);
  for (std::size_t i = 0; i < claims.size(); ++i) {
    for (const auto& [config, list] : claims[i].terms) {
      for (std::size_t k = 0; k < list.size(); ++k) {
        const PaperTerm& term = list[k];
        const std::string path = At("claims", i) + ".terms." + At(config, k);
        const PaperTable* t = Table(term.table);
        if (t == nullptr || t->config != config) {
          throw InputError(path + ".table: no table " + std::to_string(term.table) + " of " +
                           config);
        }
        if (!PerTrialMeasure(term.measure)) {
          throw InputError(path + ".measure: '" + term.measure +
                           "' has no value per trial to compare");
        }
        if (!t->ValueColumn(term.measure, term.robot)) {
          throw InputError(path + ".measure: table " + std::to_string(term.table) +
                           " has no column " + term.measure +
                           (term.robot.empty() ? "" : " of " + term.robot));
        }
      }
    }
  }
}

PaperTables LoadPaperTables(const std::string& reference,
                            const std::filesystem::path& models_dir) {
  PaperTables p;
  p.file = ResolveModelFile(reference, DataFolder::kExperiments, ".", models_dir);
  const JsonDocument doc = JsonDocument::Load(p.file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"article", "tables", "claims", "world_check"});
  p.article = root.String("article");
  for (const JsonObject& t : root.ObjectArray("tables")) p.tables.push_back(ParseTable(t));
  for (const JsonObject& c : root.ObjectArray("claims")) p.claims.push_back(ParseClaim(c));
  p.world_check = ParseWorldCheck(root.Object("world_check"));
  WithFile(p.file.string(), [&] { p.Validate(); });
  return p;
}

std::optional<double> PaperClaimValue(const PaperTables& paper, const PaperClaim& claim,
                                      const std::string& config, int scenario,
                                      const std::string& team) {
  const std::vector<PaperTerm>* terms = claim.Terms(config);
  if (terms == nullptr || terms->empty()) return std::nullopt;
  double sum = 0.0;
  for (const PaperTerm& term : *terms) {
    const PaperTable* t = paper.Table(term.table);
    const PaperRow* row = t ? t->Row(scenario, team) : nullptr;
    const std::optional<std::size_t> c = t ? t->ValueColumn(term.measure, term.robot) : std::nullopt;
    if (row == nullptr || !c) return std::nullopt;
    sum += row->values[*c];
  }
  return sum;
}

}  // namespace foresight
