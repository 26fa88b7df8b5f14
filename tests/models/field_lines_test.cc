#include "models/field_lines.h"

#include <gtest/gtest.h>

#include "tests/support/test_situations.h"

namespace foresight {
namespace {

class FieldLinesTest : public ::testing::Test {
 protected:
  FieldSpec field_ = LoadFieldSpec(testing::ModelsDir() / "fields" / "spl.json");
  FieldLines lines_ = FieldLines::Of(field_);
};

TEST_F(FieldLinesTest, OutMeansCompletelyOverTheLine) {
  // Line centre 4.5 + half a line 0.025 + one ball radius 0.05.
  EXPECT_DOUBLE_EQ(lines_.out_x_m, 4.575);
  EXPECT_DOUBLE_EQ(lines_.out_y_m, 3.075);
  EXPECT_EQ(ClassifyPosition(lines_, Vec2(4.574, 0.0)), Category::kInfield);
  EXPECT_EQ(ClassifyPosition(lines_, Vec2(4.576, 0.0)), Category::kOppGoal);
  EXPECT_EQ(ClassifyPosition(lines_, Vec2(-4.576, 0.0)), Category::kOwnGoal);
  EXPECT_EQ(ClassifyPosition(lines_, Vec2(4.576, 0.81)), Category::kOut);
  EXPECT_EQ(ClassifyPosition(lines_, Vec2(5.1, 0.0)), Category::kOut);  // behind the back net
}

TEST_F(FieldLinesTest, TheFirstLineCrossedDecides) {
  // Over the goal line between the posts, ending beside the goal: still a goal.
  EXPECT_EQ(ClassifyPath(lines_, Vec2(4.3, 0.0), Vec2(0.6, 0.8), 2.0), Category::kOppGoal);
  // Over the side line first, ending level with the goal: out.
  EXPECT_EQ(ClassifyPath(lines_, Vec2(4.0, 2.9), Vec2(0.6, 0.8), 1.0), Category::kOut);
  // Not reaching any line.
  EXPECT_EQ(ClassifyPath(lines_, Vec2(0.0, 0.0), Vec2(1.0, 0.0), 4.5), Category::kInfield);
  // Starting out: stays out whatever the path.
  EXPECT_EQ(ClassifyPath(lines_, Vec2(0.0, 3.2), Vec2(0.0, -1.0), 2.0), Category::kOut);
}

}  // namespace
}  // namespace foresight
