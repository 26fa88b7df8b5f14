#include "report/scene_trace_shard.h"

#include <cmath>
#include <string>
#include <vector>

#include "report/scene_trace_json.h"

namespace foresight {

namespace {

double Units(const ShardValue& v, double units) {
  return static_cast<double>(v.Integer()) / units;
}

Eigen::Vector3d Vector(const ShardValue& v, std::size_t at, double units) {
  return {Units(v.At(at), units), Units(v.At(at + 1), units), Units(v.At(at + 2), units)};
}

// x, y, z, qx, qy, qz, qw from `at`: the quaternion as written, w >= 0, components in [-1, 1].
ScenePose Pose(const ShardValue& v, std::size_t at) {
  ScenePose pose;
  pose.p_F = Vector(v, at, kTraceUnitsPerM);
  const int unit = static_cast<int>(kTraceUnitsPerQuat);
  double q[4];
  for (std::size_t k = 0; k < 4; ++k) {
    q[k] = v.At(at + 3 + k).IntInRange(k == 3 ? 0 : -unit, unit) / kTraceUnitsPerQuat;
  }
  pose.q_F = Eigen::Quaterniond(q[3], q[0], q[1], q[2]);
  return pose;
}

std::vector<ScenePose> Poses(const ShardValue& v, std::size_t count) {
  if (v.Size() != 7 * count) v.Fail("must hold 7 numbers per pose, " + std::to_string(count));
  std::vector<ScenePose> poses;
  for (std::size_t k = 0; k < count; ++k) poses.push_back(Pose(v, 7 * k));
  return poses;
}

std::vector<std::string> Strings(const ShardValue& v) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < v.Size(); ++i) out.push_back(v.At(i).String());
  return out;
}

void RequireUnits(const ShardValue& units) {
  const std::pair<const char*, double> expected[] = {{"m", kTraceUnitsPerM},
                                                     {"quaternion", kTraceUnitsPerQuat},
                                                     {"rad_per_s", kTraceUnitsPerRadps},
                                                     {"N_s", kTraceUnitsPerNs},
                                                     {"s", kTraceUnitsPerS},
                                                     {"heading_rad", kTraceUnitsPerQuat}};
  for (const auto& [name, value] : expected) {
    if (units[name].Double() != value) units[name].Fail("must be " + std::to_string(value));
  }
}

}  // namespace

nlohmann::json SceneTraceShardJson(const SceneTrace& trace) {
  return nlohmann::json::parse(SceneTraceJson(trace));
}

SceneTrace ReadShardSceneTrace(const ShardValue& v) {
  if (v["format"].String() != kSceneTraceFormat) {
    v["format"].Fail(std::string("must be '") + kSceneTraceFormat + "'");
  }
  RequireUnits(v["units"]);
  SceneTrace trace;
  trace.rate_hz = v["rate_hz"].InRange(0.0, 1e6);
  trace.links = Strings(v["links"]);
  trace.phases = Strings(v["phases"]);
  const ShardValue bodies = v["bodies"];
  for (std::size_t i = 0; i < bodies.Size(); ++i) {
    const ShardValue b = bodies.At(i);
    trace.bodies.push_back({b["name"].String(), b["team"].IntInRange(0, 1),
                            b["radius_m"].InRange(0.0, 100.0), b["height_m"].InRange(0.0, 100.0)});
  }
  const ShardValue t = v["t"], phase = v["phase"], ball = v["ball"], links = v["links_pose"],
                   body_poses = v["bodies_pose"];
  const std::size_t frames = t.Size();
  for (const ShardValue* column : {&phase, &ball, &links, &body_poses}) {
    if (column->Size() != frames)
      column->Fail("must have one entry per time, " + std::to_string(frames));
  }
  const int phases = static_cast<int>(trace.phases.size());
  for (std::size_t i = 0; i < frames; ++i) {
    SceneFrame f;
    f.t_s = Units(t.At(i), kTraceUnitsPerS);
    if (f.t_s < 0.0 || (i > 0 && f.t_s < trace.frames.back().t_s))
      t.At(i).Fail("must not decrease");
    f.phase = phase.At(i).IntInRange(0, phases - 1);
    const ShardValue b = ball.At(i);
    if (b.Size() != 10) b.Fail("must be [pose (7), spin (3)]");
    f.ball = Pose(b, 0);
    f.w_F_ball = Vector(b, 7, kTraceUnitsPerRadps);
    const ShardValue l = links.At(i);
    if (l.Size() != 0) f.links = Poses(l, trace.links.size());
    const ShardValue p = body_poses.At(i);
    if (p.Size() != 3 * trace.bodies.size()) p.Fail("must hold x, y, heading per body");
    for (std::size_t k = 0; k < trace.bodies.size(); ++k) {
      f.bodies.push_back(
          Pose2{Vec2(Units(p.At(3 * k), kTraceUnitsPerM), Units(p.At(3 * k + 1), kTraceUnitsPerM)),
                Units(p.At(3 * k + 2), kTraceUnitsPerQuat)});
    }
    trace.frames.push_back(std::move(f));
  }
  const ShardValue contacts = v["contacts"];
  for (std::size_t i = 0; i < contacts.Size(); ++i) {
    const ShardValue c = contacts.At(i);
    if (c.Size() != 7) c.Fail("must be [t, a, b, x, y, z, impulse]");
    const long long impulse = c.At(6).Integer();
    if (impulse < 0) c.At(6).Fail("must be 0 or more");
    trace.contacts.push_back({Units(c.At(0), kTraceUnitsPerS), c.At(1).String(), c.At(2).String(),
                              Vector(c, 3, kTraceUnitsPerM), impulse / kTraceUnitsPerNs});
  }
  const ShardValue obstacles = v["obstacles"];
  for (std::size_t i = 0; i < obstacles.Size(); ++i) {
    trace.obstacles.push_back(Poses(obstacles.At(i), trace.links.size()));
  }
  return trace;
}

nlohmann::json ViewerTrialShardJson(const ViewerTrial& trial) {
  nlohmann::json numbers = nlohmann::json::array();
  for (const auto& [name, text] : trial.numbers) numbers.push_back({name, text});
  return {
      {"label", trial.label}, {"numbers", numbers}, {"trace", SceneTraceShardJson(trial.trace)}};
}

ViewerTrial ReadShardViewerTrial(const ShardValue& v) {
  ViewerTrial trial;
  trial.label = v["label"].String();
  const ShardValue numbers = v["numbers"];
  for (std::size_t i = 0; i < numbers.Size(); ++i) {
    const ShardValue row = numbers.At(i);
    if (row.Size() != 2) row.Fail("must be [name, text]");
    trial.numbers.emplace_back(row.At(0).String(), row.At(1).String());
  }
  trial.trace = ReadShardSceneTrace(v["trace"]);
  return trial;
}

}  // namespace foresight
