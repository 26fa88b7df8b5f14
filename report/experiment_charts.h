// Charts of the paper's experiments (Mellmann & Schlotter, sec. V): line charts with optional
// logarithmic axes (Fig. 4, decision stability against the number of samples) and histograms of
// several series over shared bins with an optional logarithmic count axis (Fig. 5, rotations
// around the ball and kicks until goal or out, one series per strategy).
//
// Same conventions as report/charts.h: self-contained SVG documents built on PlotFrame
// (report/chart_axes.h), the Okabe-Ito palette, a legend row, "no data" for empty input,
// non-finite values skipped. On a logarithmic axis values <= 0 cannot be drawn and are skipped;
// its ticks are 1, 2, 5 x 10^k (labels printed without exponent, e.g. "0.01", "20", "100").
#pragma once

#include <string>
#include <vector>

#include "report/chart_axes.h"

namespace foresight {

struct LineSeries {
  std::string name;       // legend text
  std::vector<double> x;  // same length as y
  std::vector<double> y;
  bool markers = true;  // a marker at each point (series i uses marker shape i)
  bool dashed = false;
};

struct LineChart {
  std::string title;
  std::string x_label;  // with the unit, e.g. "samples per action"
  std::string y_label;
  std::vector<LineSeries> series;  // series i is drawn in PaletteColour(i)
  bool log_x = false;
  bool log_y = false;
  // Axis ranges; lo >= hi: from the data (padded on linear axes, widened to whole
  // 1-2-5 ticks on logarithmic ones).
  AxisRange x_range{0.0, 0.0};
  AxisRange y_range{0.0, 0.0};
  std::vector<double> x_markers;  // vertical dashed reference lines (e.g. N = 30)
  std::string x_markers_label;    // their legend text; empty: no legend entry
  ChartSize size{560.0, 380.0};
};
std::string LineChartSvg(const LineChart& chart);

struct BinnedSeries {
  std::string name;            // legend text
  std::vector<double> counts;  // one per bin (bin_edges.size() - 1 of them)
};

struct BinnedChart {
  std::string title;
  std::string x_label;               // e.g. "rotation around the ball (deg)"
  std::string y_label;               // e.g. "kicks"
  std::vector<double> bin_edges;     // ascending; bin i is [edges[i], edges[i+1])
  std::vector<BinnedSeries> series;  // series i in PaletteColour(i)
  bool log_y = false;                // zero counts are not drawn on a logarithmic axis
  ChartSize size{640.0, 380.0};
};
// Within each bin, one bar per series side by side (grouped bars), each a tooltip with the
// series name, the bin and the count. Bins are drawn at their true widths on a linear x axis.
std::string BinnedChartSvg(const BinnedChart& chart);

// Ticks of a logarithmic axis over [lo, hi] (both > 0): the values 1, 2, 5 x 10^k inside it
// (only the powers of ten when that leaves more than `max_ticks`), ascending. Exposed for tests.
std::vector<double> LogTicks(double lo, double hi, int max_ticks = 12);

}  // namespace foresight
