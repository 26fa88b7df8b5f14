// The referee's classes on hand-made ball paths (Ros et al. 2009, sec. 5.1.4, 5.2.2): goal,
// close on both sides of its edge, out over the goal line and the side line, the 2D
// penalty-area entry (and not in DG), and the same for the mirrored attack.
#include "match/referee.h"

#include <gtest/gtest.h>

#include "match/match_params.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

class RefereeTest : public ::testing::Test {
 protected:
  FieldSpec field_ = LoadFieldSpec(testing::ModelsDir() / "fields" / "four_legged.json");
  SimulationParams sim_ = LoadSimulationParams("simulation", testing::ModelsDir());
  FieldLines lines_ = FieldLines::Of(field_);
  // A path from 0.3 m in front of the attacked goal line to 0.3 m behind it, crossing at y.
  Vec2 In(double y, double sign = 1.0) const { return Vec2(sign * (lines_.out_x_m - 0.3), y); }
  Vec2 Beyond(double y, double sign = 1.0) const { return Vec2(sign * (lines_.out_x_m + 0.3), y); }
};

TEST_F(RefereeTest, GoalCloseAndOutOverTheGoalLine) {
  const Referee dg(field_, sim_, false, 1.0);
  EXPECT_EQ(dg.Judge(In(0.0), Beyond(0.0)), TrialOutcome::kGoal);
  const double edge = lines_.goal_half_width_m + sim_.close_margin_m;
  EXPECT_EQ(dg.Judge(In(edge - 1e-6), Beyond(edge - 1e-6)), TrialOutcome::kClose);
  EXPECT_EQ(dg.Judge(In(-(edge - 1e-6)), Beyond(-(edge - 1e-6))), TrialOutcome::kClose);
  EXPECT_EQ(dg.Judge(In(edge + 1e-6), Beyond(edge + 1e-6)), TrialOutcome::kOut);
  EXPECT_EQ(dg.Judge(In(1.2), Beyond(1.2)), TrialOutcome::kOut);
}

TEST_F(RefereeTest, SideLineAndOwnGoalAreOut) {
  const Referee dg(field_, sim_, false, 1.0);
  EXPECT_EQ(dg.Judge(Vec2(0.0, lines_.out_y_m - 0.1), Vec2(0.1, lines_.out_y_m + 0.1)),
            TrialOutcome::kOut);
  EXPECT_EQ(dg.Judge(In(0.0, -1.0), Beyond(0.0, -1.0)), TrialOutcome::kOut);
  EXPECT_FALSE(dg.Judge(Vec2(0.0, 0.0), Vec2(0.5, 0.5)).has_value());
}

TEST_F(RefereeTest, PenaltyAreaEntryEndsOnlyIn2D) {
  const Referee dg(field_, sim_, false, 1.0);
  const Referee two_d(field_, sim_, true, 1.0);
  const double line_x = field_.HalfLength() - sim_.penalty_area_depth_m;
  const Vec2 outside(line_x - 0.01, 0.2), inside(line_x + 0.01, 0.2);
  EXPECT_EQ(two_d.Judge(outside, inside), TrialOutcome::kPenaltyArea);
  EXPECT_FALSE(dg.Judge(outside, inside).has_value());
  EXPECT_FALSE(two_d.Judge(inside, inside + Vec2(0.01, 0.0)).has_value());  // already inside
  // Beside the area (|y| beyond its half width) is no entry.
  const double y = sim_.penalty_area_half_width_m + 0.01;
  EXPECT_FALSE(two_d.Judge(Vec2(line_x - 0.01, y), Vec2(line_x + 0.01, y)).has_value());
}

TEST_F(RefereeTest, MirroredAttackJudgesTheOtherGoal) {
  const Referee mirrored(field_, sim_, true, -1.0);
  EXPECT_EQ(mirrored.Judge(In(0.0, -1.0), Beyond(0.0, -1.0)), TrialOutcome::kGoal);
  EXPECT_EQ(mirrored.Judge(In(0.0), Beyond(0.0)), TrialOutcome::kOut);
  const double line_x = -(field_.HalfLength() - sim_.penalty_area_depth_m);
  EXPECT_EQ(mirrored.Judge(Vec2(line_x + 0.01, 0.0), Vec2(line_x - 0.01, 0.0)),
            TrialOutcome::kPenaltyArea);
}

}  // namespace
}  // namespace foresight
