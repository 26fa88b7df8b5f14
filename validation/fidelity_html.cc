// The fidelity report as one HTML page: aggregates per situation class with intervals, the
// strategies' decision agreement, the coarse-vs-physics utility scatter, the distributions of
// tau and regret, and the worst ten situations drawn on the field.
#include "validation/fidelity_html.h"

#include <algorithm>

#include "common/geometry.h"
#include "report/charts.h"
#include "report/field_svg.h"
#include "report/html_report.h"
#include "report/report_format.h"
#include "validation/fidelity_views.h"

namespace foresight {

namespace {

std::string MeanText(const MeanWithInterval& m, int decimals) {
  return Fixed(m.mean, decimals) + " [" + Fixed(m.ci.low, decimals) + ", " +
         Fixed(m.ci.high, decimals) + "]";
}

std::string ActionText(const Situation& s, int kick, double rotation_rad) {
  return FidelityActionText(s, kick, rotation_rad);
}

void SummaryTables(HtmlReport& html, const FidelityResult& r) {
  std::vector<std::vector<std::string>> rows;
  for (const ClassSummary& c : r.classes) {
    rows.push_back({c.situation_class, std::to_string(c.situations), MeanText(c.tau_coarse, 2),
                    MeanText(c.tau_converged, 2), MeanText(c.top1_coarse, 2),
                    MeanText(c.top1_converged, 2), MeanText(c.regret_coarse, 3),
                    MeanText(c.regret_converged, 3)});
  }
  html.Table({"class", "n", "tau-b coarse", "tau-b conv.", "top-1 coarse", "top-1 conv.",
              "regret coarse", "regret conv."},
             rows);
  html.Paragraph(
      "Means with 95 % intervals (t intervals for tau and regret, Wilson intervals "
      "for the top-1 shares). 'coarse' is the coarse model with the robot's N "
      "samples; 'converged' the coarse model with many samples: the gap between them "
      "is sampling error, the gap between 'converged' and perfect agreement is the "
      "model's error.");
  std::vector<std::vector<std::string>> decisions;
  for (const StrategyAgreementSummary& s : r.strategies) {
    decisions.push_back(
        {std::string(StrategyName(s.strategy)), MeanText(s.agreement, 2), MeanText(s.regret, 3)});
  }
  html.Heading(3, "Decisions");
  html.Table({"strategy", "coarse decision = physics decision", "physics utility lost"}, decisions);
  html.Paragraph(
      "Each strategy decides over the candidate actions twice: with the coarse "
      "model's evaluations and with physics evaluations.");
}

void Distributions(HtmlReport& html, const FidelityResult& r) {
  ScatterChart scatter;
  scatter.title = "utility: coarse model vs physics";
  scatter.x_label = "coarse utility";
  scatter.y_label = "physics utility";
  scatter.series_names = {"coarse N samples", "coarse converged"};
  for (const SituationFidelity& s : r.situations) {
    for (const CandidateScore& c : s.candidates) {
      const std::string label =
          s.situation.name + ": " + ActionText(s.situation, c.kick_index, c.rotation_rad);
      scatter.points.push_back(
          {c.coarse.utility, c.physics.utility, c.physics_ci.low, c.physics_ci.high, label, 0});
      scatter.points.push_back(
          {c.converged.utility, c.physics.utility, c.physics_ci.low, c.physics_ci.high, label, 1});
    }
  }
  HistogramChart tau;
  tau.title = "Kendall tau-b per situation (coarse N)";
  tau.x_label = "tau-b";
  HistogramChart regret;
  regret.title = "regret per situation (coarse N)";
  regret.x_label = "physics utility lost";
  for (const SituationFidelity& s : r.situations) {
    tau.values.push_back(s.coarse.tau_b);
    regret.values.push_back(s.coarse.regret);
  }
  tau.bins = regret.bins = 10;
  html.Figure(ScatterSvg(scatter),
              "Every candidate of every situation; bars: the physics utility's interval.");
  html.FigureRow({{HistogramSvg(tau), "Rank agreement between coarse model and physics."},
                  {HistogramSvg(regret), "Physics utility lost by the coarse choice."}});
}

std::string SituationDrawing(const SituationFidelity& s) {
  const Situation& sit = s.situation;
  FieldCanvas canvas(sit.field, 60.0, 0.0);
  canvas.DrawField();
  for (const Obstacle& o : sit.obstacles) {
    canvas.DrawDot(o.p_F, canvas.Px(o.radius_m), "fill:#444;fill-opacity:0.85;stroke:#000");
  }
  canvas.DrawRobot(sit.state.robot, 0.12, "#dddddd");
  for (const Outcome& o : s.coarse_outcomes) {
    canvas.DrawDot(o.p_F_rest, 3.5, "fill:#0072B2;fill-opacity:0.7");
  }
  for (const Outcome& o : s.physics_outcomes) {
    canvas.DrawDot(o.p_F_rest, 3.5, "fill:none;stroke:#D55E00;stroke-width:1.5");
  }
  const Vec2 ball = sit.state.MeanBallInField();
  canvas.DrawDot(ball, canvas.Px(sit.field.ball.radius_m), "fill:#ff7f00;stroke:#000");
  const CandidateScore& choice = s.candidates[s.coarse.choice];
  canvas.DrawArrow(ball, ball + 0.6 * UnitVector(sit.state.robot.theta_rad + choice.rotation_rad),
                   "#000000");
  return canvas.svg().Finish();
}

void WorstSituations(HtmlReport& html, const FidelityResult& r) {
  html.Heading(2, "The worst situations");
  html.Paragraph(
      "Ordered by regret, then tau. Filled blue: the coarse model's samples of its "
      "chosen action; orange rings: where physics put the ball for the same action; "
      "arrow: the robot's heading after its turn.");
  const std::vector<int> order = WorstFirst(r);
  const std::vector<int> viewed = FidelityViewSituations(r.situations);
  for (std::size_t i = 0; i < order.size() && i < 10; ++i) {
    const SituationFidelity& s = r.situations[order[i]];
    const CandidateScore& choice = s.candidates[s.coarse.choice];
    const CandidateScore& best = s.candidates[s.physics_best];
    html.Heading(3,
                 std::to_string(i + 1) + ". " + s.situation.name + " (" + s.situation_class + ")");
    html.Figure(SituationDrawing(s),
                "coarse choice " + ActionText(s.situation, choice.kick_index, choice.rotation_rad) +
                    " (physics utility " + Fixed(choice.physics.utility, 3) + "), physics best " +
                    ActionText(s.situation, best.kick_index, best.rotation_rad) + " (" +
                    Fixed(best.physics.utility, 3) + " [" + Fixed(best.physics_ci.low, 3) + ", " +
                    Fixed(best.physics_ci.high, 3) + "]); tau-b " + Fixed(s.coarse.tau_b, 3) +
                    ", regret " + Fixed(s.coarse.regret, 3));
    const auto view = std::find(viewed.begin(), viewed.end(), order[i]);
    if (view != viewed.end()) {
      html.Link(FidelityViewFile(static_cast<int>(view - viewed.begin())),
                "See it in 3D: the coarse choice's and physics's best candidate's first " +
                    std::to_string(kFidelityViewTrials) + " physics trials");
    }
  }
}

}  // namespace

std::string FidelityHtml(const FidelityRun& run) {
  const FidelityResult& r = run.result;
  HtmlReport html("Fidelity: coarse model vs physics");
  std::string rotations;
  for (double rot : run.rotations_rad) {
    if (!rotations.empty()) rotations += ' ';
    rotations += Fixed(rot * kRadToDeg, 0);
  }
  const RunProvenance& p = run.provenance;
  std::vector<std::pair<std::string, std::string>> header{
      {"situations", p.Input("situations_set") + " (" + std::to_string(r.situations.size()) + ", " +
                         p.Input("set_file") + ")"},
      {"candidate rotations (deg)", rotations},
      {"coarse samples N", std::to_string(r.coarse_samples)},
      {"converged samples", std::to_string(run.settings.converged_samples)},
      {"physics trials M", std::to_string(run.settings.physics_trials) + " per candidate (" +
                               std::to_string(r.physics_trials_run) + " in all; " +
                               StatusCountsText(r.physics_status) + ")"},
      {"seed", std::to_string(p.seed)},
      {"robot", p.Input("robot")},
      {"field", p.Input("field")},
      {"kick model", p.Input("kick_model") + " (" + p.Input("kick_model_hash") + ")"},
      {"physics", p.Input("physics_file")},
      {"robot base", p.Input("robot_base")}};
  for (auto& row : ProvenanceRows(p)) header.push_back(std::move(row));
  html.KeyValues(header);
  html.Heading(2, "Agreement");
  SummaryTables(html, r);
  Distributions(html, r);
  WorstSituations(html, r);
  return html.Finish();
}

}  // namespace foresight
