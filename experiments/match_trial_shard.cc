#include "experiments/match_trial_shard.h"

#include <cmath>
#include <string>
#include <vector>

#include "common/checks.h"

namespace foresight {

namespace {

// The largest value of each stored enum (the enums are dense from 0).
constexpr int kLastEventKind = static_cast<int>(EventKind::kPenalized);
constexpr int kLastSide = static_cast<int>(Side::kOpponents);

int EnumNumber(const ShardValue& value, int last) {
  const int n = value.Int();
  if (n < 0 || n > last) value.Fail("must be 0 .. " + std::to_string(last));
  return n;
}

// The robots of `side` (0: attackers, 1: opponents) in `shape`.
int SideSize(const TrialShape& shape, int side) {
  return side == 0 ? shape.attackers : shape.opponents;
}

int RobotIndex(const ShardValue& value, int robots) {
  const int n = value.Int();
  if (n < 0 || n >= robots) {
    value.Fail("must be a robot of its side, 0 .. " + std::to_string(robots - 1) + ", got " +
               std::to_string(n));
  }
  return n;
}

double Time(const ShardValue& value, const TrialShape& shape) {
  const double t = value.Double();
  if (!(t >= 0.0 && t <= shape.max_time_s)) {
    value.Fail("must be a time from 0 to the trial's limit " + FormatNumber(shape.max_time_s) +
               " s");
  }
  return t;
}

Vec2 Point(const ShardValue& x, const ShardValue& y, const TrialShape& shape) {
  return {x.InRange(-shape.max_abs_x_m, shape.max_abs_x_m),
          y.InRange(-shape.max_abs_y_m, shape.max_abs_y_m)};
}

nlohmann::json IntsJson(const std::vector<int>& values) {
  return nlohmann::json(values);
}

// One count per robot of a side.
std::vector<int> ReadCounts(const ShardValue& value, int robots) {
  if (value.Size() != static_cast<std::size_t>(robots)) {
    value.Fail("must have one count per robot (" + std::to_string(robots) + "), got " +
               std::to_string(value.Size()));
  }
  std::vector<int> counts;
  for (std::size_t i = 0; i < value.Size(); ++i) counts.push_back(value.At(i).Count());
  return counts;
}

nlohmann::json CountersJson(const TrialCounters& c) {
  return {{"opponent_touches", IntsJson(c.opponent_touches)},
          {"opponent_kicks", IntsJson(c.opponent_kicks)},
          {"attacker_backups", IntsJson(c.attacker_backups)},
          {"attacker_kicks", IntsJson(c.attacker_kicks)},
          {"grabs_failed", c.grabs_failed},
          {"kicks_missed", c.kicks_missed},
          {"kicks_not_settled", c.kicks_not_settled},
          {"kicks_fell", c.kicks_fell},
          {"kicks_blocked", c.kicks_blocked},
          {"time_s", ExactJson(c.time_s)},
          {"last_touch", {c.last_touch_side, c.last_touch_robot}},
          {"attacker_kick_sent", c.attacker_kick_sent ? 1 : 0},
          {"shots", {c.shots_on_target, c.shots_saved}},
          {"contests_resolved", c.contests_resolved},
          {"stuck_penalties", c.stuck_penalties}};
}

TrialCounters ReadCounters(const ShardValue& v, const TrialShape& shape) {
  TrialCounters c;
  c.opponent_touches = ReadCounts(v["opponent_touches"], shape.opponents);
  c.opponent_kicks = ReadCounts(v["opponent_kicks"], shape.opponents);
  c.attacker_backups = ReadCounts(v["attacker_backups"], shape.attackers);
  c.attacker_kicks = ReadCounts(v["attacker_kicks"], shape.attackers);
  c.grabs_failed = v["grabs_failed"].Count();
  c.kicks_missed = v["kicks_missed"].Count();
  c.kicks_not_settled = v["kicks_not_settled"].Count();
  c.kicks_fell = v["kicks_fell"].Count();
  c.kicks_blocked = v["kicks_blocked"].Count();
  c.time_s = Time(v["time_s"], shape);
  const ShardValue last = v["last_touch"];
  if (last.Size() != 2) last.Fail("must be [side, robot]");
  c.last_touch_side = last.At(0).Int();
  if (c.last_touch_side < -1 || c.last_touch_side > kLastSide) {
    last.At(0).Fail("must be -1 .. " + std::to_string(kLastSide));
  }
  if (c.last_touch_side == -1) {
    c.last_touch_robot = last.At(1).Int();
    if (c.last_touch_robot != -1) last.At(1).Fail("must be -1 when no robot touched the ball");
  } else {
    c.last_touch_robot = RobotIndex(last.At(1), SideSize(shape, c.last_touch_side));
  }
  const int sent = v["attacker_kick_sent"].Int();
  if (sent != 0 && sent != 1) v["attacker_kick_sent"].Fail("must be 0 or 1");
  c.attacker_kick_sent = sent == 1;
  const ShardValue shots = v["shots"];
  if (shots.Size() != 2) shots.Fail("must be [on target, saved]");
  c.shots_on_target = shots.At(0).Count();
  c.shots_saved = shots.At(1).Count();
  if (c.shots_saved > c.shots_on_target) shots.At(1).Fail("must not exceed the shots on target");
  c.contests_resolved = v["contests_resolved"].Count();
  c.stuck_penalties = v["stuck_penalties"].Count();
  return c;
}

nlohmann::json EventJson(const MatchEvent& e) {
  return {ExactJson(e.time_s),         static_cast<int>(e.kind),    static_cast<int>(e.side),
          e.robot,                     ExactJson(e.p_F_ball.x()), ExactJson(e.p_F_ball.y()),
          e.detail};
}

MatchEvent ReadEvent(const ShardValue& v, const TrialShape& shape) {
  if (v.Size() != 7) v.Fail("must be [time_s, kind, side, robot, ball x, ball y, detail]");
  MatchEvent e;
  e.time_s = Time(v.At(0), shape);
  e.kind = static_cast<EventKind>(EnumNumber(v.At(1), kLastEventKind));
  const int side = EnumNumber(v.At(2), kLastSide);
  e.side = static_cast<Side>(side);
  e.robot = RobotIndex(v.At(3), SideSize(shape, side));
  e.p_F_ball = Point(v.At(4), v.At(5), shape);
  e.detail = v.At(6).String();
  return e;
}

nlohmann::json FrameJson(const TraceFrame& f) {
  nlohmann::json robots = nlohmann::json::array();
  for (const Pose2& r : f.robots) {
    robots.push_back({ExactJson(r.p_F.x()), ExactJson(r.p_F.y()), ExactJson(r.theta_rad)});
  }
  return {ExactJson(f.time_s), ExactJson(f.p_F_ball.x()), ExactJson(f.p_F_ball.y()), robots};
}

TraceFrame ReadFrame(const ShardValue& v, const TrialShape& shape) {
  if (v.Size() != 4) v.Fail("must be [time_s, ball x, ball y, robots]");
  TraceFrame f;
  f.time_s = Time(v.At(0), shape);
  f.p_F_ball = Point(v.At(1), v.At(2), shape);
  const ShardValue robots = v.At(3);
  const std::size_t expected = static_cast<std::size_t>(shape.attackers + shape.opponents);
  if (robots.Size() != expected) {
    robots.Fail("must list every robot of the scenario (" + std::to_string(expected) +
                "), got " + std::to_string(robots.Size()));
  }
  for (std::size_t i = 0; i < robots.Size(); ++i) {
    const ShardValue r = robots.At(i);
    if (r.Size() != 3) r.Fail("must be [x, y, theta]");
    f.robots.push_back({Point(r.At(0), r.At(1), shape), r.At(2).Finite()});
  }
  return f;
}

}  // namespace

nlohmann::json TrialShardJson(const MatchTrialResult& trial) {
  nlohmann::json team = nlohmann::json::array(), events = nlohmann::json::array(),
                 trace = nlohmann::json::array();
  for (const TeamPolicy::Counter& c : trial.attacker_counters)
    team.push_back({c.name, ExactJson(c.value)});
  for (const MatchEvent& e : trial.events) events.push_back(EventJson(e));
  for (const TraceFrame& f : trial.trace) trace.push_back(FrameJson(f));
  return {{"outcome", static_cast<int>(trial.outcome)},
          {"counters", CountersJson(trial.counters)},
          {"team_counters", team},
          {"events", events},
          {"trace", trace}};
}

MatchTrialResult ReadShardTrial(const ShardValue& v, const TrialShape& shape) {
  MatchTrialResult t;
  t.outcome = static_cast<TrialOutcome>(EnumNumber(v["outcome"], kTrialOutcomeCount - 1));
  t.counters = ReadCounters(v["counters"], shape);
  const ShardValue team = v["team_counters"];
  for (std::size_t i = 0; i < team.Size(); ++i) {
    const ShardValue c = team.At(i);
    if (c.Size() != 2) c.Fail("must be [name, value]");
    t.attacker_counters.push_back({c.At(0).String(), c.At(1).Double()});
  }
  const ShardValue events = v["events"];
  for (std::size_t i = 0; i < events.Size(); ++i) {
    t.events.push_back(ReadEvent(events.At(i), shape));
  }
  const ShardValue trace = v["trace"];
  for (std::size_t i = 0; i < trace.Size(); ++i) t.trace.push_back(ReadFrame(trace.At(i), shape));
  return t;
}

}  // namespace foresight
