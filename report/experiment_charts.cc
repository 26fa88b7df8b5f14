#include "report/experiment_charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "report/svg_writer.h"

namespace foresight {
namespace {

using N = SvgWriter;

constexpr double kTolerance = 1e-9;  // relative, for 1-2-5 values computed in floating point
constexpr std::string_view kMarkerLineStyle =
    "stroke:#000000;stroke-width:1.5;stroke-dasharray:6 4";

// m x 10^k, as exactly as a double allows (dividing by an exact power of ten rounds once).
double Decade(int k, double m) {
  return k >= 0 ? m * std::pow(10.0, k) : m / std::pow(10.0, -k);
}

int DecadeOf(double v) {  // k with 10^k <= v < 10^(k+1), robust to log10 rounding
  return static_cast<int>(std::floor(std::log10(v) + kTolerance));
}

// The largest 1-2-5 value <= v and the smallest >= v (v > 0).
double Floor125(double v) {
  const int k = DecadeOf(v);
  double best = Decade(k, 1.0);
  for (double m : {2.0, 5.0}) {
    if (Decade(k, m) <= v * (1.0 + kTolerance)) best = Decade(k, m);
  }
  return best;
}
double Ceil125(double v) {
  const int k = DecadeOf(v);
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (Decade(k, m) >= v * (1.0 - kTolerance)) return Decade(k, m);
  }
  return Decade(k + 1, 1.0);
}

// Log tick labels have just the decimals their value needs: "0.001", "0.5", "20".
int LogDecimals(double v) {
  return std::max(0, -DecadeOf(v));
}

std::string Short(double value) {  // tooltips
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

// Finite, and positive on a logarithmic axis.
bool Plottable(bool log, double v) {
  return std::isfinite(v) && (!log || v > 0.0);
}

// One axis in data units. PlotFrame maps its coordinate linearly and prints each tick's
// coordinate as its label (also sizing its margins from those labels), which cannot express a
// logarithmic axis directly. So a log axis hands the frame u = log10(v) + shift, and exactly one
// real tick, the one with the widest label, whose u equals its value (that fixes shift): the
// frame then prints that label correctly and reserves room for the widest one. DrawLogTicks
// draws the other ticks at the same positions.
struct Axis {
  bool log = false;
  AxisRange range;         // data units
  AxisTicks linear_ticks;  // linear axes: handed to the frame as they are
  std::vector<double> log_ticks;
  std::size_t anchor = 0;  // the log tick the frame draws
  double shift = 0.0;

  double ToFrame(double v) const { return log ? std::log10(v) + shift : v; }
  bool Drawable(double v) const { return Plottable(log, v); }
  bool Inside(double v) const {
    const double slack = kTolerance * (std::abs(range.lo) + std::abs(range.hi));
    return v >= range.lo - slack && v <= range.hi + slack;
  }
  AxisRange FrameRange() const { return {ToFrame(range.lo), ToFrame(range.hi)}; }
  AxisTicks FrameTicks() const {
    if (!log) return linear_ticks;
    if (log_ticks.empty()) return {};
    const double v = log_ticks[anchor];
    return {{v}, v, LogDecimals(v)};
  }
};

Axis LinearAxis(AxisRange range, AxisTicks ticks) {
  Axis axis;
  axis.range = range;
  axis.linear_ticks = std::move(ticks);
  return axis;
}

Axis LogAxis(AxisRange range) {
  Axis axis;
  axis.log = true;
  axis.range = range;
  axis.log_ticks = LogTicks(range.lo, range.hi);
  double widest = -1.0;
  for (std::size_t i = 0; i < axis.log_ticks.size(); ++i) {
    const double v = axis.log_ticks[i];
    const double width = TextWidthPx(FormatTick(v, LogDecimals(v)), 11.0);
    if (width > widest) {
      widest = width;
      axis.anchor = i;
    }
  }
  if (!axis.log_ticks.empty()) {
    const double v = axis.log_ticks[axis.anchor];
    axis.shift = v - std::log10(v);
  }
  return axis;
}

// The log ticks other than the frame's anchor, drawn as PlotFrame draws its own (grid line,
// tick mark, label); called right after the frame is built so the grid lies under the data.
void DrawLogTicks(PlotFrame& frame, const Axis& axis, bool is_x) {
  SvgWriter& svg = frame.svg();
  const std::string tick_x = std::string(kTickStyle) + ";text-anchor:middle";
  const std::string tick_y = std::string(kTickStyle) + ";text-anchor:end";
  for (std::size_t i = 0; i < axis.log_ticks.size(); ++i) {
    if (i == axis.anchor) continue;
    const double v = axis.log_ticks[i];
    const std::string label = FormatTick(v, LogDecimals(v));
    if (is_x) {
      const double x = frame.X(axis.ToFrame(v));
      svg.Line(x, frame.top(), x, frame.bottom(), kGridStyle);
      svg.Line(x, frame.bottom(), x, frame.bottom() + 4.0, kAxisStyle);
      svg.Text(x, frame.bottom() + 16.0, label, tick_x);
    } else {
      const double y = frame.Y(axis.ToFrame(v));
      svg.Line(frame.left(), y, frame.right(), y, kGridStyle);
      svg.Line(frame.left() - 4.0, y, frame.left(), y, kAxisStyle);
      svg.Text(frame.left() - 7.0, y + 4.0, label, tick_y);
    }
  }
}

bool ValidRange(const AxisRange& r, bool log) {
  return std::isfinite(r.lo) && std::isfinite(r.hi) && r.lo < r.hi && (!log || r.lo > 0.0);
}

// An axis over `given`, or else over the drawable `values`: padded when linear, widened to
// 1-2-5 values when logarithmic. A given range that a log axis cannot show (lo <= 0) is ignored.
Axis DataAxis(bool log, AxisRange given, const std::vector<double>& values, int target) {
  AxisRange r = given;
  if (!ValidRange(given, log)) {
    if (values.empty()) {
      r = log ? AxisRange{1.0, 10.0} : AxisRange{0.0, 1.0};
    } else {
      const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
      if (!log) {
        r = PaddedRange(*lo, *hi, 0.05);
      } else if (*lo < *hi) {
        r = {Floor125(*lo), Ceil125(*hi)};
      } else {
        r = {Floor125(0.9 * *lo), Ceil125(1.1 * *hi)};  // one value: the 1-2-5 values around it
      }
    }
  }
  return log ? LogAxis(r) : LinearAxis(r, NiceTicks(r.lo, r.hi, target));
}

PlotSpec Spec(const ChartSize& size, const std::string& title, const std::string& x_label,
              const std::string& y_label, const Axis& x, const Axis& y) {
  PlotSpec spec;
  spec.size = size;
  spec.title = title;
  spec.x_label = x_label;
  spec.y_label = y_label;
  spec.x = x.FrameRange();
  spec.y = y.FrameRange();
  spec.x_ticks = x.FrameTicks();
  spec.y_ticks = y.FrameTicks();
  return spec;
}

void DrawLogAxes(PlotFrame& frame, const Axis& x, const Axis& y) {
  if (x.log) DrawLogTicks(frame, x, true);
  if (y.log) DrawLogTicks(frame, y, false);
}

// Whether a point can be drawn: finite, positive on a log axis, inside the (maybe given) range.
bool Shown(const Axis& x, const Axis& y, double vx, double vy) {
  return x.Drawable(vx) && y.Drawable(vy) && x.Inside(vx) && y.Inside(vy);
}

std::string LineStyle(int series, bool dashed) {
  return "fill:none;stroke:" + std::string(PaletteColour(series)) + ";stroke-width:1.8" +
         (dashed ? ";stroke-dasharray:6 4" : "");
}

// One series: a path through its drawable points, broken (a new "M") wherever a point cannot be
// drawn, so no line bridges a gap; then the markers, each with a tooltip.
void DrawSeries(PlotFrame& frame, const Axis& x, const Axis& y, const LineSeries& s, int index) {
  SvgWriter& svg = frame.svg();
  const std::size_t n = std::min(s.x.size(), s.y.size());
  const auto drawable = [&](std::size_t i) { return Shown(x, y, s.x[i], s.y[i]); };
  const auto px = [&](std::size_t i) { return frame.X(x.ToFrame(s.x[i])); };
  const auto py = [&](std::size_t i) { return frame.Y(y.ToFrame(s.y[i])); };
  svg.OpenGroup("class=\"series\"");
  svg.Title(s.name);
  PolylinePath path;
  for (std::size_t i = 0; i < n; ++i) {
    if (drawable(i)) {
      path.Point(px(i), py(i));
    } else {
      path.Break();
    }
  }
  if (!path.empty()) svg.Path(path.data(), LineStyle(index, s.dashed));
  const std::string marker =
      "fill:" + std::string(PaletteColour(index)) + ";stroke:#ffffff;stroke-width:0.7";
  for (std::size_t i = 0; s.markers && i < n; ++i) {
    if (!drawable(i)) continue;
    svg.OpenGroup("class=\"point\"");
    svg.Title(s.name + ": x = " + Short(s.x[i]) + ", y = " + Short(s.y[i]));
    DrawMarker(svg, px(i), py(i), 3.2, index, marker);
    svg.CloseGroup();
  }
  svg.CloseGroup();
}

// The vertical reference lines, each with a tooltip.
void DrawXMarkers(PlotFrame& frame, const Axis& x, const std::vector<double>& markers,
                  const std::string& label) {
  for (double m : markers) {
    if (!x.Inside(m)) continue;
    frame.svg().OpenGroup("class=\"marker\"");
    frame.svg().Title((label.empty() ? "x" : label) + ": " + Short(m));
    const double px = frame.X(x.ToFrame(m));
    frame.svg().Line(px, frame.top(), px, frame.bottom(), kMarkerLineStyle);
    frame.svg().CloseGroup();
  }
}

// A count axis: linear from zero to a whole tick above the largest count; logarithmic from the
// power of ten below the smallest positive count (so even the smallest bar has a visible height,
// a decade tall at least) to the 1-2-5 value at or above the largest.
Axis CountAxis(bool log, double lo, double hi) {
  if (!log) {
    AxisRange r{0.0, std::max(1.0, 1.05 * hi)};
    AxisTicks ticks = CoveringTicks(&r, 5, true);
    return LinearAxis(r, std::move(ticks));
  }
  // No positive count (lo is then +inf, the minimum over nothing): a default decade, not the
  // int conversion of an infinite log that UBSan rightly rejects.
  if (!(lo > 0.0 && std::isfinite(lo) && std::isfinite(hi))) return LogAxis({1.0, 10.0});
  const int k = static_cast<int>(std::ceil(std::log10(lo) - kTolerance)) - 1;
  return LogAxis({Decade(k, 1.0), Ceil125(hi)});
}

// Bin edges are usable if there are at least two, all finite and strictly ascending.
bool ValidEdges(const std::vector<double>& edges) {
  if (edges.size() < 2) return false;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!std::isfinite(edges[i]) || (i > 0 && !(edges[i] > edges[i - 1]))) return false;
  }
  return true;
}

// A bar is drawn for a finite positive count (zero has no height, negative counts are
// meaningless); the count of series s in bin i, or 0 if the series is short.
double BarCount(const BinnedSeries& s, std::size_t bin) {
  const double c = bin < s.counts.size() ? s.counts[bin] : 0.0;
  return std::isfinite(c) && c > 0.0 ? c : 0.0;
}

}  // namespace

std::vector<double> LogTicks(double lo, double hi, int max_ticks) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo > 0.0) || hi < lo) return {};
  std::vector<double> all;
  std::vector<int> powers;  // exponents of the powers of ten among them
  for (int k = DecadeOf(lo); k <= DecadeOf(hi); ++k) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = Decade(k, m);
      if (v < lo * (1.0 - kTolerance) || v > hi * (1.0 + kTolerance)) continue;
      all.push_back(v);
      if (m == 1.0) powers.push_back(k);
    }
  }
  max_ticks = std::max(max_ticks, 1);
  if (static_cast<int>(all.size()) <= max_ticks) return all;
  // Only powers of ten; if even those are too many, every stride-th decade, keeping 10^0.
  const int count = static_cast<int>(powers.size());
  const int stride = (count + max_ticks - 1) / max_ticks;
  std::vector<double> ticks;
  for (int k : powers) {
    if (((k % stride) + stride) % stride == 0) ticks.push_back(Decade(k, 1.0));
  }
  return ticks;
}

std::string LineChartSvg(const LineChart& chart) {
  // The axes are fitted to the points a log axis can show, and to the reference lines.
  std::vector<double> xs, ys;
  for (const LineSeries& s : chart.series) {
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!Plottable(chart.log_x, s.x[i]) || !Plottable(chart.log_y, s.y[i])) continue;
      xs.push_back(s.x[i]);
      ys.push_back(s.y[i]);
    }
  }
  std::vector<double> markers;
  for (double m : chart.x_markers) {
    if (Plottable(chart.log_x, m)) markers.push_back(m);
  }
  const int x_target = std::max(4, static_cast<int>(chart.size.width_px / 80.0));
  std::vector<double> x_values = xs;
  x_values.insert(x_values.end(), markers.begin(), markers.end());
  const Axis x = DataAxis(chart.log_x, chart.x_range, x_values, x_target);
  const Axis y = DataAxis(chart.log_y, chart.y_range, ys, 5);

  bool any = false;
  for (std::size_t i = 0; i < xs.size(); ++i) any = any || Shown(x, y, xs[i], ys[i]);

  PlotSpec spec = Spec(chart.size, chart.title, chart.x_label, chart.y_label, x, y);
  for (std::size_t i = 0; any && i < chart.series.size(); ++i) {
    const LineSeries& s = chart.series[i];
    spec.legend.push_back(
        {LegendEntry::Kind::kLine, LineStyle(static_cast<int>(i), s.dashed), s.name});
  }
  if (any && !markers.empty() && !chart.x_markers_label.empty()) {
    spec.legend.push_back(
        {LegendEntry::Kind::kLine, std::string(kMarkerLineStyle), chart.x_markers_label});
  }
  PlotFrame frame(std::move(spec));
  DrawLogAxes(frame, x, y);
  if (!any) {
    frame.NoData();
    return frame.Finish();
  }
  DrawXMarkers(frame, x, markers, chart.x_markers_label);
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    DrawSeries(frame, x, y, chart.series[i], static_cast<int>(i));
  }
  return frame.Finish();
}

std::string BinnedChartSvg(const BinnedChart& chart) {
  const std::vector<double>& edges = chart.bin_edges;
  const std::size_t bins = ValidEdges(edges) ? edges.size() - 1 : 0;
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const BinnedSeries& s : chart.series) {
    for (std::size_t i = 0; i < bins; ++i) {
      if (BarCount(s, i) == 0.0) continue;
      lo = std::min(lo, BarCount(s, i));
      hi = std::max(hi, BarCount(s, i));
    }
  }
  const bool any = hi > 0.0;
  const AxisRange xr = bins > 0 ? AxisRange{edges.front(), edges.back()} : AxisRange{0.0, 1.0};
  const int x_target = std::max(4, static_cast<int>(chart.size.width_px / 64.0));
  const Axis x = LinearAxis(xr, NiceTicks(xr.lo, xr.hi, x_target));
  const Axis y = CountAxis(chart.log_y, lo, hi);

  PlotSpec spec = Spec(chart.size, chart.title, chart.x_label, chart.y_label, x, y);
  for (std::size_t s = 0; any && s < chart.series.size(); ++s) {
    spec.legend.push_back({LegendEntry::Kind::kSwatch,
                           "fill:" + std::string(PaletteColour(static_cast<int>(s))),
                           chart.series[s].name});
  }
  PlotFrame frame(std::move(spec));
  DrawLogAxes(frame, x, y);
  if (!any) {
    frame.NoData();
    return frame.Finish();
  }
  // Each bin's bars share its middle 80 %, leaving a gap between neighbouring bins.
  SvgWriter& svg = frame.svg();
  const double base = frame.Y(y.ToFrame(y.range.lo));
  const double slots = static_cast<double>(chart.series.size());
  for (std::size_t i = 0; i < bins; ++i) {
    const double a = frame.X(edges[i]), b = frame.X(edges[i + 1]);
    const double width = 0.8 * (b - a) / slots;
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      const double c = BarCount(chart.series[s], i);
      if (c == 0.0) continue;
      const double top = frame.Y(y.ToFrame(c));
      svg.OpenGroup("class=\"bar\"");
      svg.Title(chart.series[s].name + ": [" + Short(edges[i]) + ", " + Short(edges[i + 1]) +
                "): " + Short(c));
      svg.Rect(a + 0.1 * (b - a) + s * width, top, width, base - top,
               "fill:" + std::string(PaletteColour(static_cast<int>(s))));
      svg.CloseGroup();
    }
  }
  return frame.Finish();
}

}  // namespace foresight
