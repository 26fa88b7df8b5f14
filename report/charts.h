// Statistical charts as self-contained SVG documents (report/svg_writer.h): histograms with
// a fitted density, normal QQ plots, a direction rose, scatter plots with intervals.
//
// Every chart has axes with "nice" tick labels (1, 2, 5 x 10^k steps), a title and axis labels,
// and is about 480 x 320 px unless a size is given. Non-finite values are skipped, never drawn.
// An empty data set gives a chart with the axes and the words "no data".
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/quantile.h"

namespace foresight {

struct ChartSize {
  double width_px = 480.0;
  double height_px = 320.0;
};

struct HistogramChart {
  std::string title;
  std::string x_label;  // with the unit, e.g. "launch speed (m/s)"
  std::vector<double> values;
  int bins = 0;  // <= 0: Freedman-Diaconis, clamped to [5, 60]
  // A fitted probability density in the values' units; drawn as a curve scaled to counts
  // (n * bin width * pdf). Empty: no curve.
  std::function<double(double)> density;
  std::string density_label;    // legend text of the curve, e.g. "N(0.78, 0.06^2)"
  std::vector<double> markers;  // vertical dashed lines (e.g. the committed model's value)
  std::string markers_label;
  ChartSize size;
};
std::string HistogramSvg(const HistogramChart& chart);

struct QqChart {
  std::string title;
  std::string unit;             // e.g. "m/s"
  std::vector<QqPoint> points;  // theoretical vs observed, same units
  ChartSize size;
};
// Points and the identity line y = x.
std::string QqSvg(const QqChart& chart);

struct RoseChart {
  std::string title;
  std::vector<double> angles_rad;  // robot frame: 0 ahead (drawn up), +pi/2 left (drawn left)
  int sectors = 72;
  double fitted_mean_rad = 0.0;  // drawn as a ray
  double fitted_sd_rad = 0.0;    // drawn as a wedge mean +- sd
  ChartSize size{360.0, 360.0};
};
std::string RoseSvg(const RoseChart& chart);

struct ScatterPoint {
  double x = 0.0;
  double y = 0.0;
  double y_low = 0.0;  // interval on y (equal to y: none)
  double y_high = 0.0;
  std::string label;  // tooltip (<title>)
  int series = 0;     // colour index
};
struct ScatterChart {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<ScatterPoint> points;
  std::vector<std::string> series_names;  // legend, indexed by ScatterPoint::series
  bool identity_line = true;              // draw y = x over the shared range
  ChartSize size{480.0, 400.0};
};
std::string ScatterSvg(const ScatterChart& chart);

}  // namespace foresight
