#include "experiments/passing_replay.h"

#include "report/field_svg.h"
#include "report/json_text.h"
#include "report/report_format.h"

namespace foresight {

namespace {

constexpr double kPixelsPerM = 130.0;
constexpr const char* kAttackerColour = "#0072b2";
constexpr const char* kOpponentColour = "#d55e00";

// The field, faint paths and one group per robot (id r<i>) and the ball (id ball), drawn at the
// origin; the script moves them.
std::string FieldSvg(const PassingSetup& setup, const MatchTrialResult& t) {
  FieldCanvas c(setup.field, kPixelsPerM, 0.0);
  c.DrawField();
  for (const OpponentSpec& o : setup.config.opponents) {
    const FieldBox& r = o.region;
    c.svg().Rect(c.X(r.x_min_m), c.Y(r.y_max_m), c.Px(r.x_max_m - r.x_min_m),
                 c.Px(r.y_max_m - r.y_min_m),
                 "fill:#d55e00;fill-opacity:0.10;stroke:#d55e00;stroke-dasharray:4,3");
  }
  const FieldBox area = PenaltyArea(setup.field, setup.sim, setup.mirrored ? -1.0 : 1.0);
  c.svg().Rect(c.X(area.x_min_m), c.Y(area.y_max_m), c.Px(area.x_max_m - area.x_min_m),
               c.Px(area.y_max_m - area.y_min_m), "fill:none;stroke:#555;stroke-width:1.5");
  c.DrawLinesAndPosts();
  const std::size_t robots = t.trace.front().robots.size();
  for (std::size_t r = 0; r <= robots; ++r) {
    PolylinePath path;
    for (const TraceFrame& f : t.trace) {
      const Vec2 p = r == robots ? f.p_F_ball : f.robots[r].p_F;
      path.Point(c.X(p.x()), c.Y(p.y()));
    }
    const std::string colour = r == robots ? "black" : (r < 2 ? kAttackerColour : kOpponentColour);
    c.svg().Path(path.data(), "fill:none;stroke-opacity:0.35;stroke-width:2;stroke:" + colour);
  }
  const double radius_px = c.Px(setup.robot.body_radius_m);
  for (std::size_t r = 0; r < robots; ++r) {
    c.svg().OpenGroup("id=\"r" + std::to_string(r) + "\"");
    const char* colour = r < 2 ? kAttackerColour : kOpponentColour;
    c.svg().Circle(0, 0, radius_px, Format("fill:%s;stroke:black;stroke-width:1.5", colour));
    c.svg().Line(0, 0, radius_px, 0, "stroke:white;stroke-width:3");
    c.svg().CloseGroup();
    c.svg().OpenGroup("id=\"n" + std::to_string(r) + "\"");
    c.svg().Text(0, 0, RobotName(setup, r), "font:bold 14px sans-serif;text-anchor:middle");
    c.svg().CloseGroup();
  }
  c.svg().OpenGroup("id=\"ball\"");
  c.svg().Circle(0, 0, std::max(4.0, c.Px(setup.field.ball.radius_m)),
                 "fill:#ff8c00;stroke:black;stroke-width:1");
  c.svg().CloseGroup();
  std::string svg = c.svg().Finish();
  return svg.substr(svg.find("<svg"));
}

// Frames as [t, ball x px, ball y px, x0, y0, heading0 (SVG degrees), x1, ...].
std::string FramesJson(const PassingSetup& setup, const MatchTrialResult& t) {
  const FieldCanvas c(setup.field, kPixelsPerM, 0.0);
  std::string json = "[";
  // Appends `value` with `decimals` decimals after a comma (report/json_text.h).
  const auto number = [&json](double value, int decimals, const char* what) {
    json += ',';
    json += JsonFixed(value, decimals, what);
  };
  for (std::size_t i = 0; i < t.trace.size(); ++i) {
    const TraceFrame& f = t.trace[i];
    json += i == 0 ? "[" : ",\n[";
    json += JsonFixed(f.time_s, 2, "replay frame time");
    number(c.X(f.p_F_ball.x()), 1, "replay ball x");
    number(c.Y(f.p_F_ball.y()), 1, "replay ball y");
    for (const Pose2& p : f.robots) {
      number(c.X(p.p_F.x()), 1, "replay robot x");
      number(c.Y(p.p_F.y()), 1, "replay robot y");
      number(-p.theta_rad * kRadToDeg, 1, "replay robot heading");
    }
    json += "]";
  }
  return json + "]";
}

bool IsTeamDecision(const std::string& detail) {
  for (const char* prefix : {"cbr coordinator", "cbr case", "cbr no_case", "cbr abort", "cbr end"}) {
    if (detail.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

std::string EventsJson(const PassingSetup& setup, const MatchTrialResult& t) {
  std::string json = "[";
  bool first = true;
  for (const auto& [time_s, text] : ReplayEvents(setup, t)) {
    json += first ? "[" : ",[";
    json += JsonFixed(time_s, 2, "replay event time");
    json += ',';
    json += JsonString(text);
    json += ']';
    first = false;
  }
  return json + "]";
}

constexpr const char* kScript = R"JS(
const slider = document.getElementById('t');
const label = document.getElementById('time');
const log = document.getElementById('log');
const robots = (frames[0].length - 3) / 3;
function show(i) {
  const f = frames[i];
  document.getElementById('ball').setAttribute('transform', `translate(${f[1]},${f[2]})`);
  for (let r = 0; r < robots; ++r) {
    const x = f[3 + 3 * r], y = f[4 + 3 * r], h = f[5 + 3 * r];
    document.getElementById('r' + r).setAttribute('transform', `translate(${x},${y}) rotate(${h})`);
    document.getElementById('n' + r).setAttribute('transform', `translate(${x},${y - 22})`);
  }
  label.textContent = f[0].toFixed(1) + ' s';
  log.textContent = events.filter(e => e[0] <= f[0] + 1e-9)
      .map(e => e[0].toFixed(2).padStart(6) + ' s  ' + e[1]).join('\n');
  log.scrollTop = log.scrollHeight;
}
let timer = null;
document.getElementById('play').onclick = () => {
  if (timer) { clearInterval(timer); timer = null; return; }
  timer = setInterval(() => {
    const i = Math.min(+slider.value + 1, frames.length - 1);
    slider.value = i; show(i);
    if (i === frames.length - 1) { clearInterval(timer); timer = null; }
  }, 100);
};
slider.max = frames.length - 1;
slider.value = Math.min(+location.hash.slice(1) || 0, frames.length - 1);  // replay.html#150
slider.oninput = () => show(+slider.value);
show(+slider.value);
)JS";

}  // namespace

const MatchTrialResult* ExampleTrial(const ScenarioTrials& st) {
  for (const MatchTrialResult& t : st.trials) {
    if (!t.trace.empty()) return &t;
  }
  return nullptr;
}

std::string RobotName(const PassingSetup& setup, std::size_t robot) {
  return robot < 2 ? (robot == 0 ? "A" : "B") : setup.config.opponents[robot - 2].name;
}

std::vector<std::pair<double, std::string>> ReplayEvents(const PassingSetup& setup,
                                                         const MatchTrialResult& t) {
  std::vector<std::pair<double, std::string>> events;
  for (const MatchEvent& e : t.events) {
    // Messages come twice a second per robot: only the CBR team's decisions get a line (the
    // coordinator, the case, no case, aborts and ends; not beliefs, arrivals, passes, dones).
    if (e.kind == EventKind::kMessage && !IsTeamDecision(e.detail)) continue;
    const std::size_t robot = e.side == Side::kAttackers ? static_cast<std::size_t>(e.robot)
                                                         : 2 + static_cast<std::size_t>(e.robot);
    const std::string who = e.kind == EventKind::kEnd ? "" : RobotName(setup, robot) + " ";
    const std::string kind = e.kind == EventKind::kMessage ? "" : std::string(EventKindName(e.kind));
    events.emplace_back(e.time_s, who + kind + (e.detail.empty() || kind.empty() ? "" : " ") +
                                      e.detail);
  }
  return events;
}

std::string PassingReplayHtml(const PassingRun& run, std::size_t index) {
  const PassingSetup& setup = *run.setup;
  const ScenarioTrials& st = run.result.scenarios.at(index);
  const MatchTrialResult* t = ExampleTrial(st);
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>Replay " +
      st.name +
      "</title>\n<style>body{font-family:sans-serif;margin:16px}"
      "#wrap{display:flex;gap:16px;align-items:flex-start}"
      "#log{white-space:pre;font:12px monospace;height:560px;width:400px;overflow:auto;"
      "border:1px solid #ccc;padding:4px;margin:0}#t{width:700px}</style></head><body>\n";
  if (t == nullptr) return html + "<p>No example trial was recorded.</p></body></html>\n";
  html += Format("<h2>Scenario %d (%s): %s vs %s, trial %d, outcome %s after %.1f s</h2>\n",
                 st.scenario, st.name.c_str(), run.team.c_str(), setup.config.name.c_str(),
                 static_cast<int>(t - st.trials.data()),
                 std::string(TrialOutcomeName(t->outcome)).c_str(), t->counters.time_s);
  html +=
      "<p><button id=\"play\">play / pause</button> <input id=\"t\" type=\"range\" min=\"0\" "
      "value=\"0\"> <span id=\"time\"></span></p>\n<div id=\"wrap\">" +
      FieldSvg(setup, *t) + "<pre id=\"log\"></pre></div>\n";
  html += Format(
      "<p>seed %llu; attackers blue (A, B), opponents vermilion, ball orange; faint "
      "lines: the whole paths; dashed boxes: home regions.</p>\n",
      static_cast<unsigned long long>(run.provenance.seed));
  html += "<script>\nconst frames = " + FramesJson(setup, *t) +
          ";\nconst events = " + ScriptSafeJson(EventsJson(setup, *t)) + ";\n" + kScript +
          "</script>\n</body></html>\n";
  return html;
}

}  // namespace foresight
