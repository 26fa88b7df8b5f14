// The coordinator rule (Ros et al. 2009, sec. 4.1): the lowest present id chooses, the retriever
// closest to the ball coordinates.
#include "cbr/coordination.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace foresight {
namespace {

TEST(CoordinationTest, LowestPresentIdChooses) {
  std::vector<TeammateBelief> team = {{true, 1.0}, {true, 0.5}, {true, 0.2}};
  EXPECT_EQ(Selector(team), 0);
  team[0].present = false;  // robot 0 left (crashed, penalised)
  EXPECT_EQ(Selector(team), 1);
  team[1].present = false;
  team[2].present = false;
  EXPECT_EQ(Selector(team), -1);
}

TEST(CoordinationTest, ClosestPresentRetrieverCoordinates) {
  std::vector<TeammateBelief> team = {{true, 1.0}, {true, 0.5}, {true, 0.2}};
  EXPECT_EQ(ChooseCoordinator(team, 3), 2);
  EXPECT_EQ(ChooseCoordinator(team, 2), 1);  // robot 2 is closest but no retriever
  EXPECT_EQ(ChooseCoordinator(team, 1), 0);
  team[1].present = false;
  EXPECT_EQ(ChooseCoordinator(team, 2), 0);
  team[0].present = false;
  EXPECT_EQ(ChooseCoordinator(team, 2), -1);  // no retriever present: nobody retrieves
}

TEST(CoordinationTest, TiesGoToTheLowerIndex) {
  const std::vector<TeammateBelief> team = {{true, 0.7}, {true, 0.7}};
  EXPECT_EQ(ChooseCoordinator(team, 2), 0);
}

TEST(CoordinationTest, WaitsForAPresentRetrieverThatHasNotReported) {
  std::vector<TeammateBelief> team = {{true, 1.0}, {true, std::numeric_limits<double>::infinity()}};
  EXPECT_EQ(ChooseCoordinator(team, 2), -1);
  EXPECT_EQ(ChooseCoordinator(team, 1), 0);  // robot 1 is no retriever: no need to wait
  team[1].present = false;
  EXPECT_EQ(ChooseCoordinator(team, 2), 0);
}

}  // namespace
}  // namespace foresight
