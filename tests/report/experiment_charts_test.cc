// Charts of the experiments: logarithmic ticks, line charts on log axes (Fig. 4), grouped bars
// over shared bins with a linear or logarithmic count axis (Fig. 5).
#include "report/experiment_charts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "tests/support/svg_inspect.h"

namespace foresight {
namespace {

using testing::Attr;
using testing::Count;
using testing::TagsInGroups;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Attribute `name` of the <text> element whose content is exactly `label`.
double LabelAttr(const std::string& svg, const std::string& label, const std::string& name) {
  const std::size_t at = svg.find(">" + label + "</text>");
  EXPECT_NE(at, std::string::npos) << label;
  return at == std::string::npos ? kNaN : Attr(svg, svg.rfind("<text", at), name);
}

// The path data of the first <path> after `pos`.
std::string PathData(const std::string& svg, std::size_t pos) {
  const std::size_t d = svg.find(" d=\"", svg.find("<path", pos)) + 4;
  return svg.substr(d, svg.find('"', d) - d);
}

// No non-finite number printed, nothing external, every element closed in order.
void ExpectCleanSvg(const std::string& svg) {
  std::string lower = svg;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  EXPECT_EQ(lower.find("nan"), std::string::npos);
  EXPECT_EQ(lower.find("inf"), std::string::npos);
  EXPECT_EQ(svg.find("href"), std::string::npos);
  std::vector<std::string> open;
  for (auto pos = svg.find('<'); pos != std::string::npos; pos = svg.find('<', pos + 1)) {
    const std::size_t end = svg.find('>', pos);
    ASSERT_NE(end, std::string::npos);
    if (svg[pos + 1] == '?' || svg[end - 1] == '/') continue;
    if (svg[pos + 1] == '/') {
      ASSERT_FALSE(open.empty());
      EXPECT_EQ(svg.substr(pos + 2, end - pos - 2), open.back());
      open.pop_back();
    } else {
      open.push_back(svg.substr(pos + 1, svg.find_first_of(" >", pos) - pos - 1));
    }
  }
  EXPECT_TRUE(open.empty());
}

// --- log ticks ------------------------------------------------------------------------------

TEST(ExperimentLogTicksTest, OneTwoFiveValuesInsideTheRange) {
  EXPECT_EQ(LogTicks(1.0, 110.0), (std::vector<double>{1, 2, 5, 10, 20, 50, 100}));
  const std::vector<double> t = LogTicks(0.001, 1.0);
  ASSERT_EQ(t.size(), 10u);
  EXPECT_DOUBLE_EQ(t.front(), 0.001);
  EXPECT_DOUBLE_EQ(t[1], 0.002);
  EXPECT_DOUBLE_EQ(t[5], 0.05);
  EXPECT_DOUBLE_EQ(t.back(), 1.0);
  EXPECT_EQ(std::adjacent_find(t.begin(), t.end(), std::greater_equal<double>()), t.end());
  EXPECT_EQ(LogTicks(2.0, 2.0), (std::vector<double>{2}));
  EXPECT_EQ(LogTicks(3.0, 4.5), std::vector<double>{});  // no 1-2-5 value inside
  EXPECT_EQ(LogTicks(1.5, 20.0), (std::vector<double>{2, 5, 10, 20}));
}

TEST(ExperimentLogTicksTest, OnlyPowersOfTenWhenThereAreTooMany) {
  EXPECT_EQ(LogTicks(1.0, 1e6), (std::vector<double>{1, 10, 100, 1e3, 1e4, 1e5, 1e6}));
  EXPECT_EQ(LogTicks(1.0, 1e6, 19).size(), 19u);
  const std::vector<double> wide = LogTicks(1e-30, 1e30);  // even the powers are too many
  EXPECT_LE(wide.size(), 12u);
  EXPECT_GE(wide.size(), 6u);
  EXPECT_NE(std::find(wide.begin(), wide.end(), 1.0), wide.end());
  EXPECT_EQ(std::adjacent_find(wide.begin(), wide.end(), std::greater_equal<double>()), wide.end());
}

TEST(ExperimentLogTicksTest, RangesALogAxisCannotShowGiveNoTicks) {
  EXPECT_TRUE(LogTicks(0.0, 10.0).empty());
  EXPECT_TRUE(LogTicks(-1.0, 10.0).empty());
  EXPECT_TRUE(LogTicks(10.0, 1.0).empty());
  EXPECT_TRUE(LogTicks(kNaN, 10.0).empty());
  EXPECT_TRUE(LogTicks(1.0, kInf).empty());
}

// --- line chart -----------------------------------------------------------------------------

LineChart LogLogChart(std::vector<double> x, std::vector<double> y) {
  LineChart chart;
  chart.title = "stability";
  chart.x_label = "samples per action";
  chart.y_label = "share of poses";
  chart.log_x = chart.log_y = true;
  chart.series = {{"stable", std::move(x), std::move(y)}};
  return chart;
}

TEST(ExperimentLineChartTest, LogAxesSpaceDecadesEquallyAtTheirTickLabels) {
  const std::string svg = LineChartSvg(LogLogChart({1, 10, 100}, {0.001, 0.01, 0.1}));
  ExpectCleanSvg(svg);
  const std::vector<std::size_t> p = TagsInGroups(svg, "point", "circle");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_GT(Attr(svg, p[1], "cx") - Attr(svg, p[0], "cx"), 50.0);
  EXPECT_NEAR(Attr(svg, p[2], "cx") - Attr(svg, p[1], "cx"),
              Attr(svg, p[1], "cx") - Attr(svg, p[0], "cx"), 0.01);
  EXPECT_LT(Attr(svg, p[1], "cy"), Attr(svg, p[0], "cy") - 30.0);  // up the page
  EXPECT_NEAR(Attr(svg, p[2], "cy") - Attr(svg, p[1], "cy"),
              Attr(svg, p[1], "cy") - Attr(svg, p[0], "cy"), 0.01);
  // Labels without exponent or trailing zeros, each where its value is drawn (the frame draws
  // the widest, "0.001", the chart the others).
  EXPECT_NEAR(LabelAttr(svg, "10", "x"), Attr(svg, p[1], "cx"), 0.01);
  EXPECT_NEAR(LabelAttr(svg, "100", "x"), Attr(svg, p[2], "cx"), 0.01);
  EXPECT_NEAR(LabelAttr(svg, "0.001", "y") - 4.0, Attr(svg, p[0], "cy"), 0.01);
  EXPECT_NEAR(LabelAttr(svg, "0.01", "y") - 4.0, Attr(svg, p[1], "cy"), 0.01);
  EXPECT_NEAR(LabelAttr(svg, "0.1", "y") - 4.0, Attr(svg, p[2], "cy"), 0.01);
  EXPECT_NE(svg.find(">20</text>"), std::string::npos);
  EXPECT_NE(svg.find(">0.005</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">0.100</text>"), std::string::npos);
  EXPECT_EQ(Count(svg, ">0.001</text>"), 1);
}

TEST(ExperimentLineChartTest, UndrawablePointsAreSkippedAndBreakTheLine) {
  // y = 0 and y < 0 cannot be shown on a log axis, nor a non-finite x.
  const std::string svg = LineChartSvg(
      LogLogChart({1, 2, 3, 4, 5, 6, 7, 8}, {0.5, 0.0, 0.2, 0.1, -1.0, 0.05, 0.04, 0.03}));
  ExpectCleanSvg(svg);
  EXPECT_EQ(TagsInGroups(svg, "point", "circle").size(), 6u);
  const std::string d = PathData(svg, svg.find("<g class=\"series\">"));
  EXPECT_EQ(Count(d, "M"), 3) << d;  // {1}, {3, 4}, {6, 7, 8}
  EXPECT_EQ(Count(d, "L"), 3) << d;

  LineChart chart = LogLogChart({1, kNaN, 3, kInf}, {0.5, 0.4, 0.3, 0.2});
  const std::string nonfinite = LineChartSvg(chart);
  ExpectCleanSvg(nonfinite);
  EXPECT_EQ(TagsInGroups(nonfinite, "point", "circle").size(), 2u);
  EXPECT_EQ(Count(PathData(nonfinite, nonfinite.find("<g class=\"series\">")), "L"), 0);
}

TEST(ExperimentLineChartTest, LegendEscapesNamesAndTheReferenceLineIsDashedAtItsValue) {
  LineChart chart = LogLogChart({1, 10, 100}, {0.2, 0.5, 0.9});
  chart.series[0].name = "share < 20 % & rare";
  chart.series.push_back({"second", {1, 100}, {0.01, 0.02}, false, true});
  chart.x_markers = {30.0, kNaN};
  chart.x_markers_label = "N = 30";
  const std::string svg = LineChartSvg(chart);
  ExpectCleanSvg(svg);
  EXPECT_NE(svg.find(">share &lt; 20 % &amp; rare</text>"), std::string::npos);
  EXPECT_EQ(svg.find("share < 20"), std::string::npos);
  EXPECT_NE(svg.find(">N = 30</text>"), std::string::npos);
  const std::vector<std::size_t> marker = TagsInGroups(svg, "marker", "line");
  ASSERT_EQ(marker.size(), 1u);
  const double x = Attr(svg, marker[0], "x1");
  EXPECT_DOUBLE_EQ(Attr(svg, marker[0], "x2"), x);
  EXPECT_GT(x, LabelAttr(svg, "20", "x") + 5.0);
  EXPECT_LT(x, LabelAttr(svg, "50", "x") - 5.0);
  EXPECT_NE(svg.find("stroke-dasharray", marker[0]), std::string::npos);
  // The second series: dashed, no markers, its colour the palette's second.
  EXPECT_EQ(TagsInGroups(svg, "point", "circle").size(), 3u);
  EXPECT_EQ(Count(svg, "stroke:#D55E00;stroke-width:1.8;stroke-dasharray:6 4"), 2);  // + legend
}

TEST(ExperimentLineChartTest, EmptyOrUndrawableSaysNoData) {
  LineChart chart = LogLogChart({}, {});
  chart.series.clear();
  for (const LineChart& c : {chart, LogLogChart({1, 2}, {0.0, 0.0}), LogLogChart({}, {})}) {
    const std::string svg = LineChartSvg(c);
    ExpectCleanSvg(svg);
    EXPECT_NE(svg.find(">no data</text>"), std::string::npos);
    EXPECT_EQ(svg.find("class=\"point\""), std::string::npos);
  }
}

TEST(ExperimentLineChartTest, GivenRangesAreKeptAndPointsOutsideThemAreNotDrawn) {
  LineChart chart = LogLogChart({2, 5, 20, 50}, {0.5, 0.0001, 2.0, 0.01});
  chart.x_range = {1.0, 110.0};
  chart.y_range = {0.001, 1.0};
  const std::string svg = LineChartSvg(chart);
  ExpectCleanSvg(svg);
  EXPECT_EQ(TagsInGroups(svg, "point", "circle").size(), 2u);
  EXPECT_NE(svg.find(">1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">100</text>"), std::string::npos);
  EXPECT_NE(svg.find(">0.001</text>"), std::string::npos);
}

TEST(ExperimentLineChartTest, LinearAxesMapMonotonicallyAndOutputIsDeterministic) {
  LineChart chart;
  chart.series = {{"a", {0, 1, 2, 3}, {3, 1, 4, 1}}};
  const std::string svg = LineChartSvg(chart);
  ExpectCleanSvg(svg);
  const std::vector<std::size_t> p = TagsInGroups(svg, "point", "circle");
  ASSERT_EQ(p.size(), 4u);
  EXPECT_NEAR(Attr(svg, p[1], "cy"), Attr(svg, p[3], "cy"), 0.01);
  EXPECT_LT(Attr(svg, p[2], "cy"), Attr(svg, p[0], "cy"));
  EXPECT_GT(Attr(svg, p[3], "cx"), Attr(svg, p[2], "cx"));
  EXPECT_EQ(LineChartSvg(chart), svg);
}

// --- binned chart ---------------------------------------------------------------------------

TEST(ExperimentBinnedChartTest, GroupedBarsOnALogAxisOnePerPositiveCount) {
  BinnedChart chart;
  chart.x_label = "rotation around the ball (deg)";
  chart.y_label = "kicks";
  chart.log_y = true;
  chart.bin_edges = {0, 10, 20, 30};
  chart.series = {{"a & <b>", {1, 0, 100}}, {"fast", {10, 5, 0}}};
  const std::string svg = BinnedChartSvg(chart);
  ExpectCleanSvg(svg);
  const std::vector<std::size_t> bars = TagsInGroups(svg, "bar", "rect");
  ASSERT_EQ(bars.size(), 4u);  // bin 0: a, fast; bin 1: fast; bin 2: a
  const auto height = [&](int i) { return Attr(svg, bars[i], "height"); };
  const auto x = [&](int i) { return Attr(svg, bars[i], "x"); };
  // The axis starts a decade below the smallest count (0.1), so heights go as log10(c / 0.1).
  EXPECT_NEAR(height(1) / height(0), 2.0, 1e-3);
  EXPECT_NEAR(height(3) / height(0), 3.0, 1e-3);
  for (int i = 1; i < 4; ++i) {
    EXPECT_NEAR(Attr(svg, bars[i], "y") + height(i), Attr(svg, bars[0], "y") + height(0), 0.01);
  }
  // Side by side within a bin, each series at the same slot in every bin.
  const double width = Attr(svg, bars[0], "width");
  EXPECT_NEAR(x(1) - x(0), width, 0.01);
  EXPECT_NEAR(x(3) - x(0), 5.0 * width, 0.01);  // two bins of 2.5 bar widths (80 % filled)
  EXPECT_NEAR(x(1) - x(2), -2.5 * width, 0.01);
  EXPECT_NE(svg.find("<title>a &amp; &lt;b&gt;: [0, 10): 1</title>"), std::string::npos);
  EXPECT_NE(svg.find(">a &amp; &lt;b&gt;</text>"), std::string::npos);
  EXPECT_NE(svg.find(">0.1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">100</text>"), std::string::npos);
  EXPECT_EQ(BinnedChartSvg(chart), svg);
}

TEST(ExperimentBinnedChartTest, LinearAxisBarsStartAtZeroAndSkipNonCounts) {
  BinnedChart chart;
  chart.bin_edges = {1, 2, 3, 4, 5, 6};
  chart.series = {{"kicks", {2, 4, 0, kNaN, -3}}};  // the sixth bin has no count: none drawn
  const std::string svg = BinnedChartSvg(chart);
  ExpectCleanSvg(svg);
  const std::vector<std::size_t> bars = TagsInGroups(svg, "bar", "rect");
  ASSERT_EQ(bars.size(), 2u);
  EXPECT_NEAR(Attr(svg, bars[1], "height") / Attr(svg, bars[0], "height"), 2.0, 1e-3);
  EXPECT_NEAR(Attr(svg, bars[0], "y") + Attr(svg, bars[0], "height"),
              LabelAttr(svg, "0", "y") - 4.0, 0.01);
}

TEST(ExperimentBinnedChartTest, NoDataForEmptySeriesZeroCountsOrBadEdges) {
  BinnedChart chart;
  chart.log_y = true;
  chart.bin_edges = {0, 10, 20};
  const auto expect_no_data = [](const BinnedChart& c) {
    const std::string svg = BinnedChartSvg(c);
    ExpectCleanSvg(svg);
    EXPECT_NE(svg.find(">no data</text>"), std::string::npos);
    EXPECT_EQ(svg.find("class=\"bar\""), std::string::npos);
  };
  expect_no_data(chart);
  chart.series = {{"zero", {0, 0}}};
  expect_no_data(chart);
  chart.series = {{"one", {1, 2}}};
  chart.bin_edges = {0};
  expect_no_data(chart);
  chart.bin_edges = {0, 20, 10};
  expect_no_data(chart);
  chart.bin_edges = {0, kNaN, 10};
  expect_no_data(chart);
}

}  // namespace
}  // namespace foresight
