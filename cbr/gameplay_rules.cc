#include "cbr/gameplay_rules.h"

#include <string>
#include <vector>

#include "common/error.h"

namespace foresight {
namespace {

bool IsBallAction(ActionType type) {
  return type == ActionType::kGetBall || type == ActionType::kReceive ||
         type == ActionType::kPass || type == ActionType::kKick || type == ActionType::kDribble;
}

std::string At(std::size_t robot, std::size_t action) {
  return "teammates[" + std::to_string(robot) + "].actions[" + std::to_string(action) + "]";
}

// "teammates[I].actions[J]KEY: problem"; KEY is "" or ".to".
[[noreturn]] void Fail(std::size_t robot, std::size_t action, const std::string& key,
                       const std::string& problem) {
  throw InputError(At(robot, action) + key + ": " + problem);
}

std::string Robot(const Case& c, std::size_t robot) {
  return "robot " + std::to_string(c.teammates[robot].id);
}

int IndexOfId(const Case& c, int id) {
  for (std::size_t i = 0; i < c.teammates.size(); ++i) {
    if (c.teammates[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

// The robot that starts with get_ball; throws if none or several do.
std::size_t Starter(const Case& c) {
  int starter = -1;
  for (std::size_t i = 0; i < c.teammates.size(); ++i) {
    const auto& actions = c.teammates[i].actions;
    if (actions.empty() || actions[0].type != ActionType::kGetBall) continue;
    if (starter >= 0) {
      Fail(i, 0, "",
           "get_ball: " + Robot(c, i) + " starts with get_ball, but " +
               Robot(c, static_cast<std::size_t>(starter)) +
               " already does (only one robot may fetch the ball)");
    }
    starter = static_cast<int>(i);
  }
  if (starter < 0) {
    throw InputError("teammates: no robot has get_ball as its first action (rule (i))");
  }
  return static_cast<std::size_t>(starter);
}

}  // namespace

void ValidateGameplay(const Case& c) {
  std::vector<std::vector<bool>> visited;
  for (const auto& tm : c.teammates) visited.emplace_back(tm.actions.size(), false);
  std::vector<std::size_t> cursor(c.teammates.size(), 0);

  // Follow the ball from the robot that gets it.
  std::size_t holder = Starter(c);
  visited[holder][0] = true;
  cursor[holder] = 1;
  bool released = false;
  while (!released) {
    const auto& actions = c.teammates[holder].actions;
    std::size_t j = cursor[holder];
    for (; j < actions.size(); ++j) {
      const CaseAction& a = actions[j];
      if (!IsBallAction(a.type)) continue;
      if (a.type == ActionType::kGetBall || a.type == ActionType::kReceive) {
        Fail(holder, j, "",
             std::string(ActionTypeName(a.type)) + ": " + Robot(c, holder) +
                 " already controls the ball here (rule (ii))");
      }
      visited[holder][j] = true;
      if (a.type == ActionType::kDribble) continue;
      break;  // a pass or a kick
    }
    if (j >= actions.size()) break;  // the gameplay ends with the ball controlled
    const CaseAction& a = actions[j];
    if (a.type == ActionType::kKick) break;
    // A pass: the receiver's next ball action must be receive from the holder.
    const int r = IndexOfId(c, a.teammate);
    if (r < 0 || static_cast<std::size_t>(r) == holder) {
      Fail(holder, j, ".to", std::to_string(a.teammate) + " is not another robot of the case");
    }
    const auto& theirs = c.teammates[static_cast<std::size_t>(r)].actions;
    std::size_t k = cursor[static_cast<std::size_t>(r)];
    while (k < theirs.size() && !IsBallAction(theirs[k].type)) ++k;
    if (k >= theirs.size() || theirs[k].type != ActionType::kReceive ||
        theirs[k].teammate != c.teammates[holder].id) {
      Fail(holder, j, ".to",
           std::to_string(a.teammate) + ": robot " + std::to_string(a.teammate) +
               " has no matching receive from " + Robot(c, holder) + " as its next ball action");
    }
    visited[static_cast<std::size_t>(r)][k] = true;
    cursor[holder] = j + 1;
    cursor[static_cast<std::size_t>(r)] = k + 1;
    holder = static_cast<std::size_t>(r);
  }

  // Any ball action the chain did not reach happens without the ball.
  for (std::size_t i = 0; i < c.teammates.size(); ++i) {
    const auto& actions = c.teammates[i].actions;
    for (std::size_t j = 0; j < actions.size(); ++j) {
      if (!IsBallAction(actions[j].type) || visited[i][j]) continue;
      if (actions[j].type == ActionType::kReceive) {
        Fail(i, j, ".from",
             std::to_string(actions[j].teammate) + ": no pass of robot " +
                 std::to_string(actions[j].teammate) + " to " + Robot(c, i) +
                 " reaches this receive (rule (ii))");
      }
      Fail(i, j, "",
           std::string(ActionTypeName(actions[j].type)) + ": " + Robot(c, i) +
               " does not control the ball here (a robot controls it from get_ball "
               "or receive until its pass or kick; rule (ii))");
    }
  }
}

}  // namespace foresight
