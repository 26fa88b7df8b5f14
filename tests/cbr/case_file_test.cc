// Case files: the shipped format loads; every rule of cbr/case_file.h fails with a message naming
// the file, the case, the field and the value.
#include "cbr/case_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;

CaseRules Rules() {
  const auto dir = testing::ModelsDir();
  return {LoadFieldSpec(dir / "fields/four_legged.json"),
          LoadKickModel(dir / "kicks/aibo_ers7.json")};
}

constexpr char kOpponents[] =
    R"([{"id": 1, "x_m": 1.8, "y_m": 0.2, "scope": {"tau_x_m": 0.35, "tau_y_m": 0.3}}])";

std::string CaseJson(const std::string& robot1_actions, const std::string& robot2_actions,
                     const std::string& extra = "", const std::string& ball_x = "1.3") {
  return R"({"name": "c", "notes": "a test case", "defending": "cyan",
    "ball": {"x_m": )" +
         ball_x + R"(, "y_m": 0.2},
    "ball_scope": {"tau_x_m": 0.45, "tau_y_m": 0.25},
    "teammates": [
      {"id": 1, "x_m": 1.0, "y_m": 0.2, "actions": [)" +
         robot1_actions + R"(]},
      {"id": 2, "x_m": 1.4, "y_m": 1.0, "actions": [)" +
         robot2_actions + R"(]}],
    "opponents": )" +
         kOpponents + extra + "}";
}

const std::string kGood1 =
    R"({"type": "get_ball"}, {"type": "pass", "kick": "head_kick_left", "to": 2})";
const std::string kGood2 =
    R"({"type": "receive", "from": 1}, {"type": "kick", "kick": "forward", "at": "goal"})";

Case Load(const std::string& text) {
  return LoadCaseFile(testing::WriteTempFile("case.json", text), Rules());
}

std::string LoadError(const std::string& text) {
  try {
    Load(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CaseFileTest, LoadsAPassCase) {
  const Case c = Load(CaseJson(kGood1, kGood2));
  EXPECT_EQ(c.name, "c");
  EXPECT_EQ(c.source, "c");
  EXPECT_EQ(c.transform, CaseTransform::kOriginal);
  ASSERT_EQ(c.teammates.size(), 2u);
  EXPECT_EQ(c.teammates[0].actions[1].type, ActionType::kPass);
  EXPECT_EQ(c.teammates[0].actions[1].teammate, 2);
  EXPECT_EQ(c.teammates[0].actions[1].kick, "head_kick_left");
  EXPECT_TRUE(c.teammates[1].actions[1].at_goal);
  ASSERT_EQ(c.opponents.size(), 1u);
  EXPECT_DOUBLE_EQ(c.opponents[0].scope.tau_x_m, 0.35);
}

TEST(CaseFileTest, ReadsEveryActionKind) {
  const Case c = Load(CaseJson(
      R"({"type": "get_ball"}, {"type": "turn", "heading_deg": 90}, {"type": "dribble", "target": {"x_m": 1.5, "y_m": 0.5}},
         {"type": "kick", "kick": "forward", "target": {"x_m": 2.7, "y_m": -0.3}})",
      R"({"type": "wait"}, {"type": "go_to", "target": {"x_m": 2.0, "y_m": 0.0}}, {"type": "turn", "face": {"x_m": 2.7, "y_m": 0.0}})"));
  EXPECT_NEAR(*c.teammates[0].actions[1].heading_rad, kPi / 2, 1e-12);
  EXPECT_EQ(c.teammates[0].actions[3].target_F->y(), -0.3);
  EXPECT_EQ(c.teammates[1].actions[2].target_F->x(), 2.7);
}

// A give-and-go: 1 passes to 2, 2 passes back, 1 kicks; the ball changes hands twice.
TEST(CaseFileTest, AcceptsAReturnPass) {
  const Case c = Load(CaseJson(
      R"({"type": "get_ball"}, {"type": "pass", "kick": "forward", "to": 2},
         {"type": "go_to", "target": {"x_m": 2.0, "y_m": 0.2}}, {"type": "receive", "from": 2},
         {"type": "kick", "kick": "forward", "at": "goal"})",
      R"({"type": "receive", "from": 1}, {"type": "pass", "kick": "head_kick_right", "to": 1})"));
  EXPECT_EQ(c.teammates[0].actions.size(), 5u);
}

TEST(CaseFileTest, RejectsActionsAfterTheBallIsKickedAndIdleRobots) {
  EXPECT_THAT(
      LoadError(CaseJson(R"({"type": "get_ball"}, {"type": "kick", "kick": "forward", "at": "goal"},
                                    {"type": "dribble", "target": {"x_m": 2.0, "y_m": 0.0}})",
                         R"({"type": "wait"})")),
      HasSubstr("case c: teammates[0].actions[2]: dribble: robot 1 does not control"));
  EXPECT_THAT(LoadError(CaseJson(R"({"type": "get_ball"})", "")),
              HasSubstr("case c: teammates[1].actions: must list at least one action"));
}

TEST(CaseFileTest, ErrorsNameFileCaseFieldAndValue) {
  struct Bad {
    std::string text, field, value;
  };
  const std::string gb = R"({"type": "get_ball"})";
  const std::string kick = R"({"type": "kick", "kick": "forward", "at": "goal"})";
  const Bad bad[] = {
      {CaseJson(kGood1, kGood2, R"(, "colour": 1)"), "colour", "unknown"},
      {CaseJson(kGood1, kGood2, "", "2.9"), "ball", "(2.9, 0.2)"},
      {CaseJson(
           kGood1,
           R"({"type": "receive", "from": 1}, {"type": "kick", "kick": "bicycle", "at": "goal"})"),
       "teammates[1].actions[1].kick", "bicycle"},
      {CaseJson(R"({"type": "get_ball"}, {"type": "pass", "kick": "forward", "to": 3})", kGood2),
       "teammates[0].actions[1].to", "3"},
      {CaseJson(gb + "," + kick, gb + "," + kick), "teammates[1].actions[0]", "robot 2"},
      {CaseJson(R"({"type": "wait"})", R"({"type": "wait"})"), "teammates", "get_ball"},
      {CaseJson(gb, kick), "teammates[1].actions[0]", "kick: robot 2 does not control"},
      {CaseJson(kGood1, R"({"type": "kick", "kick": "forward", "at": "goal"})"),
       "teammates[0].actions[1].to", "no matching receive"},
      {CaseJson(gb + "," + kick, kGood2), "teammates[1].actions[0].from", "1: no pass of robot 1"},
      {CaseJson(
           kGood1,
           R"({"type": "receive", "from": 1}, {"type": "go_to", "target": {"x_m": 3.0, "y_m": 0}})"),
       "teammates[1].actions[1].target", "(3, 0)"},
  };
  for (const Bad& b : bad) {
    const std::string message = LoadError(b.text);
    EXPECT_THAT(message, HasSubstr("case.json: case c: ")) << b.text;
    EXPECT_THAT(message, HasSubstr(b.field)) << message;
    EXPECT_THAT(message, HasSubstr(b.value)) << message;
  }
}

TEST(CaseFileTest, RejectsBadIdsCountsAndScopes) {
  std::string text = CaseJson(kGood1, kGood2);
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    return LoadError(t);
  };
  EXPECT_THAT(with(R"("id": 2, "x_m": 1.4)", R"("id": 5, "x_m": 1.4)"),
              HasSubstr("case c: teammates[1].id: must be 1..4, got 5"));
  EXPECT_THAT(with(R"("id": 2, "x_m": 1.4)", R"("id": 1, "x_m": 1.4)"),
              HasSubstr("case c: teammates[1].id: 1 is used twice"));
  EXPECT_THAT(with(R"("tau_x_m": 0.45)", R"("tau_x_m": 0)"),
              HasSubstr("case c: ball_scope.tau_x_m: must be > 0, got 0"));
  EXPECT_THAT(with(R"("tau_x_m": 0.35)", R"("tau_x_m": -1)"),
              HasSubstr("case c: opponents[0].scope.tau_x_m: must be > 0, got -1"));
  const std::string opp =
      R"({"id": 1, "x_m": 0, "y_m": 0, "scope": {"tau_x_m": 0.3, "tau_y_m": 0.3}})";
  EXPECT_THAT(with(kOpponents, "[" + opp + "," + opp + "," + opp + "," + opp + "," + opp + "]"),
              HasSubstr("case c: opponents: must list 0-4 robots, got 5"));
  EXPECT_THAT(with(R"("defending": "cyan")", R"("defending": "blue")"),
              HasSubstr("case c: defending: must be \"cyan\" or \"yellow\", got \"blue\""));
  EXPECT_THAT(with(R"("name": "c")", R"("name": "c/mirror_y")"),
              HasSubstr("case c/mirror_y: name: must be a non-empty name without '/'"));
  EXPECT_THAT(with(R"("notes": "a test case")", R"("notes": "")"),
              HasSubstr("case c: notes: must say"));
  const std::string tm = R"({"id": 1, "x_m": 1.0, "y_m": 0.2, "actions": [)";
  EXPECT_THAT(
      with(
          tm,
          R"({"id": 3, "x_m": 0, "y_m": 0}, {"id": 4, "x_m": 0, "y_m": 0}, {"id": 5, "x_m": 0, "y_m": 0}, )" +
              tm),
      HasSubstr("teammates: must list 1-4 robots, got 5"));
}

}  // namespace
}  // namespace foresight
