// The world check (experiments/world_check.h) on hand-made scorecard rows: a share inside our
// interval, one outside it within the spec's points, one off; only the spec's measures decide a
// scenario; sds are not judged; only the check's team is read.
#include "experiments/world_check.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

ScorecardCell Cell(double paper, double ours, double low, double high) {
  return ScorecardCell{paper, ours, Interval{low, high}, low <= paper && paper <= high};
}

ScorecardCell Unjudged(double paper, double ours) { return ScorecardCell{paper, ours, {}, {}}; }

// Table 1's columns: goal, close, block, out, to goal (%), touches D avg, sd, time avg.
ScorecardRow Row(int scenario, const std::string& team, ScorecardCell goal, ScorecardCell block,
                 ScorecardCell out) {
  return {scenario,
          team,
          500,
          {goal, Cell(5, 5, 3, 7), block, out, Cell(30, 30, 26, 34), Cell(2.0, 5.0, 4.5, 5.5),
           Unjudged(1.3, 9.0), Cell(20.0, 20.5, 19.0, 22.0)}};
}

TEST(WorldCheckTest, ScenariosAgreeInsideOrWithinThePointsAndNameWhatIsOff) {
  const PaperTables paper = LoadPaperTables("ros2009_tables", testing::ModelsDir());
  ASSERT_EQ(paper.world_check.team, "reactive");
  ASSERT_DOUBLE_EQ(paper.world_check.within_points, 10.0);
  ScorecardTable t1{1, "", "", {}, {}, 0, 0};
  for (const PaperColumn& c : paper.Table(1)->columns) t1.columns.push_back(c.Label());
  // Scenario 1: goal inside, block 9 points from ours outside the interval, out 17 points off.
  t1.rows.push_back(Row(1, "reactive", Cell(25, 27, 23, 31), Cell(35, 44, 40, 48),
                        Cell(37, 20, 17, 23)));
  // Scenario 2: all three inside; the touches (not deciding) off.
  t1.rows.push_back(Row(2, "reactive", Cell(25, 24, 21, 28), Cell(28, 30, 26, 34),
                        Cell(41, 40, 36, 44)));
  // The CBR team's rows are not the check's.
  t1.rows.push_back(Row(1, "cbr", Cell(25, 0, 0, 1), Cell(38, 0, 0, 1), Cell(28, 99, 98, 100)));
  const WorldCheck check = BuildWorldCheck(paper, {t1}, "dg");
  ASSERT_EQ(check.scenarios.size(), 2u);
  const WorldCheckScenario& s1 = check.scenarios[0];
  EXPECT_FALSE(s1.agrees);
  ASSERT_EQ(s1.off.size(), 1u);
  EXPECT_EQ(s1.off[0], "out %");
  EXPECT_EQ(s1.cells[0].verdict, "inside");
  EXPECT_EQ(s1.cells[2].verdict, "within 10 points");
  EXPECT_EQ(s1.cells[3].verdict, "off");
  EXPECT_TRUE(s1.cells[0].decides && s1.cells[2].decides && s1.cells[3].decides);
  EXPECT_FALSE(s1.cells[1].decides);  // close is shown, not deciding
  EXPECT_EQ(s1.cells[5].verdict, "off");         // touches: outside, a mean has no points
  EXPECT_EQ(s1.cells[6].verdict, "not judged");  // the sd
  EXPECT_TRUE(check.scenarios[1].agrees);
  EXPECT_EQ(check.agreeing, 1);
  const std::string text = WorldCheckText(check);
  EXPECT_NE(text.find("1 of 2 scenarios agree"), std::string::npos);
  EXPECT_NE(text.find("s1 off: out %"), std::string::npos);
  EXPECT_EQ(WorldCheckJson(check)["scenarios"][0]["off"][0], "out %");
}

TEST(WorldCheckTest, AWorldCheckMeasureWithoutAShareColumnIsAnError) {
  const std::string shipped =
      testing::ReadText(testing::ModelsDir() / "experiments" / "ros2009_tables.json");
  std::string text = shipped;
  const std::string from = "\"dg\": [\"goal\", \"block\", \"out\"]";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "\"dg\": [\"goal\", \"saves\"]");
  const auto file = testing::WriteTempFile("tables.json", text);
  try {
    LoadPaperTables(file.string(), ".");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": world_check.measures.dg[1]"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("saves"), std::string::npos);
  }
}

}  // namespace
}  // namespace foresight
