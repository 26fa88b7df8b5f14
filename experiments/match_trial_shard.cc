#include "experiments/match_trial_shard.h"

#include <string>
#include <vector>

namespace foresight {

namespace {

// The largest value of each stored enum (the enums are dense from 0).
constexpr int kLastEventKind = static_cast<int>(EventKind::kKickEnd);
constexpr int kLastSide = static_cast<int>(Side::kOpponents);

int EnumNumber(const ShardValue& value, int last) {
  const int n = value.Int();
  if (n < 0 || n > last) value.Fail("must be 0 .. " + std::to_string(last));
  return n;
}

nlohmann::json IntsJson(const std::vector<int>& values) {
  return nlohmann::json(values);
}

std::vector<int> ReadInts(const ShardValue& value) {
  std::vector<int> ints;
  for (std::size_t i = 0; i < value.Size(); ++i) ints.push_back(value.At(i).Int());
  return ints;
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
          {"time_s", ExactJson(c.time_s)},
          {"last_touch", {c.last_touch_side, c.last_touch_robot}},
          {"attacker_kick_sent", c.attacker_kick_sent ? 1 : 0},
          {"shots", {c.shots_on_target, c.shots_saved}}};
}

TrialCounters ReadCounters(const ShardValue& v) {
  TrialCounters c;
  c.opponent_touches = ReadInts(v["opponent_touches"]);
  c.opponent_kicks = ReadInts(v["opponent_kicks"]);
  c.attacker_backups = ReadInts(v["attacker_backups"]);
  c.attacker_kicks = ReadInts(v["attacker_kicks"]);
  c.grabs_failed = v["grabs_failed"].Int();
  c.kicks_missed = v["kicks_missed"].Int();
  c.kicks_not_settled = v["kicks_not_settled"].Int();
  c.kicks_fell = v["kicks_fell"].Int();
  c.time_s = v["time_s"].Double();
  const ShardValue last = v["last_touch"];
  if (last.Size() != 2) last.Fail("must be [side, robot]");
  c.last_touch_side = last.At(0).Int();
  c.last_touch_robot = last.At(1).Int();
  if (c.last_touch_side < -1 || c.last_touch_side > kLastSide) {
    last.At(0).Fail("must be -1 .. " + std::to_string(kLastSide));
  }
  c.attacker_kick_sent = v["attacker_kick_sent"].Int() != 0;
  const ShardValue shots = v["shots"];
  if (shots.Size() != 2) shots.Fail("must be [on target, saved]");
  c.shots_on_target = shots.At(0).Int();
  c.shots_saved = shots.At(1).Int();
  return c;
}

nlohmann::json EventJson(const MatchEvent& e) {
  return {ExactJson(e.time_s),         static_cast<int>(e.kind),    static_cast<int>(e.side),
          e.robot,                     ExactJson(e.p_F_ball.x()), ExactJson(e.p_F_ball.y()),
          e.detail};
}

MatchEvent ReadEvent(const ShardValue& v) {
  if (v.Size() != 7) v.Fail("must be [time_s, kind, side, robot, ball x, ball y, detail]");
  MatchEvent e;
  e.time_s = v.At(0).Double();
  e.kind = static_cast<EventKind>(EnumNumber(v.At(1), kLastEventKind));
  e.side = static_cast<Side>(EnumNumber(v.At(2), kLastSide));
  e.robot = v.At(3).Int();
  e.p_F_ball = {v.At(4).Double(), v.At(5).Double()};
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

TraceFrame ReadFrame(const ShardValue& v) {
  if (v.Size() != 4) v.Fail("must be [time_s, ball x, ball y, robots]");
  TraceFrame f;
  f.time_s = v.At(0).Double();
  f.p_F_ball = {v.At(1).Double(), v.At(2).Double()};
  const ShardValue robots = v.At(3);
  for (std::size_t i = 0; i < robots.Size(); ++i) {
    const ShardValue r = robots.At(i);
    if (r.Size() != 3) r.Fail("must be [x, y, theta]");
    f.robots.push_back({{r.At(0).Double(), r.At(1).Double()}, r.At(2).Double()});
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

MatchTrialResult ReadShardTrial(const ShardValue& v) {
  MatchTrialResult t;
  t.outcome = static_cast<TrialOutcome>(EnumNumber(v["outcome"], kTrialOutcomeCount - 1));
  t.counters = ReadCounters(v["counters"]);
  const ShardValue team = v["team_counters"];
  for (std::size_t i = 0; i < team.Size(); ++i) {
    const ShardValue c = team.At(i);
    if (c.Size() != 2) c.Fail("must be [name, value]");
    t.attacker_counters.push_back({c.At(0).String(), c.At(1).Double()});
  }
  const ShardValue events = v["events"];
  for (std::size_t i = 0; i < events.Size(); ++i) t.events.push_back(ReadEvent(events.At(i)));
  const ShardValue trace = v["trace"];
  for (std::size_t i = 0; i < trace.Size(); ++i) t.trace.push_back(ReadFrame(trace.At(i)));
  return t;
}

}  // namespace foresight
