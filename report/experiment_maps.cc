#include "report/experiment_maps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/chart_axes.h"
#include "report/field_svg.h"
#include "report/svg_writer.h"

namespace foresight {
namespace {

using N = SvgWriter;

constexpr double kRobotRadiusM = 0.15;
constexpr std::string_view kRobotColour = "#9e9e9e";
constexpr double kBarWidthPx = 16.0;   // the colour bar
constexpr int kBarSteps = 64;          // colour bands drawn to approximate the continuous ramp
constexpr double kLegendRowPx = 20.0;  // ball paths' legend

// Viridis (van der Walt & Smith, matplotlib's default colour map): perceptually uniform, readable
// in grey and by the colour-blind. These are its colours sampled at t = 0, 1/8, ..., 1; straight
// lines between them stay within a few levels of the full 256-entry table.
constexpr std::array<std::array<int, 3>, 9> kViridis = {{{0x44, 0x01, 0x54},
                                                         {0x47, 0x2d, 0x7b},
                                                         {0x3b, 0x52, 0x8b},
                                                         {0x2c, 0x72, 0x8e},
                                                         {0x21, 0x91, 0x8c},
                                                         {0x28, 0xae, 0x80},
                                                         {0x5e, 0xc9, 0x62},
                                                         {0xad, 0xdc, 0x30},
                                                         {0xfd, 0xe7, 0x25}}};

std::string CellTip(const Vec2& centre, double value) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.3g, %.3g) m: %.3g", centre.x(), centre.y(), value);
  return buffer;
}

// The scale's ends; a degenerate or non-finite one falls back to [0, 1] rather than dividing by
// zero.
AxisRange Scale(const FieldCellMap& map) {
  const bool ok =
      std::isfinite(map.value_lo) && std::isfinite(map.value_hi) && map.value_hi > map.value_lo;
  return ok ? AxisRange{map.value_lo, map.value_hi} : AxisRange{0.0, 1.0};
}

// The title in the canvas's top margin, centred over the carpet.
void DrawTitle(FieldCanvas& canvas, const std::string& title) {
  if (title.empty()) return;
  canvas.svg().Text(canvas.X(0.0), 15.0, title, kTitleStyle);
}

// The field lines and goal posts again, over the cells (same geometry and style as
// FieldCanvas::DrawField, which draws them under anything added later).
// The cells cover the lines and the posts half over the outermost cells: redrawn on top.
void DrawFieldLines(FieldCanvas& canvas) {
  canvas.svg().OpenGroup("class=\"field-lines\"");
  canvas.DrawLinesAndPosts();
  canvas.svg().CloseGroup();
}

void DrawCells(FieldCanvas& canvas, const FieldCellMap& map, AxisRange scale) {
  const double half = 0.5 * map.cell_size_m, side = canvas.Px(map.cell_size_m);
  for (std::size_t i = 0; i < map.values.size(); ++i) {
    const double v = map.values[i];
    const Vec2& c = map.cell_centres_F[i];
    if (!std::isfinite(v) || !std::isfinite(c.x()) || !std::isfinite(c.y())) continue;
    const std::string colour = SequentialColour((v - scale.lo) / (scale.hi - scale.lo));
    canvas.svg().OpenGroup("class=\"cell\"");
    canvas.svg().Title(CellTip(c, v));
    // A hairline of the same colour closes the anti-aliasing seams between neighbours.
    canvas.svg().Rect(canvas.X(c.x() - half), canvas.Y(c.y() + half), side, side,
                      "fill:" + colour + ";stroke:" + colour + ";stroke-width:0.5");
    canvas.svg().CloseGroup();
  }
}

// Room right of the carpet for the colour bar, its tick labels and its rotated label.
double ColourBarWidth(const AxisTicks& ticks) {
  double labels = 0.0;
  for (double v : ticks.values) {
    labels = std::max(labels, TextWidthPx(FormatTick(v, ticks.decimals), 11.0));
  }
  return kBarWidthPx + 7.0 + labels + 30.0;
}

// A vertical ramp beside the field (as tall as the field), low values at the bottom.
void DrawColourBar(FieldCanvas& canvas, const FieldSpec& field, const FieldCellMap& map,
                   AxisRange scale, const AxisTicks& ticks) {
  SvgWriter& svg = canvas.svg();
  const double x = canvas.legend_x();
  const double top = canvas.Y(field.HalfWidth()), bottom = canvas.Y(-field.HalfWidth());
  const double band = (bottom - top) / kBarSteps;
  svg.OpenGroup("class=\"colour-bar\"");
  for (int i = 0; i < kBarSteps; ++i) {  // bands overlap by half a pixel to avoid seams
    const double t = (i + 0.5) / kBarSteps;
    svg.Rect(x, bottom - (i + 1) * band, kBarWidthPx, band + (i + 1 < kBarSteps ? 0.5 : 0.0),
             "fill:" + SequentialColour(t));
  }
  svg.Rect(x, top, kBarWidthPx, bottom - top, "fill:none;" + std::string(kAxisStyle));
  double label_width = 0.0;
  for (double v : ticks.values) {
    const double y = bottom - (v - scale.lo) / (scale.hi - scale.lo) * (bottom - top);
    const std::string label = FormatTick(v, ticks.decimals);
    label_width = std::max(label_width, TextWidthPx(label, 11.0));
    svg.Line(x + kBarWidthPx, y, x + kBarWidthPx + 4.0, y, kAxisStyle);
    svg.Text(x + kBarWidthPx + 7.0, y + 4.0, label, kTickStyle);
  }
  svg.CloseGroup();
  if (map.value_label.empty()) return;
  const double lx = x + kBarWidthPx + 7.0 + label_width + 14.0;
  svg.OpenGroup("transform=\"translate(" + N::Num(lx) + "," + N::Num((top + bottom) / 2.0) +
                ") rotate(-90)\"");
  svg.Text(0, 0, map.value_label, kLabelStyle);
  svg.CloseGroup();
}

// The ball's positions joined by a line that breaks at non-finite positions; a circle at each,
// the start hollow.
// Paths drawn earlier are wider, so a later path that retraces one (two strategies often take
// the same kicks) leaves the earlier colour visible along its edges.
void DrawBallPath(FieldCanvas& canvas, const BallPath& path, int index, int count) {
  const double width_px = 2.2 + 2.0 * (count - 1 - index);
  SvgWriter& svg = canvas.svg();
  const std::string colour(PaletteColour(index));
  svg.OpenGroup("class=\"ball-path\"");
  svg.Title(path.name);
  PolylinePath line;
  for (const Vec2& b : path.balls_F) {
    if (std::isfinite(b.x()) && std::isfinite(b.y())) {
      line.Point(canvas.X(b.x()), canvas.Y(b.y()));
    } else {
      line.Break();
    }
  }
  if (!line.empty()) {  // a pale casing keeps dark or green lines visible on the green carpet
    svg.Path(line.data(), "fill:none;stroke:#ffffff;stroke-opacity:0.6;stroke-width:" +
                              N::Num(width_px + 2.8) + ";stroke-linejoin:round");
    svg.Path(line.data(), "fill:none;stroke:" + colour + ";stroke-width:" + N::Num(width_px) +
                              ";stroke-linejoin:round");
  }
  bool first = true;
  for (const Vec2& b : path.balls_F) {
    if (!std::isfinite(b.x()) || !std::isfinite(b.y())) continue;
    canvas.DrawDot(b, first ? 5.0 : 4.0,
                   first ? "fill:none;stroke:" + colour + ";stroke-width:2"
                         : "fill:" + colour + ";stroke:#ffffff;stroke-width:1");
    first = false;
  }
  svg.CloseGroup();
}

std::vector<std::string> LegendNotes() {
  return {"hollow circle: the ball at the start", "dots: the ball after each kick",
          "grey: the robot at the start"};
}

double PathLegendWidth(const BallPathsMap& map) {
  double width = 0.0;
  for (const BallPath& p : map.paths) width = std::max(width, 30.0 + TextWidthPx(p.name, 12.0));
  for (const std::string& note : LegendNotes()) width = std::max(width, TextWidthPx(note, 11.0));
  return width + 20.0;
}

// One row per path (line, dot and name), then what the symbols mean; rows shrink to fit the
// canvas's height when there are many paths.
void DrawPathLegend(FieldCanvas& canvas, const BallPathsMap& map) {
  SvgWriter& svg = canvas.svg();
  const double x = canvas.legend_x();
  double y = 34.0;
  const double notes = 16.0 * LegendNotes().size() + 10.0;
  const double rows = std::max<double>(map.paths.size(), 1.0);
  const double row = std::min(kLegendRowPx, (canvas.height() - 20.0 - y - notes) / rows);
  if (map.paths.empty()) {
    svg.Text(x, y, "no data", std::string(kNoDataStyle) + ";text-anchor:start");
    y += row;
  }
  for (std::size_t i = 0; i < map.paths.size(); ++i, y += row) {
    const std::string colour(PaletteColour(static_cast<int>(i)));
    svg.Line(x, y - 4.0, x + 22.0, y - 4.0, "stroke:" + colour + ";stroke-width:2.2");
    svg.Circle(x + 11.0, y - 4.0, 4.0, "fill:" + colour + ";stroke:#ffffff;stroke-width:1");
    svg.Text(x + 30.0, y, map.paths[i].name, "font-size:12px;fill:#222222");
  }
  y += 10.0;
  for (const std::string& note : LegendNotes()) {
    svg.Text(x, y, note, "font-size:11px;fill:#555555");
    y += 16.0;
  }
}

}  // namespace

std::string SequentialColour(double t) {
  // NaN has no place on the scale; it gets the low end rather than undefined arithmetic.
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  const double pos = t * (kViridis.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(pos), kViridis.size() - 2);
  const double f = pos - static_cast<double>(i);
  char buffer[8];
  int rgb[3];
  for (int c = 0; c < 3; ++c) {
    rgb[c] =
        static_cast<int>(std::lround(kViridis[i][c] + f * (kViridis[i + 1][c] - kViridis[i][c])));
  }
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return buffer;
}

std::string FieldCellMapSvg(const FieldSpec& field, const FieldCellMap& map) {
  if (map.cell_centres_F.size() != map.values.size()) {
    throw std::invalid_argument("FieldCellMapSvg: " + std::to_string(map.cell_centres_F.size()) +
                                " cell centres but " + std::to_string(map.values.size()) +
                                " values");
  }
  const AxisRange scale = Scale(map);
  const AxisTicks ticks = NiceTicks(scale.lo, scale.hi, 5);
  FieldCanvas canvas(field, map.pixels_per_m, ColourBarWidth(ticks));
  canvas.DrawField();
  DrawCells(canvas, map, scale);
  DrawFieldLines(canvas);
  DrawTitle(canvas, map.title);
  DrawColourBar(canvas, field, map, scale, ticks);
  const bool any =
      std::any_of(map.values.begin(), map.values.end(), [](double v) { return std::isfinite(v); });
  if (!any) canvas.svg().Text(canvas.X(0.0), canvas.Y(0.0) + 4.0, "no data", kNoDataStyle);
  return canvas.svg().Finish();
}

std::string BallPathsSvg(const FieldSpec& field, const BallPathsMap& map) {
  FieldCanvas canvas(field, map.pixels_per_m, PathLegendWidth(map));
  canvas.DrawField();
  DrawTitle(canvas, map.title);
  canvas.DrawRobot(map.robot_start, kRobotRadiusM, kRobotColour);
  for (std::size_t i = 0; i < map.paths.size(); ++i) {
    DrawBallPath(canvas, map.paths[i], static_cast<int>(i), static_cast<int>(map.paths.size()));
  }
  DrawPathLegend(canvas, map);
  return canvas.svg().Finish();
}

}  // namespace foresight
