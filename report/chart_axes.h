// Shared pieces of the statistical charts (report/charts.h): "nice" axis ticks and their
// labels, the palette and text styles, a legend row, and a Cartesian plot frame with a white
// background, a light grid, axes, tick labels, axis labels and a title.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "report/charts.h"
#include "report/svg_writer.h"

namespace foresight {

struct AxisRange {
  double lo = 0.0;
  double hi = 1.0;
};

struct AxisTicks {
  std::vector<double> values;  // multiples of step inside the range, ascending
  double step = 1.0;           // 1, 2 or 5 x 10^k
  int decimals = 0;            // just enough to print a multiple of step exactly
};

// The 1-2-5 step giving about `target` intervals over [lo, hi] (with `integers`, a step of at
// least 1) and its multiples inside [lo, hi]. An empty or non-finite range gives no ticks.
AxisTicks NiceTicks(double lo, double hi, int target = 5, bool integers = false);
// The multiples of `step` inside [lo, hi].
AxisTicks TicksWithStep(double lo, double hi, double step);
// Nice ticks over *range, with *range extended outwards to the outermost ticks (count axes).
AxisTicks CoveringTicks(AxisRange* range, int target, bool integers);
// Fixed-point with `decimals` digits; never "-0".
std::string FormatTick(double value, int decimals);

// [lo, hi] widened by `pad` times its span on each side. A single value (lo == hi) gets a span
// of 20% of its magnitude (1 around zero); non-finite bounds give [0, 1].
AxisRange PaddedRange(double lo, double hi, double pad);
// The range extended outwards to multiples of `step`.
AxisRange ExtendToStep(AxisRange range, double step);

// Okabe & Ito (2008) colour-blind-safe colours without the yellow; the index wraps.
std::string_view PaletteColour(int index);
// Approximate advance width of `text` in a sans-serif font of `font_px` (for layout only).
double TextWidthPx(std::string_view text, double font_px);

inline constexpr std::string_view kTitleStyle =
    "font-size:13px;font-weight:bold;fill:#111111;text-anchor:middle";
inline constexpr std::string_view kLabelStyle = "font-size:12px;fill:#222222;text-anchor:middle";
inline constexpr std::string_view kTickStyle = "font-size:11px;fill:#444444";
inline constexpr std::string_view kGridStyle = "stroke:#e6e6e6;stroke-width:1";
inline constexpr std::string_view kAxisStyle = "stroke:#555555;stroke-width:1";
inline constexpr std::string_view kBarStyle = "fill:#56B4E9;stroke:#ffffff;stroke-width:0.6";
inline constexpr std::string_view kNoDataStyle =
    "font-size:13px;fill:#777777;text-anchor:middle;font-style:italic";

// Point markers: 0 circle, 1 square, 2 diamond, 3 triangle (wraps), centred on (x, y).
void DrawMarker(SvgWriter& svg, double x, double y, double radius, int shape,
                std::string_view style);

struct LegendEntry {
  enum class Kind { kSwatch, kLine, kPoint };
  Kind kind = Kind::kLine;
  std::string style;  // the SVG style of the swatch, line or point
  std::string label;
  int shape = 0;  // kPoint
};
// Entries laid out left to right, wrapping within `max_width`; returns the height used.
double DrawLegend(SvgWriter* svg, double x, double y, double max_width,
                  const std::vector<LegendEntry>& entries);
inline double LegendHeight(const std::vector<LegendEntry>& entries, double max_width) {
  return DrawLegend(nullptr, 0.0, 0.0, max_width, entries);
}

struct PlotSpec {
  ChartSize size;
  std::string title;
  std::string x_label;
  std::string y_label;
  AxisRange x;
  AxisRange y;
  AxisTicks x_ticks;
  AxisTicks y_ticks;
  std::vector<LegendEntry> legend;  // drawn in a row between the title and the plot
};

// A Cartesian chart: the constructor draws background, title, legend and grid; data is drawn
// next in plot coordinates X(), Y(); Finish() adds axes and labels on top and ends the document.
class PlotFrame {
 public:
  explicit PlotFrame(PlotSpec spec);

  double X(double x) const;
  double Y(double y) const;
  double left() const { return left_; }
  double right() const { return right_; }
  double top() const { return top_; }
  double bottom() const { return bottom_; }
  SvgWriter& svg() { return svg_; }

  void NoData();  // "no data" in the middle of the plot
  std::string Finish();

 private:
  PlotSpec spec_;
  double left_ = 0.0, right_ = 0.0, top_ = 0.0, bottom_ = 0.0;
  SvgWriter svg_;
};

}  // namespace foresight
