#include "cbr/case_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "cbr/gameplay_rules.h"
#include "common/checks.h"
#include "common/data_file.h"
#include "common/error.h"
#include "common/json_reader.h"
#include "models/placement.h"

namespace foresight {
namespace {

void RequireScope(const std::string& field, const Scope& scope) {
  RequirePositive(field + ".tau_x_m", scope.tau_x_m);
  RequirePositive(field + ".tau_y_m", scope.tau_y_m);
}

void RequireIds(const std::string& list, const std::vector<int>& ids) {
  std::set<int> seen;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::string at = list + "[" + std::to_string(i) + "].id";
    if (ids[i] < 1 || ids[i] > 4) {
      throw InputError(at + ": must be 1..4, got " + std::to_string(ids[i]));
    }
    if (!seen.insert(ids[i]).second) {
      throw InputError(at + ": " + std::to_string(ids[i]) + " is used twice");
    }
  }
}

void RequireKick(const std::string& field, const std::string& kick, const KickModel& kicks) {
  if (kicks.Find(kick)) return;
  throw InputError(field + ": unknown kick '" + kick + "' (the " + kicks.robot + " has " +
                   kicks.Names() + ")");
}

Vec2 ReadPoint(const JsonObject& o) {
  o.RejectUnknownKeys({"x_m", "y_m"});
  return Vec2(o.Number("x_m"), o.Number("y_m"));
}

Scope ReadScope(const JsonObject& o) {
  o.RejectUnknownKeys({"tau_x_m", "tau_y_m"});
  return Scope{o.Number("tau_x_m"), o.Number("tau_y_m")};
}

CaseAction ReadAction(const JsonObject& o) {
  CaseAction a;
  const std::string type = o.String("type");
  const auto parsed = ParseActionType(type);
  if (!parsed) o.Fail("type", "unknown action '" + type + "' (one of " + ActionTypeNames() + ")");
  a.type = *parsed;
  switch (a.type) {
    case ActionType::kGetBall:
    case ActionType::kWait:
      o.RejectUnknownKeys({"type"});
      break;
    case ActionType::kKick:
      o.RejectUnknownKeys({"type", "kick", "at", "target"});
      a.kick = o.String("kick");
      if (o.Has("at") == o.Has("target"))
        o.Fail("at", "give either \"at\": \"goal\" or \"target\"");
      if (o.Has("at")) {
        if (o.String("at") != "goal")
          o.Fail("at", "must be \"goal\", got \"" + o.String("at") + "\"");
        a.at_goal = true;
      } else {
        a.target_F = ReadPoint(o.Object("target"));
      }
      break;
    case ActionType::kPass:
      o.RejectUnknownKeys({"type", "kick", "to"});
      a.kick = o.String("kick");
      a.teammate = o.Integer("to");
      break;
    case ActionType::kReceive:
      o.RejectUnknownKeys({"type", "from"});
      a.teammate = o.Integer("from");
      break;
    case ActionType::kGoTo:
    case ActionType::kDribble:
      o.RejectUnknownKeys({"type", "target"});
      a.target_F = ReadPoint(o.Object("target"));
      break;
    case ActionType::kTurn:
      o.RejectUnknownKeys({"type", "heading_deg", "face"});
      if (o.Has("heading_deg") == o.Has("face")) {
        o.Fail("heading_deg", "give either \"heading_deg\" or \"face\"");
      }
      if (o.Has("heading_deg")) {
        a.heading_rad = o.Number("heading_deg") * kDegToRad;
      } else {
        a.target_F = ReadPoint(o.Object("face"));
      }
      break;
  }
  return a;
}

void ValidateAction(const std::string& at, const CaseAction& a, const Case& c,
                    const CaseRules& rules) {
  if (a.type == ActionType::kKick || a.type == ActionType::kPass) {
    RequireKick(at + ".kick", a.kick, rules.kicks);
  }
  if (a.type == ActionType::kPass || a.type == ActionType::kReceive) {
    const bool known = std::any_of(c.teammates.begin(), c.teammates.end(),
                                   [&](const CaseTeammate& t) { return t.id == a.teammate; });
    const std::string key = a.type == ActionType::kPass ? ".to" : ".from";
    if (!known) {
      throw InputError(at + key + ": robot " + std::to_string(a.teammate) +
                       " is not a teammate of the case");
    }
  }
  if (a.target_F) RequireOnField(rules.field, at + ".target", *a.target_F);
  if (a.heading_rad) RequireFinite(at + ".heading_deg", *a.heading_rad);
}

}  // namespace

void ValidateCase(const Case& c, const CaseRules& rules) {
  try {
    if (c.teammates.empty() || c.teammates.size() > 4) {
      throw InputError("teammates: must list 1-4 robots, got " +
                       std::to_string(c.teammates.size()));
    }
    if (c.opponents.size() > 4) {
      throw InputError("opponents: must list 0-4 robots, got " +
                       std::to_string(c.opponents.size()));
    }
    RequireOnField(rules.field, "ball", c.p_F_ball);
    RequireScope("ball_scope", c.ball_scope);
    std::vector<int> ids;
    for (const auto& t : c.teammates) ids.push_back(t.id);
    RequireIds("teammates", ids);
    ids.clear();
    for (const auto& o : c.opponents) ids.push_back(o.id);
    RequireIds("opponents", ids);
    for (std::size_t i = 0; i < c.teammates.size(); ++i) {
      const std::string at = "teammates[" + std::to_string(i) + "]";
      RequireOnField(rules.field, at, c.teammates[i].p_F);
      if (c.teammates[i].actions.empty()) {
        throw InputError(at +
                         ".actions: must list at least one action (\"wait\" for a robot "
                         "that only holds its place)");
      }
      for (std::size_t j = 0; j < c.teammates[i].actions.size(); ++j) {
        ValidateAction(at + ".actions[" + std::to_string(j) + "]", c.teammates[i].actions[j], c,
                       rules);
      }
    }
    for (std::size_t i = 0; i < c.opponents.size(); ++i) {
      const std::string at = "opponents[" + std::to_string(i) + "]";
      RequireOnField(rules.field, at, c.opponents[i].p_F);
      RequireScope(at + ".scope", c.opponents[i].scope);
    }
    ValidateGameplay(c);
  } catch (const InputError& e) {
    throw InputError("case " + c.name + ": " + e.what());
  }
}

Case LoadCaseFile(const std::filesystem::path& file, const CaseRules& rules) {
  // Read once for the name, then again with the name in every message's prefix.
  const std::string text = ReadDataFile(file);
  const std::string name = JsonDocument::Parse(text, file.string()).Root().String("name");
  const JsonDocument doc = JsonDocument::Parse(text, file.string() + ": case " + name);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys(
      {"name", "notes", "defending", "ball", "ball_scope", "teammates", "opponents"});

  if (name.empty() || name.find('/') != std::string::npos) {
    root.Fail("name",
              "must be a non-empty name without '/' (copies are named NAME/mirror_y), got \"" +
                  name + "\"");
  }
  Case c;
  c.name = name;
  c.source = name;
  c.notes = root.String("notes");
  if (c.notes.empty()) root.Fail("notes", "must say what situation the case is for");
  const std::string goal = root.String("defending");
  const auto defending = ParseDefendingGoal(goal);
  if (!defending) root.Fail("defending", "must be \"cyan\" or \"yellow\", got \"" + goal + "\"");
  c.defending = *defending;
  c.p_F_ball = ReadPoint(root.Object("ball"));
  c.ball_scope = ReadScope(root.Object("ball_scope"));
  for (const JsonObject& t : root.ObjectArray("teammates")) {
    t.RejectUnknownKeys({"id", "x_m", "y_m", "actions"});
    CaseTeammate tm{t.Integer("id"), Vec2(t.Number("x_m"), t.Number("y_m")), {}};
    for (const JsonObject& a : t.ObjectArray("actions")) tm.actions.push_back(ReadAction(a));
    c.teammates.push_back(std::move(tm));
  }
  for (const JsonObject& o : root.ObjectArray("opponents")) {
    o.RejectUnknownKeys({"id", "x_m", "y_m", "scope"});
    c.opponents.push_back(
        {o.Integer("id"), Vec2(o.Number("x_m"), o.Number("y_m")), ReadScope(o.Object("scope"))});
  }
  WithFile(file.string(), [&] { ValidateCase(c, rules); });
  std::sort(c.teammates.begin(), c.teammates.end(),
            [](const CaseTeammate& a, const CaseTeammate& b) { return a.id < b.id; });
  return c;
}

}  // namespace foresight
