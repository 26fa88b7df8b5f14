#include "app/cbr_drawing.h"

#include <cmath>
#include <string>
#include <vector>

#include "cbr/free_path.h"
#include "cbr/own_situation.h"
#include "cbr/similarity.h"
#include "report/field_svg.h"
#include "report/report_format.h"

namespace foresight {

namespace {

constexpr double kRobotRadiusM = 0.12;
constexpr const char* kTeamColour = "#3b7ddd";
constexpr const char* kOpponentColour = "#d7301f";
constexpr const char* kBallStyle = "fill:#ff7f00;stroke:#000;stroke-width:1";
constexpr const char* kBallScopeStyle =
    "fill:#ff7f00;fill-opacity:0.10;stroke:#ff7f00;stroke-width:2;stroke-dasharray:6 4";
constexpr const char* kOpponentScopeStyle =
    "fill:#d7301f;fill-opacity:0.12;stroke:#d7301f;stroke-width:1.5;stroke-dasharray:5 3";
constexpr const char* kTrajectoryStyle =
    "fill:#ffe066;fill-opacity:0.45;stroke:#b8860b;stroke-width:1.2";

// The exp(-1) edge of a scope Gaussian: the ellipse with radii tau.
void Ellipse(FieldCanvas& canvas, const Vec2& centre_F, const Scope& scope, std::string_view style) {
  const double rx = canvas.Px(scope.tau_x_m), ry = canvas.Px(scope.tau_y_m);
  const double cx = canvas.X(centre_F.x()), cy = canvas.Y(centre_F.y());
  const std::string a =
      " A " + SvgWriter::Num(rx) + " " + SvgWriter::Num(ry) + " 0 1 0 ";
  canvas.svg().Path("M " + SvgWriter::Num(cx - rx) + " " + SvgWriter::Num(cy) + a +
                        SvgWriter::Num(cx + rx) + " " + SvgWriter::Num(cy) + a +
                        SvgWriter::Num(cx - rx) + " " + SvgWriter::Num(cy) + " Z",
                    style);
}

// mu = exp(-1) on a fuzzy trajectory: the trapezoid of Fig. 7a.
void Trapezoid(FieldCanvas& canvas, const FuzzyTrajectory& t) {
  if (t.length_m <= 0.0) return;
  const Vec2 n(-t.u.y(), t.u.x());
  const Vec2 end = t.start_F + t.length_m * t.u;
  const Vec2 knee = t.start_F + (t.knee_m > 0.0 ? t.knee_m : t.length_m) * t.u;
  const Vec2 corners[6] = {t.start_F + t.r_start_m * n, knee + t.r_end_m * n, end + t.r_end_m * n,
                           end - t.r_end_m * n,         knee - t.r_end_m * n, t.start_F - t.r_start_m * n};
  std::string d;
  for (const Vec2& p : corners) {
    d += (d.empty() ? "M " : " L ") + SvgWriter::Num(canvas.X(p.x())) + " " +
         SvgWriter::Num(canvas.Y(p.y()));
  }
  canvas.svg().Path(d + " Z", kTrajectoryStyle);
}

// An arrow with its own style (e.g. dashed); the barbs are `barb_m` long.
void Arrow(FieldCanvas& canvas, const Vec2& from_F, const Vec2& to_F, std::string_view colour,
           double width_px, bool dashed, double barb_m) {
  const Vec2 d = to_F - from_F;
  if (d.norm() < 1e-6) return;
  const std::string stroke = "fill:none;stroke:" + std::string(colour) +
                             ";stroke-width:" + SvgWriter::Num(width_px) +
                             ";stroke-linecap:round";
  canvas.svg().Line(canvas.X(from_F.x()), canvas.Y(from_F.y()), canvas.X(to_F.x()),
                    canvas.Y(to_F.y()), stroke + (dashed ? ";stroke-dasharray:5 4" : ""));
  const double heading = std::atan2(d.y(), d.x());
  const double barb = std::min(barb_m, 0.5 * d.norm());
  auto xy = [&](const Vec2& q) {
    return SvgWriter::Num(canvas.X(q.x())) + " " + SvgWriter::Num(canvas.Y(q.y()));
  };
  const std::string path = "M " + xy(to_F - barb * UnitVector(heading - 0.45)) + " L " +
                           xy(to_F) + " L " + xy(to_F - barb * UnitVector(heading + 0.45));
  canvas.svg().Path(path, stroke);
}

void Label(FieldCanvas& canvas, const Vec2& p_F, const std::string& text, double size_px) {
  canvas.svg().Text(canvas.X(p_F.x()) + canvas.Px(kRobotRadiusM) + 1.0,
                    canvas.Y(p_F.y()) - canvas.Px(kRobotRadiusM) + 2.0, text,
                    "font-size:" + SvgWriter::Num(size_px) +
                        "px;font-weight:bold;fill:#fff;stroke:#000;stroke-width:0.6;"
                        "paint-order:stroke");
}

void Opponent(FieldCanvas& canvas, const Vec2& p_F) {
  canvas.DrawDot(p_F, canvas.Px(kRobotRadiusM),
                 std::string("fill:") + kOpponentColour + ";stroke:#111;stroke-width:1.2");
}

void Ball(FieldCanvas& canvas, const Vec2& p_F, double min_radius_px) {
  canvas.DrawDot(p_F, std::max(canvas.Px(0.042), min_radius_px), kBallStyle);
}

void Trajectories(FieldCanvas& canvas, const CaseBallPath& path, double width_px, double barb_m) {
  for (const FuzzyTrajectory& t : path.View()) Trapezoid(canvas, t);
  for (const FuzzyTrajectory& t : path.View()) {
    Arrow(canvas, t.start_F, t.start_F + t.length_m * t.u,
          t.action == ActionType::kPass ? "#222222" : "#8b0000", width_px, false, barb_m);
  }
}

void LegendLine(SvgWriter& svg, double x, double* y, const std::string& text,
                std::string_view style = "font-size:12px") {
  svg.Text(x, *y, text, style);
  *y += 16.0;
}

}  // namespace

std::string CbrRetrieveSvg(const CbrRetrieveRun& run, const FieldSpec& field) {
  FieldCanvas canvas(field, 900.0 / field.carpet_length_m, 360.0);
  canvas.DrawField();
  const Problem& p = run.problem;
  const Case* c = run.Retrieved();
  if (c != nullptr) {
    Ellipse(canvas, p.p_F_ball, c->ball_scope, kBallScopeStyle);
    for (const CaseOpponent& o : c->opponents) {
      Ellipse(canvas, MovedScopeCentre(p, *c, o), o.scope, kOpponentScopeStyle);
    }
    Trajectories(canvas, run.result.ball_path, 2.5, 0.15);
  }
  for (const Vec2& o : p.opponents) Opponent(canvas, o);
  for (const ProblemTeammate& t : p.teammates) {
    canvas.DrawRobot(t.pose, kRobotRadiusM, kTeamColour);
    Label(canvas, t.pose.p_F, std::to_string(t.id), 14.0);
  }
  if (c != nullptr) {
    const CaseEvaluation& e = *run.result.Best();
    for (int i = 0; i < e.correspondence.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const ProblemTeammate& robot =
          p.teammates[static_cast<std::size_t>(e.correspondence.problem_index[k])];
      const Vec2 to = e.correspondence.adapted_F[k];
      canvas.DrawDot(to, canvas.Px(kRobotRadiusM),
                     std::string("fill:none;stroke:") + kTeamColour +
                         ";stroke-width:2;stroke-dasharray:4 3");
      Arrow(canvas, robot.pose.p_F, to, "#0b3d91", 2.0, true, 0.12);
    }
  }
  Ball(canvas, p.p_F_ball, 4.0);

  SvgWriter& svg = canvas.svg();
  const double x = canvas.legend_x();
  double y = 34.0;
  svg.Text(x, y, "cbr retrieve", "font-size:17px;font-weight:bold");
  y += 22.0;
  LegendLine(svg, x, &y, run.problem_file.filename().string() + ", defending " +
                             std::string(DefendingGoalName(p.defending)));
  y += 8.0;
  if (c == nullptr) {
    LegendLine(svg, x, &y, "no case retrieved", "font-size:14px;font-weight:bold;fill:#a00");
    LegendLine(svg, x, &y, Format("%zu cases, 0 candidates", run.cases.size()));
  } else {
    const CaseEvaluation& e = *run.result.Best();
    LegendLine(svg, x, &y, c->name, "font-size:14px;font-weight:bold");
    LegendLine(svg, x, &y,
               Format("similarity %.3f (band %s), cost %.2f m", e.ball_similarity,
                      e.band == 0 ? "H" : e.band == 1 ? "h" : e.band == 2 ? "l" : "L",
                      e.correspondence.cost.primary));
    LegendLine(svg, x, &y,
               Format("conditions %d of %zu, teammates %d", e.conditions, c->opponents.size(),
                      e.teammates));
    for (int i = 0; i < e.correspondence.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const ProblemTeammate& robot =
          p.teammates[static_cast<std::size_t>(e.correspondence.problem_index[k])];
      LegendLine(svg, x, &y,
                 Format("robot %d plays teammate %d, walks %.2f m", robot.id, c->teammates[k].id,
                        e.correspondence.distance_m[k]));
    }
    LegendLine(svg, x, &y,
               Format("%zu candidates, ball path of %d trajectories", run.result.ranking.size(),
                      run.result.ball_path.count));
  }
  y += 14.0;
  const std::string key = "font-size:11px;fill:#444";
  svg.Circle(x + 6, y - 4, 6, std::string("fill:") + kTeamColour + ";stroke:#111");
  LegendLine(svg, x + 18, &y, "teammate (line: heading), dashed: adapted position", key);
  svg.Circle(x + 6, y - 4, 6, std::string("fill:") + kOpponentColour + ";stroke:#111");
  LegendLine(svg, x + 18, &y, "opponent", key);
  svg.Rect(x, y - 10, 12, 8, kBallScopeStyle);
  LegendLine(svg, x + 18, &y, "case ball scope at the problem ball (exp(-1))", key);
  svg.Rect(x, y - 10, 12, 8, kOpponentScopeStyle);
  LegendLine(svg, x + 18, &y, "case opponent scopes, moved with the ball", key);
  svg.Rect(x, y - 10, 12, 8, kTrajectoryStyle);
  LegendLine(svg, x + 18, &y, "ball path: mu > exp(-1) (black pass, red kick)", key);
  return svg.Finish();
}

std::string CaseSvg(const Case& c, const FieldSpec& field, const RetrievalParams& params,
                    double pixels_per_m, const std::string& warning) {
  FieldCanvas canvas(field, pixels_per_m, 0.0);
  canvas.DrawField();
  const CaseBallPath path = OwnBallPath(c, params);

  Ellipse(canvas, c.p_F_ball, c.ball_scope, kBallScopeStyle);
  for (const CaseOpponent& o : c.opponents) Ellipse(canvas, o.p_F, o.scope, kOpponentScopeStyle);
  Trajectories(canvas, path, 1.6, 0.14);
  // Walks and dribbles, in each teammate's action order.
  for (const CaseTeammate& t : c.teammates) {
    Vec2 at = t.p_F;
    for (const CaseAction& a : t.actions) {
      if ((a.type == ActionType::kGoTo || a.type == ActionType::kDribble) && a.target_F) {
        Arrow(canvas, at, *a.target_F, a.type == ActionType::kDribble ? "#ff7f00" : "#0b3d91",
              1.6, a.type == ActionType::kGoTo, 0.14);
        at = *a.target_F;
      }
    }
  }
  for (const CaseOpponent& o : c.opponents) Opponent(canvas, o.p_F);
  for (const CaseTeammate& t : c.teammates) {
    canvas.DrawRobot(Pose2{t.p_F, AttackSign(c.defending) > 0 ? 0.0 : kPi}, kRobotRadiusM,
                     kTeamColour);
    Label(canvas, t.p_F, std::to_string(t.id), 11.0);
  }
  Ball(canvas, c.p_F_ball, 3.0);
  canvas.svg().Text(canvas.X(-field.CarpetHalfLength()), 15.0,
                    c.name + " (defending " + std::string(DefendingGoalName(c.defending)) + ")",
                    "font-size:13px;font-weight:bold");
  if (!warning.empty()) {
    canvas.svg().Text(canvas.X(field.CarpetHalfLength()), 15.0, warning,
                      "font-size:12px;font-weight:bold;fill:#c00000;text-anchor:end");
  }
  return canvas.svg().Finish();
}

}  // namespace foresight
