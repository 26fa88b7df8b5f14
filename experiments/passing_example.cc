#include "experiments/passing_example.h"

#include <cmath>

#include "report/field_svg.h"
#include "report/report_format.h"

namespace foresight {

namespace {

constexpr double kPixelsPerM = 110.0;
constexpr double kLegendPx = 330.0;
constexpr const char* kAttackerColour = "#0072b2";
constexpr const char* kOpponentColour = "#d55e00";

const MatchTrialResult* ExampleTrial(const ScenarioTrials& st) {
  for (const MatchTrialResult& t : st.trials) {
    if (!t.trace.empty()) return &t;
  }
  return nullptr;
}

void DrawRegion(FieldCanvas& c, const FieldBox& r, std::string_view style) {
  c.svg().Rect(c.X(r.x_min_m), c.Y(r.y_max_m), c.Px(r.x_max_m - r.x_min_m),
               c.Px(r.y_max_m - r.y_min_m), style);
}

void DrawPath(FieldCanvas& c, const std::vector<TraceFrame>& trace, int robot,
              std::string_view style, double mark_period_s, std::string_view colour) {
  PolylinePath path;
  for (const TraceFrame& f : trace) {
    const Vec2 p = robot < 0 ? f.p_F_ball : f.robots[static_cast<std::size_t>(robot)].p_F;
    path.Point(c.X(p.x()), c.Y(p.y()));
  }
  c.svg().Path(path.data(), style);
  int next_mark = 1;
  for (const TraceFrame& f : trace) {
    if (f.time_s + 1e-9 < next_mark * mark_period_s) continue;
    const Vec2 p = robot < 0 ? f.p_F_ball : f.robots[static_cast<std::size_t>(robot)].p_F;
    c.svg().Circle(c.X(p.x()), c.Y(p.y()), 6.0,
                   Format("fill:white;stroke:%s;stroke-width:1", std::string(colour).c_str()));
    c.svg().Text(
        c.X(p.x()), c.Y(p.y()) + 3.5, std::to_string(next_mark),
        Format("font:9px sans-serif;text-anchor:middle;fill:%s", std::string(colour).c_str()));
    ++next_mark;
  }
}

// The cases a CBR team retrieved in the trial (its "cbr case cycle N NAME" messages, once per
// cycle), with where the ball was and how each case ended if it was aborted.
struct RetrievedCase {
  double time_s = 0.0;
  Vec2 p_F_ball{0.0, 0.0};
  std::string name;
  std::string abort;
};

std::vector<RetrievedCase> RetrievedCases(const MatchTrialResult& t) {
  std::vector<RetrievedCase> cases;
  std::string last_cycle;
  for (const MatchEvent& e : t.events) {
    if (e.kind != EventKind::kMessage) continue;
    const bool is_case = e.detail.rfind("cbr case cycle ", 0) == 0;
    const bool is_abort = e.detail.rfind("cbr abort cycle ", 0) == 0;
    if (!is_case && !is_abort) continue;
    const std::string rest = e.detail.substr(is_case ? 15 : 16);
    const std::string cycle = rest.substr(0, rest.find(' '));
    const std::string what = rest.substr(rest.find(' ') + 1);
    if (is_case && cycle != last_cycle) {
      cases.push_back({e.time_s, e.p_F_ball, what, ""});
      last_cycle = cycle;
    } else if (is_abort && cycle == last_cycle && cases.back().abort.empty()) {
      cases.back().abort = what;
    }
  }
  return cases;
}

void DrawCases(FieldCanvas& c, const std::vector<RetrievedCase>& cases) {
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Vec2& p = cases[i].p_F_ball;
    c.svg().Rect(c.X(p.x()) + 5, c.Y(p.y()) - 19, 16, 13, "fill:#009e73;stroke:none");
    c.svg().Text(c.X(p.x()) + 13, c.Y(p.y()) - 9, std::to_string(i + 1),
                 "font:bold 9px sans-serif;text-anchor:middle;fill:white");
  }
}

void DrawLegend(FieldCanvas& c, const PassingRun& run, const ScenarioTrials& st,
                const MatchTrialResult& t) {
  const double x = c.legend_x();
  double y = 30.0;
  auto line = [&](const std::string& text, std::string_view style = "font:13px sans-serif") {
    c.svg().Text(x, y, text, style);
    y += 18.0;
  };
  line("Scenario " + std::to_string(st.scenario) + " (" + st.name + ")",
       "font:bold 14px sans-serif");
  line(run.team + " vs " + run.setup->config.name);
  line(Format("outcome: %s after %.1f s", std::string(TrialOutcomeName(t.outcome)).c_str(),
              t.counters.time_s));
  line(Format("marks every %.0f s", run.setup->params.step_mark_period_s));
  y += 6.0;
  c.svg().Line(x, y - 4, x + 26, y - 4, Format("stroke:%s;stroke-width:2", kAttackerColour));
  c.svg().Text(x + 32, y, "attackers A, B", "font:12px sans-serif");
  y += 18.0;
  c.svg().Line(x, y - 4, x + 26, y - 4, Format("stroke:%s;stroke-width:2", kOpponentColour));
  c.svg().Text(x + 32, y, "opponents", "font:12px sans-serif");
  y += 18.0;
  c.svg().Line(x, y - 4, x + 26, y - 4, "stroke:black;stroke-width:2;stroke-dasharray:5,3");
  c.svg().Text(x + 32, y, "ball (dots: kicks)", "font:12px sans-serif");
  y += 18.0;
  c.svg().Rect(x, y - 10, 26, 12, "fill:#d55e00;fill-opacity:0.12;stroke:#d55e00");
  c.svg().Text(x + 32, y, "home regions", "font:12px sans-serif");
  const std::vector<RetrievedCase> cases = RetrievedCases(t);
  if (cases.empty()) return;
  y += 26.0;
  line(Format("cases retrieved: %zu", cases.size()), "font:bold 12px sans-serif");
  constexpr std::size_t kListed = 14;
  for (std::size_t i = 0; i < cases.size() && i < kListed; ++i) {
    line(Format("%zu  %.1f s  %s%s", i + 1, cases[i].time_s, cases[i].name.c_str(),
                cases[i].abort.empty() ? "" : (" (abort: " + cases[i].abort + ")").c_str()),
         "font:10px sans-serif");
  }
  if (cases.size() > kListed) line(Format("... and %zu more", cases.size() - kListed), "font:10px sans-serif");
}

}  // namespace

std::string PassingExampleSvg(const PassingRun& run, std::size_t index) {
  const PassingSetup& setup = *run.setup;
  const ScenarioTrials& st = run.result.scenarios.at(index);
  FieldCanvas c(setup.field, kPixelsPerM, kLegendPx);
  c.DrawField();
  const MatchTrialResult* t = ExampleTrial(st);
  if (t == nullptr) return c.svg().Finish();
  for (const OpponentSpec& o : setup.config.opponents) {
    DrawRegion(c, o.region, "fill:#d55e00;fill-opacity:0.10;stroke:#d55e00;stroke-dasharray:4,3");
  }
  DrawRegion(c, PenaltyArea(setup.field, setup.sim, setup.mirrored ? -1.0 : 1.0),
             "fill:none;stroke:#555;stroke-width:1.5");
  c.DrawLinesAndPosts();
  const std::size_t attackers = 2;
  const std::size_t robots = t->trace.front().robots.size();
  const double mark = setup.params.step_mark_period_s;
  for (std::size_t r = 0; r < robots; ++r) {
    const char* colour = r < attackers ? kAttackerColour : kOpponentColour;
    DrawPath(c, t->trace, static_cast<int>(r),
             Format("fill:none;stroke:%s;stroke-width:2;stroke-opacity:0.8", colour), mark, colour);
    c.DrawRobot(t->trace.front().robots[r], setup.robot.body_radius_m, "none");
    c.DrawRobot(t->trace.back().robots[r], setup.robot.body_radius_m, colour);
    const Vec2 p = t->trace.front().robots[r].p_F;
    const std::string name =
        r < attackers ? (r == 0 ? "A" : "B") : setup.config.opponents[r - attackers].name;
    c.svg().Text(c.X(p.x()), c.Y(p.y()) - c.Px(setup.robot.body_radius_m) - 4, name,
                 "font:bold 13px sans-serif;text-anchor:middle");
  }
  DrawPath(c, t->trace, -1, "fill:none;stroke:black;stroke-width:2;stroke-dasharray:5,3", mark,
           "black");
  for (const MatchEvent& e : t->events) {
    if (e.kind == EventKind::kKick) c.DrawDot(e.p_F_ball, 4.0, "fill:black");
  }
  c.DrawDot(t->trace.back().p_F_ball, 5.0, "fill:white;stroke:black;stroke-width:2");
  DrawCases(c, RetrievedCases(*t));
  DrawLegend(c, run, st, *t);
  return c.svg().Finish();
}

}  // namespace foresight
