#include "experiments/world_check.h"

#include <algorithm>
#include <cmath>

#include "report/report_format.h"

namespace foresight {

namespace {

using Json = nlohmann::ordered_json;

std::string WithinText(double points) { return "within " + Format("%g", points) + " points"; }

std::string CellVerdict(const ScorecardCell& c, bool share, double within_points) {
  if (!c.ci || !c.ours) return "not judged";
  if (c.inside && *c.inside) return "inside";
  if (share && std::abs(*c.ours - c.paper) <= within_points + 1e-9) return WithinText(within_points);
  return "off";
}

WorldCheckScenario& ScenarioOf(WorldCheck& check, int scenario, int trials) {
  for (WorldCheckScenario& s : check.scenarios) {
    if (s.scenario == scenario) return s;
  }
  check.scenarios.push_back({scenario, trials, {}, false, {}});
  return check.scenarios.back();
}

std::string Number(const std::optional<double>& v, bool share) {
  return v ? Fixed(*v, share ? 1 : 2) : std::string("-");
}

std::string Verdict(const WorldCheck& check, const WorldCheckScenario& s) {
  if (s.agrees) {
    const bool all_inside = std::all_of(s.cells.begin(), s.cells.end(), [](const auto& c) {
      return !c.decides || c.verdict == "inside";
    });
    return all_inside ? "agrees: the paper's value inside our interval"
                      : "agrees: the paper's value inside our interval or " +
                            WithinText(check.within_points);
  }
  std::string off;
  for (const std::string& m : s.off) off += (off.empty() ? "" : ", ") + m;
  return "off: " + off;
}

}  // namespace

WorldCheck BuildWorldCheck(const PaperTables& paper, const std::vector<ScorecardTable>& tables,
                           const std::string& config) {
  const WorldCheckSpec& spec = paper.world_check;
  WorldCheck check;
  check.team = spec.team;
  check.within_points = spec.within_points;
  if (const std::vector<std::string>* m = spec.Measures(config)) check.measures = *m;
  for (const ScorecardTable& t : tables) {
    const PaperTable* source = paper.Table(t.table);
    for (const ScorecardRow& r : t.rows) {
      if (r.team != spec.team || source == nullptr) continue;
      WorldCheckScenario& s = ScenarioOf(check, r.scenario, r.trials);
      for (std::size_t c = 0; c < r.cells.size(); ++c) {
        const PaperColumn& col = source->columns[c];
        const bool share = col.stat == PaperStat::kPct;
        const bool decides = share && col.robot.empty() &&
                             std::find(check.measures.begin(), check.measures.end(),
                                       col.measure) != check.measures.end();
        s.cells.push_back({t.table, t.columns[c], decides, r.cells[c],
                           CellVerdict(r.cells[c], share, spec.within_points)});
      }
    }
  }
  std::sort(check.scenarios.begin(), check.scenarios.end(),
            [](const auto& a, const auto& b) { return a.scenario < b.scenario; });
  for (WorldCheckScenario& s : check.scenarios) {
    bool any = false;
    for (const WorldCheckCell& c : s.cells) {
      if (!c.decides) continue;
      any = true;
      if (c.verdict != "inside" && c.verdict != WithinText(spec.within_points)) {
        s.off.push_back(c.column);
      }
    }
    s.agrees = any && s.trials > 0 && s.off.empty();
    check.agreeing += s.agrees;
  }
  return check;
}

Json WorldCheckJson(const WorldCheck& check) {
  Json scenarios = Json::array();
  for (const WorldCheckScenario& s : check.scenarios) {
    Json cells = Json::array();
    for (const WorldCheckCell& c : s.cells) {
      cells.push_back({{"table", c.table},
                       {"column", c.column},
                       {"decides", c.decides},
                       {"paper", c.cell.paper},
                       {"ours", c.cell.ours ? Json(*c.cell.ours) : Json(nullptr)},
                       {"ours_ci", c.cell.ci ? Json::array({c.cell.ci->low, c.cell.ci->high})
                                             : Json(nullptr)},
                       {"verdict", c.verdict}});
    }
    scenarios.push_back({{"scenario", s.scenario},
                         {"trials", s.trials},
                         {"agrees", s.agrees},
                         {"off", s.off},
                         {"verdict", Verdict(check, s)},
                         {"cells", cells}});
  }
  return {{"team", check.team},
          {"within_points", check.within_points},
          {"measures", check.measures},
          {"scenarios_agreeing", check.agreeing},
          {"scenarios", scenarios}};
}

std::string WorldCheckText(const WorldCheck& check) {
  std::string text = Format("the world against the paper's %s rows (%d of %zu scenarios agree):\n",
                            check.team.c_str(), check.agreeing, check.scenarios.size());
  for (const WorldCheckScenario& s : check.scenarios) {
    text += Format("  s%d %s |", s.scenario, Verdict(check, s).c_str());
    for (const WorldCheckCell& c : s.cells) {
      if (!c.decides) continue;
      text += Format(" %s paper %g ours %s%s;", c.column.c_str(), c.cell.paper,
                     Number(c.cell.ours, true).c_str(),  // the deciding cells are shares
                     c.cell.ci ? Format(" [%.1f, %.1f]", c.cell.ci->low, c.cell.ci->high).c_str()
                               : "");
    }
    text += "\n";
  }
  return text;
}

std::vector<std::vector<std::string>> WorldCheckScenarioRows(const WorldCheck& check) {
  std::vector<std::vector<std::string>> rows;
  for (const WorldCheckScenario& s : check.scenarios) {
    rows.push_back({std::to_string(s.scenario), std::to_string(s.trials), Verdict(check, s)});
  }
  return rows;
}

std::vector<std::vector<std::string>> WorldCheckCellRows(const WorldCheck& check) {
  std::vector<std::vector<std::string>> rows;
  for (const WorldCheckScenario& s : check.scenarios) {
    for (const WorldCheckCell& c : s.cells) {
      const bool share = !c.column.empty() && c.column.back() == '%';
      const std::string ci =
          c.cell.ci ? Format("[%s, %s]", Fixed(c.cell.ci->low, share ? 1 : 2).c_str(),
                             Fixed(c.cell.ci->high, share ? 1 : 2).c_str())
                    : std::string("-");
      rows.push_back({std::to_string(s.scenario), "Table " + std::to_string(c.table),
                      c.column + (c.decides ? " (decides)" : ""), Format("%g", c.cell.paper),
                      Number(c.cell.ours, share), ci, c.verdict});
    }
  }
  return rows;
}

}  // namespace foresight
