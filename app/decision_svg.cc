#include "app/decision_svg.h"

#include <cstdio>
#include <string>
#include <vector>

#include "report/field_svg.h"
#include "report/report_format.h"

namespace foresight {

namespace {

// The paper's Fig. 2 draws forward cyan, left yellow, right red; here the left kick is purple
// because the field draws the opponent's posts yellow and the own posts blue, the ball orange
// (report/field_svg.cc): every colour below is far from those and from each other, so a sample
// is never mistaken for a post or the ball.
const char* KickColour(int index) {
  static const char* const kColours[] = {"#00c8e6", "#911eb4", "#e6194b", "#f032e6",
                                         "#9a6324", "#000075", "#fabebe", "#808080"};
  return kColours[static_cast<std::size_t>(index) % (sizeof kColours / sizeof *kColours)];
}

// Every sample's rest position of one kick at its chosen rotation; out samples hollow.
void DrawKickSamples(FieldCanvas& canvas, const DecisionRun& run, const ActionEvaluator& evaluator,
                     const KickOption& option) {
  const bool chosen = option.kick_index == run.decision.kick_index;
  const std::string colour = KickColour(option.kick_index);
  const std::string filled = "fill:" + colour +
                             ";stroke:#000;stroke-width:" + (chosen ? "1.2" : "0.6") +
                             ";fill-opacity:" + (chosen ? "1" : "0.75");
  const std::string hollow = "fill:none;stroke:" + colour + ";stroke-width:2";
  const double radius_px = chosen ? 5.0 : 3.5;
  canvas.svg().OpenGroup("class=\"kick\"");
  canvas.svg().Title(KickName(run, option.kick_index));
  for (const Outcome& o : evaluator.Outcomes(option.kick_index, option.choice.rotation_rad)) {
    canvas.DrawDot(o.p_F_rest, radius_px, o.category == Category::kOut ? hollow : filled);
  }
  canvas.svg().CloseGroup();
}

void DrawLegend(FieldCanvas& canvas, const DecisionRun& run) {
  SvgWriter& svg = canvas.svg();
  const double x = canvas.legend_x();
  double y = 34.0;
  svg.Text(x, y, run.planner->situation().name, "font-size:17px;font-weight:bold");
  y += 22.0;
  svg.Text(
      x, y,
      "strategy " + std::string(StrategyName(run.decision.strategy)) +
          Format(", N = %d, seed %llu", run.samples, static_cast<unsigned long long>(run.seed)),
      "font-size:13px");
  y += 30.0;
  for (const KickOption& k : run.decision.kicks) {
    if (!k.considered) continue;
    const ActionEvaluation& e = k.choice.evaluation;
    const bool chosen = k.kick_index == run.decision.kick_index;
    svg.Circle(x + 7, y - 5, 6, "fill:" + std::string(KickColour(k.kick_index)) + ";stroke:#000");
    svg.Text(x + 20, y, KickName(run, k.kick_index) + (chosen ? "  (chosen)" : ""),
             chosen ? "font-size:14px;font-weight:bold" : "font-size:14px");
    y += 18.0;
    svg.Text(x + 20, y,
             Format("turn %+.1f deg, utility %.3f%s", k.choice.rotation_rad * kRadToDeg,
                    e.trimmed_utility, e.too_risky ? " (too risky)" : ""),
             "font-size:12px");
    y += 16.0;
    svg.Text(x + 20, y,
             Format("goal %.2f  out %.2f  own %.2f  infield %.2f", e.p_opp_goal, e.p_out,
                    e.p_own_goal, e.p_infield),
             "font-size:12px");
    y += 26.0;
  }
  svg.Text(x, y, Format("none: utility %.3f", run.decision.none.trimmed_utility), "font-size:12px");
  y += 20.0;
  svg.Text(x, y, "hollow circles: samples that end out", "font-size:11px;fill:#555");
  if (!run.decision.note.empty())
    svg.Text(x, y + 16.0, run.decision.note, "font-size:11px;fill:#a00");
}

}  // namespace

std::string DecisionSvg(const DecisionRun& run) {
  const Situation& s = run.planner->situation();
  FieldCanvas canvas(s.field, 900.0 / s.field.carpet_length_m, 330.0);
  canvas.DrawField();
  // The decision's own samples (same seed), drawn once for every kick.
  const CoarseActionEvaluator evaluator = run.planner->MakeEvaluator(run.samples, run.seed);
  for (const Obstacle& o : s.obstacles) {
    canvas.DrawDot(o.p_F, canvas.Px(o.radius_m), "fill:#444;fill-opacity:0.85;stroke:#000");
  }
  const Vec2 ball = s.state.MeanBallInField();
  // The robot as estimated, and where turning around the ball takes it for the chosen kick.
  canvas.DrawRobot(s.state.robot, 0.12, "#dddddd");
  if (run.decision.rotation_rad != 0.0) {
    Pose2 turned{ball, s.state.robot.theta_rad + run.decision.rotation_rad};
    turned.p_F = ball - (turned.ToField(s.state.p_R_ball) - ball);
    canvas.DrawRobot(turned, 0.12, "#ffffff");
  }
  for (const KickOption& k : run.decision.kicks) {
    if (k.considered && k.kick_index != run.decision.kick_index)
      DrawKickSamples(canvas, run, evaluator, k);
  }
  for (const KickOption& k : run.decision.kicks) {
    if (k.considered && k.kick_index == run.decision.kick_index)
      DrawKickSamples(canvas, run, evaluator, k);
  }
  canvas.DrawDot(ball, canvas.Px(s.field.ball.radius_m), "fill:#ff7f00;stroke:#000;stroke-width:1");
  if (run.decision.kick_index != kNoKick) {
    const KickSpec& kick = s.kicks.kicks[static_cast<std::size_t>(run.decision.kick_index)];
    const double heading = s.state.robot.theta_rad + run.decision.rotation_rad + kick.direction_rad;
    canvas.DrawArrow(ball, ball + 0.6 * UnitVector(heading), "#000000");
  }
  DrawLegend(canvas, run);
  return canvas.svg().Finish();
}

}  // namespace foresight
