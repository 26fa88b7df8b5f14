#include "report/charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include "common/quantile.h"
#include "report/chart_axes.h"
#include "report/svg_writer.h"

namespace foresight {
namespace {

using N = SvgWriter;

constexpr std::string_view kCurveStyle = "fill:none;stroke:#D55E00;stroke-width:2";
constexpr std::string_view kMarkerLineStyle =
    "stroke:#000000;stroke-width:1.5;stroke-dasharray:6 4";
constexpr std::string_view kIdentityStyle = "stroke:#777777;stroke-width:1.2;stroke-dasharray:5 4";
constexpr std::string_view kPointStyle =
    "fill:#0072B2;fill-opacity:0.45;stroke:#0072B2;stroke-width:0.8";
constexpr std::string_view kRayStyle = "stroke:#D55E00;stroke-width:2.2";
constexpr std::string_view kWedgeStyle =
    "fill:#E69F00;fill-opacity:0.25;stroke:#E69F00;stroke-opacity:0.8;stroke-width:1";

std::vector<double> Finite(const std::vector<double>& values) {
  std::vector<double> out;
  for (double v : values) {
    if (std::isfinite(v)) out.push_back(v);
  }
  return out;
}

std::string Short(double value) {  // tooltips
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

std::string Degrees(double rad) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%+.1f\u00b0", rad * 180.0 / std::numbers::pi);
  return buffer;
}

int FreedmanDiaconisBins(const std::vector<double>& sorted, double span) {
  const double n = static_cast<double>(sorted.size());
  const double width =
      2.0 * (QuantileOfSorted(sorted, 0.75) - QuantileOfSorted(sorted, 0.25)) / std::cbrt(n);
  const double bins = width > 0.0 ? std::ceil(span / width) : std::ceil(std::sqrt(n));
  return static_cast<int>(std::clamp(bins, 5.0, 60.0));
}

PlotSpec BaseSpec(const ChartSize& size, std::string title, std::string x_label,
                  std::string y_label) {
  PlotSpec spec;
  spec.size = size;
  spec.title = std::move(title);
  spec.x_label = std::move(x_label);
  spec.y_label = std::move(y_label);
  return spec;
}

}  // namespace

std::string HistogramSvg(const HistogramChart& chart) {
  std::vector<double> values = Finite(chart.values);
  std::sort(values.begin(), values.end());
  const std::vector<double> markers = Finite(chart.markers);
  const int n = static_cast<int>(values.size());
  const int skipped = static_cast<int>(chart.values.size()) - n;

  PlotSpec spec = BaseSpec(chart.size, chart.title, chart.x_label, "count");
  if (values.empty()) {
    spec.x = markers.empty() ? AxisRange{0.0, 1.0}
                             : PaddedRange(*std::min_element(markers.begin(), markers.end()),
                                           *std::max_element(markers.begin(), markers.end()), 0.05);
    spec.x_ticks = NiceTicks(spec.x.lo, spec.x.hi);
    spec.y_ticks = CoveringTicks(&spec.y, 5, true);
    PlotFrame frame(std::move(spec));
    frame.NoData();
    return frame.Finish();
  }

  // Bins over the data range (a single repeated value gets a small range around it).
  const AxisRange data = values.front() < values.back()
                             ? AxisRange{values.front(), values.back()}
                             : PaddedRange(values.front(), values.back(), 0.0);
  const int bins =
      chart.bins > 0 ? std::min(chart.bins, 500) : FreedmanDiaconisBins(values, data.hi - data.lo);
  const double width = (data.hi - data.lo) / bins;
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  for (double v : values) {
    const int i = std::clamp(static_cast<int>(std::floor((v - data.lo) / width)), 0, bins - 1);
    ++counts[static_cast<std::size_t>(i)];
  }
  const int max_count = *std::max_element(counts.begin(), counts.end());

  double x_lo = data.lo, x_hi = data.hi;
  for (double m : markers) {
    x_lo = std::min(x_lo, m);
    x_hi = std::max(x_hi, m);
  }
  spec.x = PaddedRange(x_lo, x_hi, 0.03);
  spec.x_ticks = NiceTicks(spec.x.lo, spec.x.hi);

  // The density scaled to counts, sampled across the plot; non-finite or negative values break
  // the curve.
  std::vector<std::pair<double, double>> curve;
  double curve_max = 0.0;
  if (chart.density) {
    constexpr int kSamples = 240;
    for (int i = 0; i <= kSamples; ++i) {
      const double x = spec.x.lo + (spec.x.hi - spec.x.lo) * i / kSamples;
      const double y = n * width * chart.density(x);
      curve.emplace_back(x, y);
      if (std::isfinite(y)) curve_max = std::max(curve_max, y);
    }
  }
  spec.y = {0.0, 1.05 * std::max<double>(max_count, std::min(curve_max, 4.0 * max_count))};
  spec.y_ticks = CoveringTicks(&spec.y, 5, true);

  if (chart.density || !markers.empty() || skipped > 0) {
    std::string data_label = "data (n = " + std::to_string(n);
    if (skipped > 0) data_label += ", " + std::to_string(skipped) + " non-finite skipped";
    spec.legend.push_back({LegendEntry::Kind::kSwatch, std::string(kBarStyle), data_label + ")"});
    if (chart.density) {
      spec.legend.push_back({LegendEntry::Kind::kLine, std::string(kCurveStyle),
                             chart.density_label.empty() ? "fitted density" : chart.density_label});
    }
    if (!markers.empty()) {
      spec.legend.push_back({LegendEntry::Kind::kLine, std::string(kMarkerLineStyle),
                             chart.markers_label.empty() ? "marker" : chart.markers_label});
    }
  }

  PlotFrame frame(std::move(spec));
  SvgWriter& svg = frame.svg();
  for (int i = 0; i < bins; ++i) {
    const int c = counts[static_cast<std::size_t>(i)];
    if (c == 0) continue;
    const double a = data.lo + i * width, b = data.lo + (i + 1) * width;
    svg.OpenGroup("class=\"bar\"");
    svg.Title(std::string("[") + Short(a) + ", " + Short(b) + "): " + std::to_string(c));
    svg.Rect(frame.X(a), frame.Y(c), frame.X(b) - frame.X(a), frame.Y(0) - frame.Y(c), kBarStyle);
    svg.CloseGroup();
  }
  if (!curve.empty()) {
    PolylinePath path;
    for (const auto& [x, y] : curve) {
      if (!std::isfinite(y) || y < 0.0) {
        path.Break();
        continue;
      }
      path.Point(frame.X(x), std::max(frame.Y(y), frame.top()));
    }
    if (!path.empty()) svg.Path(path.data(), kCurveStyle);
  }
  for (double m : markers) {
    svg.OpenGroup("class=\"marker\"");
    svg.Title((chart.markers_label.empty() ? "marker" : chart.markers_label) + ": " + Short(m));
    svg.Line(frame.X(m), frame.top(), frame.X(m), frame.bottom(), kMarkerLineStyle);
    svg.CloseGroup();
  }
  return frame.Finish();
}

std::string QqSvg(const QqChart& chart) {
  std::vector<QqPoint> points;
  for (const QqPoint& p : chart.points) {
    if (std::isfinite(p.theoretical) && std::isfinite(p.observed)) points.push_back(p);
  }
  const std::string unit = chart.unit.empty() ? "" : " (" + chart.unit + ")";
  PlotSpec spec = BaseSpec(chart.size, chart.title, "normal quantile" + unit, "observed" + unit);
  if (!points.empty()) {
    double lo = points.front().observed, hi = lo;
    for (const QqPoint& p : points) {
      lo = std::min({lo, p.theoretical, p.observed});
      hi = std::max({hi, p.theoretical, p.observed});
    }
    spec.x = spec.y = PaddedRange(lo, hi, 0.05);
    spec.legend = {{LegendEntry::Kind::kPoint, std::string(kPointStyle),
                    "sample (n = " + std::to_string(points.size()) + ")"},
                   {LegendEntry::Kind::kLine, std::string(kCurveStyle), "y = x"}};
  }
  spec.x_ticks = NiceTicks(spec.x.lo, spec.x.hi);
  spec.y_ticks = NiceTicks(spec.y.lo, spec.y.hi);
  const AxisRange range = spec.x;
  PlotFrame frame(std::move(spec));
  if (points.empty()) {
    frame.NoData();
    return frame.Finish();
  }
  SvgWriter& svg = frame.svg();
  svg.Line(frame.X(range.lo), frame.Y(range.lo), frame.X(range.hi), frame.Y(range.hi), kCurveStyle);
  for (const QqPoint& p : points) {
    svg.Circle(frame.X(p.theoretical), frame.Y(p.observed), 3.2, kPointStyle);
  }
  return frame.Finish();
}

std::string RoseSvg(const RoseChart& chart) {
  constexpr double kPi = std::numbers::pi;
  const double w = chart.size.width_px, h = chart.size.height_px;
  const std::vector<double> angles = Finite(chart.angles_rad);
  const int sectors = std::clamp(chart.sectors, 4, 360);
  const double sector = 2.0 * kPi / sectors;
  std::vector<int> counts(static_cast<std::size_t>(sectors), 0);
  for (double a : angles) {  // sector i is centred on i * sector
    double t = std::fmod(a + sector / 2.0, 2.0 * kPi);
    if (t < 0.0) t += 2.0 * kPi;
    ++counts[static_cast<std::size_t>(std::min(static_cast<int>(t / sector), sectors - 1))];
  }
  const int max_count = *std::max_element(counts.begin(), counts.end());
  const bool has_data = !angles.empty();
  const bool has_mean = has_data && std::isfinite(chart.fitted_mean_rad);
  const bool has_wedge = has_mean && std::isfinite(chart.fitted_sd_rad) && chart.fitted_sd_rad > 0;

  std::vector<LegendEntry> legend;
  if (has_data) {
    legend.push_back({LegendEntry::Kind::kSwatch, std::string(kBarStyle),
                      "directions (n = " + std::to_string(angles.size()) + ")"});
  }
  if (has_mean) {
    legend.push_back({LegendEntry::Kind::kLine, std::string(kRayStyle),
                      "mean " + Degrees(chart.fitted_mean_rad)});
  }
  if (has_wedge) {
    legend.push_back({LegendEntry::Kind::kSwatch, std::string(kWedgeStyle),
                      "mean \u00b1 sd (sd " + Degrees(chart.fitted_sd_rad).substr(1) + ")"});
  }

  SvgWriter svg(w, h);
  svg.Rect(0, 0, w, h, "fill:#ffffff");
  const double title_height = chart.title.empty() ? 8.0 : 28.0;
  if (!chart.title.empty()) svg.Text(w / 2.0, 19.0, chart.title, kTitleStyle);
  const double legend_height = DrawLegend(&svg, 12.0, title_height, w - 24.0, legend);
  const double top = title_height + legend_height + 6.0, bottom = h - 20.0;
  const double radius = std::max(10.0, std::min(w / 2.0 - 42.0, (bottom - top) / 2.0 - 16.0));
  const double cx = w / 2.0, cy = (top + bottom) / 2.0;
  // Robot frame to page: angle 0 points up, +pi/2 points left.
  const auto px = [&](double a, double r) { return cx - r * std::sin(a); };
  const auto py = [&](double a, double r) { return cy - r * std::cos(a); };
  const auto wedge = [&](double a0, double a1, double r) {
    return "M " + N::Num(cx) + " " + N::Num(cy) + " L " + N::Num(px(a0, r)) + " " +
           N::Num(py(a0, r)) + " A " + N::Num(r) + " " + N::Num(r) + " 0 " +
           (a1 - a0 > kPi ? "1" : "0") + " 0 " + N::Num(px(a1, r)) + " " + N::Num(py(a1, r)) + " Z";
  };

  // Count rings and direction spokes.
  AxisRange count_range{0.0, std::max(1.0, static_cast<double>(max_count))};
  const AxisTicks rings = CoveringTicks(&count_range, 4, true);
  const double per_count = radius / count_range.hi;
  for (double v : rings.values) {
    if (v > 0.0) svg.Circle(cx, cy, v * per_count, "fill:none;" + std::string(kGridStyle));
  }
  for (int deg = 0; deg < 360; deg += 30) {
    const double a = deg * kPi / 180.0;
    svg.Line(cx, cy, px(a, radius), py(a, radius), kGridStyle);
  }
  svg.Circle(cx, cy, radius, "fill:none;stroke:#aaaaaa;stroke-width:1");

  if (has_wedge) {  // under the sectors, so they keep their colour
    const double sd = chart.fitted_sd_rad, mean = chart.fitted_mean_rad;
    if (2.0 * sd >= 2.0 * kPi) {
      svg.Circle(cx, cy, radius, kWedgeStyle);
    } else {
      svg.Path(wedge(mean - sd, mean + sd, radius), kWedgeStyle);
    }
  }
  for (int i = 0; i < sectors; ++i) {
    const int c = counts[static_cast<std::size_t>(i)];
    if (c == 0) continue;
    const double a0 = i * sector - sector / 2.0, a1 = a0 + sector;
    svg.OpenGroup("class=\"sector\"");
    svg.Title(std::string("[") + Degrees(a0) + ", " + Degrees(a1) + "): " + std::to_string(c));
    svg.Path(wedge(a0, a1, c * per_count), kBarStyle);
    svg.CloseGroup();
  }
  if (has_mean) {
    const double a = chart.fitted_mean_rad;
    svg.OpenGroup("class=\"mean\"");
    svg.Title("mean " + Degrees(a));
    svg.Line(cx, cy, px(a, radius), py(a, radius), kRayStyle);
    svg.CloseGroup();
  }

  // Count labels inside the rings beside the backward spoke (kicks rarely go backwards), angle
  // labels outside the circle.
  for (double v : has_data ? rings.values : std::vector<double>{}) {
    if (v > 0.0) {
      svg.Text(cx + 3.0, cy + v * per_count - 3.0, FormatTick(v, 0), "font-size:10px;fill:#777777");
    }
  }
  for (int deg = -135; deg <= 180; deg += 45) {
    const double a = deg * kPi / 180.0;
    const double x = px(a, radius + 8.0), y = py(a, radius + 8.0);
    const char* anchor = x < cx - 1.0 ? "end" : x > cx + 1.0 ? "start" : "middle";
    const double dy = y < cy - 1.0 ? -1.0 : y > cy + 1.0 ? 10.0 : 4.0;
    std::string label = deg > 0 && deg < 180 ? "+" : "";
    label += std::to_string(deg) + "\u00b0";
    svg.Text(x, y + dy, label, std::string(kTickStyle) + ";text-anchor:" + anchor);
  }
  svg.Text(w / 2.0, h - 6.0, "robot frame: 0\u00b0 ahead (up), +90\u00b0 left",
           std::string(kTickStyle) + ";text-anchor:middle");
  if (!has_data) svg.Text(cx, cy + 4.0, "no data", kNoDataStyle);
  return svg.Finish();
}

std::string ScatterSvg(const ScatterChart& chart) {
  struct Point {
    ScatterPoint p;
    bool interval;
  };
  std::vector<Point> points;
  for (const ScatterPoint& p : chart.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    Point q{p, std::isfinite(p.y_low) && std::isfinite(p.y_high) && p.y_low != p.y_high};
    if (q.interval && q.p.y_low > q.p.y_high) std::swap(q.p.y_low, q.p.y_high);
    points.push_back(q);
  }
  PlotSpec spec = BaseSpec(chart.size, chart.title, chart.x_label, chart.y_label);
  if (!points.empty()) {
    double x_lo = points.front().p.x, x_hi = x_lo, y_lo = points.front().p.y, y_hi = y_lo;
    for (const Point& q : points) {
      x_lo = std::min(x_lo, q.p.x);
      x_hi = std::max(x_hi, q.p.x);
      y_lo = std::min({y_lo, q.p.y, q.interval ? q.p.y_low : q.p.y});
      y_hi = std::max({y_hi, q.p.y, q.interval ? q.p.y_high : q.p.y});
    }
    spec.x = PaddedRange(x_lo, x_hi, 0.05);
    spec.y = PaddedRange(y_lo, y_hi, 0.05);
  }
  spec.x_ticks = NiceTicks(spec.x.lo, spec.x.hi);
  spec.y_ticks = NiceTicks(spec.y.lo, spec.y.hi);
  const double id_lo = std::max(spec.x.lo, spec.y.lo), id_hi = std::min(spec.x.hi, spec.y.hi);
  const bool identity = chart.identity_line && !points.empty() && id_hi > id_lo;

  // Legend: the series that occur, in index order, then the identity line.
  std::vector<int> used;
  for (const Point& q : points) used.push_back(std::max(q.p.series, 0));
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  const auto point_style = [](int series) {
    return "fill:" + std::string(PaletteColour(series)) +
           ";fill-opacity:0.85;stroke:#ffffff;stroke-width:0.7";
  };
  if (used.size() > 1 || !chart.series_names.empty()) {
    for (int s : used) {
      const auto index = static_cast<std::size_t>(s);
      spec.legend.push_back({LegendEntry::Kind::kPoint, point_style(s),
                             index < chart.series_names.size() ? chart.series_names[index]
                                                               : "series " + std::to_string(s),
                             s});
    }
  }
  if (identity) {
    spec.legend.push_back({LegendEntry::Kind::kLine, std::string(kIdentityStyle), "y = x"});
  }

  PlotFrame frame(std::move(spec));
  if (points.empty()) {
    frame.NoData();
    return frame.Finish();
  }
  SvgWriter& svg = frame.svg();
  if (identity) {
    svg.Line(frame.X(id_lo), frame.Y(id_lo), frame.X(id_hi), frame.Y(id_hi), kIdentityStyle);
  }
  for (const Point& q : points) {
    const ScatterPoint& p = q.p;
    const int s = std::max(p.series, 0);
    const std::string colour(PaletteColour(s));
    const double x = frame.X(p.x);
    std::string tip =
        (p.label.empty() ? "" : p.label + ": ") + "x = " + Short(p.x) + ", y = " + Short(p.y);
    if (q.interval) tip += " [" + Short(p.y_low) + ", " + Short(p.y_high) + "]";
    svg.OpenGroup("class=\"point\"");
    svg.Title(tip);
    if (q.interval) {
      const std::string bar = "stroke:" + colour + ";stroke-width:1.2;stroke-opacity:0.7";
      const double y0 = frame.Y(p.y_low), y1 = frame.Y(p.y_high);
      svg.Line(x, y0, x, y1, bar);
      svg.Line(x - 3.0, y0, x + 3.0, y0, bar);
      svg.Line(x - 3.0, y1, x + 3.0, y1, bar);
    }
    DrawMarker(svg, x, frame.Y(p.y), 3.6, s, point_style(s));
    svg.CloseGroup();
  }
  return frame.Finish();
}

}  // namespace foresight
