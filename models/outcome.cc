#include "models/outcome.h"

namespace foresight {

std::string_view CategoryName(Category category) {
  switch (category) {
    case Category::kInfield:
      return "infield";
    case Category::kOppGoal:
      return "opp_goal";
    case Category::kOwnGoal:
      return "own_goal";
    case Category::kOut:
      return "out";
  }
  return "?";
}

std::string_view ContactName(Contact contact) {
  switch (contact) {
    case Contact::kNone:
      return "none";
    case Contact::kPost:
      return "post";
    case Contact::kNet:
      return "net";
    case Contact::kObstacle:
      return "obstacle";
    case Contact::kRobot:
      return "robot";
  }
  return "?";
}

}  // namespace foresight
