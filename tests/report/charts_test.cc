// Statistical charts: nice ticks, histogram bars and density, QQ plot, direction rose, scatter.
#include "report/charts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "report/chart_axes.h"
#include "tests/support/svg_inspect.h"

namespace foresight {
namespace {

using testing::Attr;
using testing::Count;
using testing::TagsInGroups;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<double> Numbers(const std::string& text) {
  std::vector<double> out;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.') {
      std::size_t used = 0;
      out.push_back(std::stod(text.substr(i), &used));
      i += used;
    } else {
      ++i;
    }
  }
  return out;
}

// The numbers of the path data `d` of the path tag at `pos`.
std::vector<double> PathNumbers(const std::string& svg, std::size_t pos) {
  const std::size_t d = svg.find(" d=\"", pos) + 4;
  return Numbers(svg.substr(d, svg.find('"', d) - d));
}

// Every element opened is closed in order, and nothing executable or external is referenced.
void ExpectSelfContainedAndBalanced(const std::string& svg) {
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_EQ(Lower(svg).find("nan"), std::string::npos);
  EXPECT_EQ(Lower(svg).find("inf"), std::string::npos);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("href"), std::string::npos);
  std::vector<std::string> open;
  for (auto pos = svg.find('<'); pos != std::string::npos; pos = svg.find('<', pos + 1)) {
    if (svg[pos + 1] == '?') continue;
    const std::size_t end = svg.find('>', pos);
    ASSERT_NE(end, std::string::npos);
    if (svg[end - 1] == '/') continue;
    if (svg[pos + 1] == '/') {
      ASSERT_FALSE(open.empty());
      EXPECT_EQ(svg.substr(pos + 2, end - pos - 2), open.back());
      open.pop_back();
    } else {
      const std::size_t name_end = svg.find_first_of(" >", pos);
      open.push_back(svg.substr(pos + 1, name_end - pos - 1));
    }
  }
  EXPECT_TRUE(open.empty());
}

// --- ticks ----------------------------------------------------------------------------------

TEST(ChartAxesTest, NiceTicksUseOneTwoFiveSteps) {
  AxisTicks t = NiceTicks(0.0, 0.97);
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  EXPECT_EQ(t.decimals, 1);
  ASSERT_EQ(t.values.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(t.values[i], 0.2 * i, 1e-12);

  t = NiceTicks(-3.7, 12.2);
  EXPECT_DOUBLE_EQ(t.step, 2.0);
  EXPECT_EQ(t.decimals, 0);
  EXPECT_EQ(t.values.front(), -2.0);
  EXPECT_EQ(t.values.back(), 12.0);

  t = NiceTicks(0.7012, 0.7088);
  EXPECT_NEAR(t.step, 0.002, 1e-15);
  EXPECT_EQ(t.decimals, 3);
  ASSERT_EQ(t.values.size(), 4u);
  EXPECT_EQ(FormatTick(t.values[0], t.decimals), "0.702");
  EXPECT_EQ(FormatTick(t.values[3], t.decimals), "0.708");

  t = NiceTicks(0.0, 45000.0);
  EXPECT_DOUBLE_EQ(t.step, 10000.0);
  EXPECT_EQ(FormatTick(t.values.back(), t.decimals), "40000");
}

TEST(ChartAxesTest, IntegerTicksAndDegenerateRanges) {
  const AxisTicks counts = NiceTicks(0.0, 3.0, 5, true);
  EXPECT_DOUBLE_EQ(counts.step, 1.0);
  EXPECT_EQ(counts.values, (std::vector<double>{0, 1, 2, 3}));
  AxisRange range{0.0, 10.5};  // a count axis is extended to its top tick
  const AxisTicks covering = CoveringTicks(&range, 5, true);
  EXPECT_DOUBLE_EQ(range.hi, 12.0);
  EXPECT_EQ(covering.values, (std::vector<double>{0, 2, 4, 6, 8, 10, 12}));
  EXPECT_TRUE(NiceTicks(1.0, 1.0).values.empty());
  EXPECT_TRUE(NiceTicks(2.0, 1.0).values.empty());
  EXPECT_TRUE(NiceTicks(0.0, kNaN).values.empty());
  EXPECT_TRUE(NiceTicks(-kInf, 1.0).values.empty());
}

TEST(ChartAxesTest, TickLabelsAndRanges) {
  EXPECT_EQ(FormatTick(3 * 0.2, 1), "0.6");
  EXPECT_EQ(FormatTick(-0.00001, 2), "0.00");
  EXPECT_EQ(FormatTick(-0.2, 0), "0");
  EXPECT_EQ(FormatTick(-1.5, 1), "-1.5");
  EXPECT_EQ(FormatTick(12.0, 0), "12");

  AxisRange r = PaddedRange(0.0, 10.0, 0.1);
  EXPECT_DOUBLE_EQ(r.lo, -1.0);
  EXPECT_DOUBLE_EQ(r.hi, 11.0);
  r = PaddedRange(2.0, 2.0, 0.0);
  EXPECT_DOUBLE_EQ(r.lo, 1.8);
  EXPECT_DOUBLE_EQ(r.hi, 2.2);
  r = PaddedRange(0.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(r.lo, -0.5);
  EXPECT_DOUBLE_EQ(r.hi, 0.5);
  r = PaddedRange(kNaN, 1.0, 0.1);
  EXPECT_DOUBLE_EQ(r.lo, 0.0);
  EXPECT_DOUBLE_EQ(r.hi, 1.0);
  r = ExtendToStep({0.1, 0.97}, 0.2);
  EXPECT_NEAR(r.lo, 0.0, 1e-12);
  EXPECT_NEAR(r.hi, 1.0, 1e-12);
}

// --- histogram ------------------------------------------------------------------------------

TEST(ChartHistogramTest, BarHeightsAreProportionalToBinCounts) {
  HistogramChart chart;
  chart.title = "speeds";
  chart.x_label = "launch speed (m/s)";
  chart.bins = 4;  // over [0.05, 0.35]: counts 1, 2, 3, 4
  chart.values = {0.05, 0.15, 0.15, 0.25, 0.25, 0.25, 0.35, 0.35, 0.35, 0.35};
  const std::string svg = HistogramSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  const std::vector<std::size_t> bars = TagsInGroups(svg, "bar", "rect");
  ASSERT_EQ(bars.size(), 4u);
  const double h0 = Attr(svg, bars[0], "height"), bottom = Attr(svg, bars[0], "y") + h0;
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(Attr(svg, bars[i], "height") / h0, i + 1.0, 1e-2) << i;
    EXPECT_NEAR(Attr(svg, bars[i], "y") + Attr(svg, bars[i], "height"), bottom, 1e-2);
    if (i > 0) {
      EXPECT_GT(Attr(svg, bars[i], "x"), Attr(svg, bars[i - 1], "x"));
    }
  }
  EXPECT_NE(svg.find("): 4</title>"), std::string::npos);
  EXPECT_NE(svg.find("launch speed (m/s)"), std::string::npos);
  EXPECT_NE(svg.find(">count</text>"), std::string::npos);
  EXPECT_EQ(Count(svg, "<path"), 0);                     // no density, so no curve
  EXPECT_EQ(svg.find("data (n = "), std::string::npos);  // and no legend
}

TEST(ChartHistogramTest, EmptyBinsDrawNoBar) {
  HistogramChart chart;
  chart.bins = 3;
  chart.values = {0.0, 0.0, 1.0};
  const std::string svg = HistogramSvg(chart);
  const std::vector<std::size_t> bars = TagsInGroups(svg, "bar", "rect");
  ASSERT_EQ(bars.size(), 2u);
  EXPECT_NEAR(Attr(svg, bars[0], "height") / Attr(svg, bars[1], "height"), 2.0, 1e-2);
}

TEST(ChartHistogramTest, FreedmanDiaconisBinsWhenNotGiven) {
  HistogramChart chart;
  // Evenly spread: IQR = range / 2, so range / (2 IQR / cbrt(n)) = cbrt(500) = 7.94 -> 8 bins.
  for (int i = 0; i < 500; ++i) chart.values.push_back(i / 499.0);
  EXPECT_EQ(TagsInGroups(HistogramSvg(chart), "bar", "rect").size(), 8u);
  chart.values = {1, 2, 3};  // few values: still 5 bins, so bins 0, 2 and 4 are filled
  const std::string few = HistogramSvg(chart);
  const std::vector<std::size_t> bars = TagsInGroups(few, "bar", "rect");
  ASSERT_EQ(bars.size(), 3u);
  EXPECT_NEAR(Attr(few, bars[2], "x") - Attr(few, bars[0], "x"), 4.0 * Attr(few, bars[0], "width"),
              0.01);
}

TEST(ChartHistogramTest, DensityCurveIsScaledToCountsAndLabelled) {
  HistogramChart chart;
  chart.bins = 10;
  for (int i = 0; i < 100; ++i) chart.values.push_back(i * 0.01);  // 10 per bin over [0, 0.99]
  chart.density = [](double x) { return x >= 0.0 && x <= 0.99 ? 1.0 / 0.99 : 0.0; };
  chart.density_label = "U(0, 0.99)";
  const std::string svg = HistogramSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  const std::vector<std::size_t> bars = TagsInGroups(svg, "bar", "rect");
  ASSERT_EQ(bars.size(), 10u);
  const double bar_top = Attr(svg, bars[0], "y");
  const double x0 = Attr(svg, bars[0], "x");
  const double x1 = Attr(svg, bars[9], "x") + Attr(svg, bars[9], "width");
  ASSERT_EQ(Count(svg, "<path"), 1);
  const std::vector<double> d = PathNumbers(svg, svg.find("<path"));
  int inside = 0;
  for (std::size_t i = 0; i + 1 < d.size(); i += 2) {
    if (d[i] > x0 + 2.0 && d[i] < x1 - 2.0) {
      EXPECT_NEAR(d[i + 1], bar_top, 0.01);  // n * bin width * pdf = 10 = bar height
      ++inside;
    }
  }
  EXPECT_GT(inside, 50);
  EXPECT_NE(svg.find(">U(0, 0.99)</text>"), std::string::npos);
  EXPECT_NE(svg.find("data (n = 100)"), std::string::npos);
}

TEST(ChartHistogramTest, NonFiniteValuesAreSkippedNeverPrinted) {
  HistogramChart chart;
  chart.values = {0.7, kNaN, 0.8, kInf, 0.75, -kInf, 0.72};
  chart.density = [](double x) { return x < 0.75 ? kNaN : 2.0; };
  chart.markers = {0.78, kNaN};
  chart.markers_label = "model";
  const std::string svg = HistogramSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  EXPECT_NE(svg.find("data (n = 4, 3 non-finite skipped)"), std::string::npos);
  EXPECT_EQ(Count(svg, "<g class=\"marker\">"), 1);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find(">model</text>"), std::string::npos);
}

TEST(ChartHistogramTest, MarkerSitsAtItsValue) {
  HistogramChart chart;
  chart.bins = 2;
  chart.values = {0.0, 1.0};
  chart.markers = {0.5};
  const std::string svg = HistogramSvg(chart);
  const std::vector<std::size_t> bars = TagsInGroups(svg, "bar", "rect");
  ASSERT_EQ(bars.size(), 2u);
  const double mid = Attr(svg, bars[1], "x");
  const std::size_t line = TagsInGroups(svg, "marker", "line").at(0);
  EXPECT_NEAR(Attr(svg, line, "x1"), mid, 0.01);
  EXPECT_NEAR(Attr(svg, line, "x2"), mid, 0.01);
}

TEST(ChartHistogramTest, EmptyOrAllNonFiniteSaysNoData) {
  HistogramChart chart;
  chart.title = "speeds";
  for (const std::vector<double>& values : {std::vector<double>{}, std::vector<double>{kNaN}}) {
    chart.values = values;
    const std::string svg = HistogramSvg(chart);
    ExpectSelfContainedAndBalanced(svg);
    EXPECT_NE(svg.find(">no data</text>"), std::string::npos);
    EXPECT_EQ(svg.find("class=\"bar\""), std::string::npos);
  }
  chart.values = {0.5, 0.5, 0.5};  // one repeated value
  const std::string svg = HistogramSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  EXPECT_EQ(TagsInGroups(svg, "bar", "rect").size(), 1u);
}

// --- QQ -------------------------------------------------------------------------------------

TEST(ChartQqTest, PointsAndIdentityLine) {
  QqChart chart;
  chart.title = "QQ";
  chart.unit = "m/s";
  for (int i = 0; i < 20; ++i) chart.points.push_back({0.5 + 0.01 * i, 0.5 + 0.012 * i});
  chart.points.push_back({kNaN, 0.6});
  const std::string svg = QqSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  EXPECT_EQ(Count(svg, "<circle"), 21);  // 20 points and the legend's
  EXPECT_NE(svg.find("sample (n = 20)"), std::string::npos);
  EXPECT_NE(svg.find("normal quantile (m/s)"), std::string::npos);
  std::vector<std::size_t> circles;
  for (auto p = svg.find("<circle"); p != std::string::npos; p = svg.find("<circle", p + 1)) {
    circles.push_back(p);
  }
  circles.erase(circles.begin());  // the legend comes first
  for (std::size_t i = 1; i < circles.size(); ++i) {
    EXPECT_GT(Attr(svg, circles[i], "cx"), Attr(svg, circles[i - 1], "cx"));
    EXPECT_LT(Attr(svg, circles[i], "cy"), Attr(svg, circles[i - 1], "cy"));  // up the page
  }
  EXPECT_NE(QqSvg({"QQ", "m/s", {}, {}}).find(">no data</text>"), std::string::npos);
}

// --- rose -----------------------------------------------------------------------------------

struct Wedge {
  double cx, cy, x0, y0, r, x1, y1;
};
// "M cx cy L x0 y0 A r r 0 large sweep x1 y1 Z"
Wedge ParseWedge(const std::string& svg, std::size_t pos) {
  const std::vector<double> n = PathNumbers(svg, pos);
  EXPECT_EQ(n.size(), 11u);
  return {n[0], n[1], n[2], n[3], n[4], n[9], n[10]};
}

TEST(ChartRoseTest, LeftIsDrawnLeftAndAheadIsDrawnUp) {
  RoseChart chart;
  chart.sectors = 36;
  chart.angles_rad = {kPi / 2, kPi / 2, kPi / 2, 0.0, -kPi / 2 + 2 * kPi};
  chart.fitted_mean_rad = kPi / 2;
  chart.fitted_sd_rad = 0.2;
  const std::string svg = RoseSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  const std::vector<std::size_t> sectors = TagsInGroups(svg, "sector", "path");
  ASSERT_EQ(sectors.size(), 3u);
  std::vector<Wedge> w;
  for (std::size_t s : sectors) w.push_back(ParseWedge(svg, s));
  // In document order: sector 0 (ahead), 9 (left, 3 angles), 27 (right).
  EXPECT_LT(std::max(w[0].y0, w[0].y1), w[0].cy - 10.0);                  // ahead: up
  EXPECT_LT(std::max(w[1].x0, w[1].x1), w[1].cx - 10.0);                  // left: left
  EXPECT_GT(std::min(w[2].x0, w[2].x1), w[2].cx + 10.0);                  // right: right
  EXPECT_NEAR(w[1].r / w[0].r, 3.0, 1e-2);                                // radius ~ count
  EXPECT_NEAR(std::abs((w[1].y0 + w[1].y1) / 2.0 - w[1].cy), 0.0, 1e-2);  // centred on +90
  // The mean ray points left too.
  const std::size_t ray = TagsInGroups(svg, "mean", "line").at(0);
  EXPECT_NEAR(Attr(svg, ray, "x1"), w[1].cx, 1e-2);
  EXPECT_LT(Attr(svg, ray, "x2"), w[1].cx - 50.0);
  EXPECT_NEAR(Attr(svg, ray, "y2"), w[1].cy, 1e-2);
  EXPECT_EQ(Count(svg, "fill:#E69F00"), 2);  // the wedge and its legend swatch
  EXPECT_NE(svg.find("mean +90.0\u00b0"), std::string::npos);
}

TEST(ChartRoseTest, NoWedgeWithoutSpreadAndNoDataWhenEmpty) {
  RoseChart chart;
  chart.angles_rad = {0.1, kNaN, 0.2};
  chart.fitted_sd_rad = kNaN;
  std::string svg = RoseSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  EXPECT_EQ(Count(svg, "fill:#E69F00"), 0);
  EXPECT_NE(svg.find("directions (n = 2)"), std::string::npos);
  chart.angles_rad = {kNaN};
  svg = RoseSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  EXPECT_NE(svg.find(">no data</text>"), std::string::npos);
  EXPECT_EQ(svg.find("class=\"sector\""), std::string::npos);
  EXPECT_EQ(svg.find("class=\"mean\""), std::string::npos);
}

// --- scatter --------------------------------------------------------------------------------

TEST(ChartScatterTest, PointsMapMonotonicallyWithIntervalsAroundThem) {
  ScatterChart chart;
  chart.x_label = "coarse utility";
  chart.y_label = "physics utility";
  for (int i = 0; i < 10; ++i) {
    chart.points.push_back({i * 0.1, i * i * 0.01, i * i * 0.01 - 0.05, i * i * 0.01 + 0.05,
                            "option " + std::to_string(i), 0});
  }
  const std::string svg = ScatterSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  const std::vector<std::size_t> points = TagsInGroups(svg, "point", "circle");
  ASSERT_EQ(points.size(), 10u);
  for (std::size_t i = 1; i < points.size(); ++i) {
    EXPECT_GT(Attr(svg, points[i], "cx"), Attr(svg, points[i - 1], "cx"));
    EXPECT_LT(Attr(svg, points[i], "cy"), Attr(svg, points[i - 1], "cy"));
  }
  // The interval bar (the group's first line) is vertical through the point, around it.
  const std::vector<std::size_t> bars = TagsInGroups(svg, "point", "line");
  ASSERT_EQ(bars.size(), 10u);
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const double cx = Attr(svg, points[i], "cx"), cy = Attr(svg, points[i], "cy");
    EXPECT_NEAR(Attr(svg, bars[i], "x1"), cx, 1e-2);
    EXPECT_NEAR(Attr(svg, bars[i], "x2"), cx, 1e-2);
    EXPECT_GT(Attr(svg, bars[i], "y1"), cy + 2.0);  // low end below the point
    EXPECT_LT(Attr(svg, bars[i], "y2"), cy - 2.0);
  }
  EXPECT_NE(svg.find("<title>option 3: x = 0.3, y = 0.09 [0.04, 0.14]</title>"), std::string::npos);
  EXPECT_NE(svg.find(">y = x</text>"), std::string::npos);
  chart.identity_line = false;
  EXPECT_EQ(ScatterSvg(chart).find(">y = x</text>"), std::string::npos);
}

TEST(ChartScatterTest, SeriesHaveColoursShapesAndLegend) {
  ScatterChart chart;
  chart.series_names = {"kick A", "kick B"};
  chart.points = {{0.1, 0.2, 0.2, 0.2, "", 0},
                  {0.3, 0.1, 0.1, 0.1, "", 1},
                  {0.5, 0.6, kNaN, 0.7, "", 1},
                  {kNaN, 0.5, 0.5, 0.5, "", 0},
                  {0.4, kInf, 0.0, 1.0, "", 0}};
  const std::string svg = ScatterSvg(chart);
  ExpectSelfContainedAndBalanced(svg);
  EXPECT_EQ(Count(svg, "<g class=\"point\">"), 3);
  EXPECT_NE(svg.find(">kick A</text>"), std::string::npos);
  EXPECT_NE(svg.find(">kick B</text>"), std::string::npos);
  EXPECT_GE(Count(svg, "fill:#0072B2"), 2);        // point and legend
  EXPECT_GE(Count(svg, "fill:#D55E00"), 3);        // two points (squares) and legend
  EXPECT_EQ(Count(svg, "stroke-opacity:0.7"), 0);  // no interval: equal or non-finite bounds
  EXPECT_NE(ScatterSvg({}).find(">no data</text>"), std::string::npos);
}

}  // namespace
}  // namespace foresight
