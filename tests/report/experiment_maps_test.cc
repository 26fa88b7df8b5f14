// Field maps of the experiments: the sequential colour scale, cell maps with a colour bar, ball
// paths with a legend.
#include "report/experiment_maps.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/chart_axes.h"
#include "tests/support/svg_inspect.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

using testing::Attr;
using testing::Count;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

FieldSpec Spl() {
  return LoadFieldSpec(testing::ModelsDir() / "fields" / "spl.json");
}

// The positions of <g class="klass"> groups, in document order.
std::vector<std::size_t> Groups(const std::string& svg, const std::string& klass) {
  std::vector<std::size_t> out;
  const std::string open = "<g class=\"" + klass + "\">";
  for (auto pos = svg.find(open); pos != std::string::npos; pos = svg.find(open, pos + 1)) {
    out.push_back(pos);
  }
  return out;
}

// The text of a group (up to its first closing tag; the groups here do not nest).
std::string GroupText(const std::string& svg, std::size_t pos) {
  return svg.substr(pos, svg.find("</g>", pos) - pos);
}

void ExpectNoNonFinite(const std::string& svg) {
  std::string lower = svg;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  EXPECT_EQ(lower.find("nan"), std::string::npos);
  EXPECT_EQ(lower.find("inf"), std::string::npos);
  EXPECT_EQ(svg.find("href"), std::string::npos);
}

// The paper's grid: 30 x 20 cells of 0.3 m covering the 9 x 6 m field.
FieldCellMap GridMap() {
  FieldCellMap map;
  map.title = "stability";
  map.value_label = "share < 1 & most frequent";
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 20; ++j) {
      map.cell_centres_F.emplace_back(-4.35 + 0.3 * i, -2.85 + 0.3 * j);
      map.values.push_back((i + j) / 48.0);
    }
  }
  return map;
}

// --- colour scale ---------------------------------------------------------------------------

TEST(ExperimentSequentialColourTest, EndsAreTheViridisAnchorsAndTIsClamped) {
  EXPECT_EQ(SequentialColour(0.0), "#440154");
  EXPECT_EQ(SequentialColour(0.5), "#21918c");
  EXPECT_EQ(SequentialColour(1.0), "#fde725");
  EXPECT_EQ(SequentialColour(-3.0), SequentialColour(0.0));
  EXPECT_EQ(SequentialColour(7.0), SequentialColour(1.0));
  EXPECT_EQ(SequentialColour(kInf), SequentialColour(1.0));
  EXPECT_EQ(SequentialColour(kNaN), SequentialColour(0.0));
}

TEST(ExperimentSequentialColourTest, LightnessRisesAlongTheScale) {
  double previous = -1.0;
  for (int i = 0; i <= 32; ++i) {
    const std::string c = SequentialColour(i / 32.0);
    ASSERT_EQ(c.size(), 7u);
    ASSERT_EQ(c[0], '#');
    for (char h : c.substr(1)) EXPECT_TRUE(std::isxdigit(static_cast<unsigned char>(h))) << c;
    const auto channel = [&](int k) { return std::stoi(c.substr(1 + 2 * k, 2), nullptr, 16); };
    const double luma = 0.2126 * channel(0) + 0.7152 * channel(1) + 0.0722 * channel(2);
    EXPECT_GT(luma, previous) << i;  // dark to light: readable in grey too
    previous = luma;
  }
}

// --- cell map -------------------------------------------------------------------------------

TEST(ExperimentFieldCellMapTest, OneCellPerFiniteValueUnderTheFieldLines) {
  FieldCellMap map = GridMap();
  map.values[7] = kNaN;
  map.values[100] = kInf;
  map.cell_centres_F[200].x() = kNaN;
  const std::string svg = FieldCellMapSvg(Spl(), map);
  ExpectNoNonFinite(svg);
  const std::vector<std::size_t> cells = Groups(svg, "cell");
  ASSERT_EQ(cells.size(), 597u);
  const std::vector<std::size_t> lines = Groups(svg, "field-lines");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_GT(lines[0], cells.back());  // drawn over the cells, so they stay visible
  // The field rectangle (9 x 6 m at 70 px/m) bounds every cell, each 0.3 m = 21 px wide.
  const std::size_t field = svg.find("<rect", lines[0]);
  const double fx = Attr(svg, field, "x"), fy = Attr(svg, field, "y");
  EXPECT_NEAR(Attr(svg, field, "width"), 630.0, 0.01);
  EXPECT_NEAR(Attr(svg, field, "height"), 420.0, 0.01);
  for (std::size_t c : cells) {
    const std::size_t rect = svg.find("<rect", c);
    EXPECT_NEAR(Attr(svg, rect, "width"), 21.0, 0.01);
    EXPECT_GE(Attr(svg, rect, "x"), fx - 0.01);
    EXPECT_LE(Attr(svg, rect, "x") + 21.0, fx + 630.01);
    EXPECT_GE(Attr(svg, rect, "y"), fy - 0.01);
    EXPECT_LE(Attr(svg, rect, "y") + 21.0, fy + 420.01);
  }
  EXPECT_EQ(Groups(svg, "colour-bar").size(), 1u);
  EXPECT_NE(svg.find(">share &lt; 1 &amp; most frequent</text>"), std::string::npos);
  EXPECT_NE(svg.find(">0.0</text>"), std::string::npos);
  EXPECT_NE(svg.find(">1.0</text>"), std::string::npos);
  EXPECT_NE(svg.find(">stability</text>"), std::string::npos);
  EXPECT_EQ(FieldCellMapSvg(Spl(), map), svg);
}

TEST(ExperimentFieldCellMapTest, CellsAreColouredOnTheClampedScale) {
  FieldCellMap map;
  map.cell_centres_F = {{0, 0}, {0.3, 0}, {0.6, 0}, {0.9, 0}, {1.2, 0}};
  map.values = {0.0, 1.0, 2.0, -1.0, 0.5};
  std::string svg = FieldCellMapSvg(Spl(), map);
  std::vector<std::size_t> cells = Groups(svg, "cell");
  ASSERT_EQ(cells.size(), 5u);
  const std::vector<std::string> expected = {"#440154", "#fde725", "#fde725", "#440154", "#21918c"};
  for (std::size_t i = 0; i < cells.size(); ++i) {
    EXPECT_NE(GroupText(svg, cells[i]).find("fill:" + expected[i]), std::string::npos) << i;
  }
  map.value_hi = 2.0;  // now 1.0 is the middle
  svg = FieldCellMapSvg(Spl(), map);
  cells = Groups(svg, "cell");
  ASSERT_EQ(cells.size(), 5u);
  EXPECT_NE(GroupText(svg, cells[1]).find("fill:#21918c"), std::string::npos);
  EXPECT_NE(GroupText(svg, cells[2]).find("fill:#fde725"), std::string::npos);
}

TEST(ExperimentFieldCellMapTest, LengthMismatchThrowsAndNoValuesSaysNoData) {
  FieldCellMap map = GridMap();
  map.values.pop_back();
  EXPECT_THROW(FieldCellMapSvg(Spl(), map), std::invalid_argument);
  map.values.assign(map.cell_centres_F.size(), kNaN);
  const std::string svg = FieldCellMapSvg(Spl(), map);
  ExpectNoNonFinite(svg);
  EXPECT_TRUE(Groups(svg, "cell").empty());
  EXPECT_NE(svg.find(">no data</text>"), std::string::npos);
}

// --- ball paths -----------------------------------------------------------------------------

BallPathsMap TwoPaths() {
  BallPathsMap map;
  map.title = "from (-3, 1.5)";
  map.robot_start = Pose2{Vec2(-3.2, 1.6), -0.5};
  map.paths = {{"optimal_all: 3 kicks, goal", {{-3, 1.5}, {-0.5, 0.8}, {2.0, 0.3}, {4.6, 0.1}}},
               {"fast: <out> & gone", {{-3, 1.5}, {kNaN, 0.0}, {0.5, 2.5}, {3.5, 3.3}}}};
  return map;
}

TEST(ExperimentBallPathsTest, OnePathPerBallPathWithACircleAtEachPosition) {
  const BallPathsMap map = TwoPaths();
  const std::string svg = BallPathsSvg(Spl(), map);
  ExpectNoNonFinite(svg);
  const std::vector<std::size_t> paths = Groups(svg, "ball-path");
  ASSERT_EQ(paths.size(), 2u);
  const std::vector<int> positions = {4, 3};  // the second has a non-finite position
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string group = GroupText(svg, paths[i]);
    const std::string colour(PaletteColour(static_cast<int>(i)));
    EXPECT_EQ(Count(group, "<circle"), positions[i]) << i;
    const std::size_t first = group.find("<circle");
    EXPECT_NE(
        group.substr(first, group.find('>', first) - first).find("fill:none;stroke:" + colour),
        std::string::npos);  // the start is hollow
    EXPECT_EQ(Count(group, "fill:" + colour), positions[i] - 1);
    EXPECT_NE(group.find("stroke:" + colour + ";stroke-width:"), std::string::npos);
  }
  // The non-finite position breaks the second line: two pieces.
  const std::string second = GroupText(svg, paths[1]);
  const std::size_t line = second.find("stroke:" + std::string(PaletteColour(1)) + ";stroke-w");
  const std::size_t d = second.rfind(" d=\"", line);
  EXPECT_EQ(Count(second.substr(d, line - d), "M"), 2);
  // The robot, the legend (escaped) and the title.
  EXPECT_EQ(Count(svg, "fill:#9e9e9e"), 1);
  EXPECT_NE(svg.find(">optimal_all: 3 kicks, goal</text>"), std::string::npos);
  EXPECT_NE(svg.find(">fast: &lt;out&gt; &amp; gone</text>"), std::string::npos);
  EXPECT_NE(svg.find(">from (-3, 1.5)</text>"), std::string::npos);
  EXPECT_EQ(BallPathsSvg(Spl(), map), svg);
}

TEST(ExperimentBallPathsTest, LegendFitsBesideTheCarpetAndNoPathsSaysNoData) {
  BallPathsMap map = TwoPaths();
  map.paths[0].name = std::string(80, 'w');  // a long name widens the legend
  const std::string svg = BallPathsSvg(Spl(), map);
  const double width = Attr(svg, svg.find("<svg"), "width");
  const std::size_t text = svg.rfind("<text", svg.find(">" + map.paths[0].name + "</text>"));
  EXPECT_LE(Attr(svg, text, "x") + TextWidthPx(map.paths[0].name, 12.0), width);
  map.paths.clear();
  const std::string empty = BallPathsSvg(Spl(), map);
  ExpectNoNonFinite(empty);
  EXPECT_TRUE(Groups(empty, "ball-path").empty());
  EXPECT_NE(empty.find(">no data</text>"), std::string::npos);
}

}  // namespace
}  // namespace foresight
