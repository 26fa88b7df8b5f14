// Kick motions: loading, checking and sampling.
//
// Between keyframes k and k+1 (h = t_{k+1} - t_k, s = (t - t_k) / h in [0, 1]) the target is the
// cubic Hermite polynomial
//   q(s) = h00(s) p_k + h10(s) h m_k + h01(s) p_{k+1} + h11(s) h m_{k+1},
//   h00 = 2s^3 - 3s^2 + 1, h10 = s^3 - 2s^2 + s, h01 = -2s^3 + 3s^2, h11 = s^3 - s^2,
// with the Catmull-Rom tangents of a non-uniform spline, m_k = (p_{k+1} - p_{k-1}) /
// (t_{k+1} - t_{k-1}), and m = 0 at the first and the last keyframe (the motion starts and ends
// at rest). q is C1: position and velocity are continuous at every keyframe.
// (Catmull & Rom 1974; the Hermite basis as in Kochanek & Bartels 1984.)
#include "models/kick_motion.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "common/checks.h"
#include "common/error.h"
#include "common/json_reader.h"
#include "models/physics_params.h"
#include "models/robot_model.h"

namespace foresight {
namespace {

// The Catmull-Rom tangent of joint j at keyframe k; zero at both ends.
double Tangent(const std::vector<KickKeyframe>& keyframes, std::size_t k, std::size_t j) {
  if (k == 0 || k + 1 == keyframes.size()) return 0.0;
  const KickKeyframe& before = keyframes[k - 1];
  const KickKeyframe& after = keyframes[k + 1];
  return (after.positions_rad[j] - before.positions_rad[j]) / (after.time_s - before.time_s);
}

std::string KeyframeField(std::size_t k, const std::string& field) {
  return "keyframes[" + std::to_string(k) + "]." + field;
}

// The stance's height must be positive (checked here); its joints are checked against the
// robot's body when the robot loads (models/robot_spec.cc).
KickStance ReadStance(const JsonObject& object) {
  object.RejectUnknownKeys({"base_height_m", "pose_deg"});
  KickStance stance;
  stance.base_height_m = object.Number("base_height_m");
  if (!(stance.base_height_m > 0.0 && stance.base_height_m <= kMaxRobotLengthM)) {
    object.Fail("base_height_m", "must be in (0, " + FormatNumber(kMaxRobotLengthM) + "], got " +
                                     FormatNumber(stance.base_height_m));
  }
  const JsonObject pose = object.Object("pose_deg");
  for (const std::string& joint : pose.Keys()) {
    if (joint == "notes") continue;  // allowed everywhere (json_reader.h)
    if (joint.empty()) pose.Fail(joint, "joint names must not be empty");
    stance.pose_rad.emplace_back(joint, pose.Number(joint) * kDegToRad);  // files: degrees
  }
  return stance;
}

// The balance's times must be positive (checked here); its joints and the offset stances are
// checked against the robot's body when the robot loads (models/robot_spec.cc).
KickBalance ReadBalance(const JsonObject& object) {
  object.RejectUnknownKeys({"shift_s", "settle_s", "offsets_deg"});
  KickBalance balance;
  balance.shift_s = object.Number("shift_s");
  balance.settle_s = object.Number("settle_s");
  if (!(balance.shift_s > 0.0 && balance.shift_s <= 10.0)) {
    object.Fail("shift_s", "must be in (0, 10], got " + FormatNumber(balance.shift_s));
  }
  if (!(balance.settle_s >= 0.0 && balance.settle_s <= 10.0)) {
    object.Fail("settle_s", "must be in [0, 10], got " + FormatNumber(balance.settle_s));
  }
  const JsonObject offsets = object.Object("offsets_deg");
  for (const std::string& joint : offsets.Keys()) {
    if (joint == "notes") continue;
    if (joint.empty()) offsets.Fail(joint, "joint names must not be empty");
    balance.offsets_rad.emplace_back(joint, offsets.Number(joint) * kDegToRad);
  }
  if (balance.offsets_rad.empty()) object.Fail("offsets_deg", "must name at least one joint");
  return balance;
}

}  // namespace

double KickBalance::Share(double t_s) const {
  if (!Has()) return 0.0;
  const double u = std::clamp(t_s / shift_s, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}

void KickMotion::Sample(double t_s, std::span<double> q_rad, std::span<double> qdot_radps) const {
  assert(keyframes.size() >= 2 && !std::isnan(t_s));  // Validate() ensures the former
  assert(q_rad.size() == joints.size() && qdot_radps.size() == joints.size());
  const double t = std::clamp(t_s, 0.0, DurationS());
  // The segment [t_k, t_{k+1}] holding t; the last segment includes its end.
  std::size_t k = 0;
  while (k + 2 < keyframes.size() && t >= keyframes[k + 1].time_s) ++k;
  const KickKeyframe& a = keyframes[k];
  const KickKeyframe& b = keyframes[k + 1];
  const double h = b.time_s - a.time_s;
  const double s = (t - a.time_s) / h;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s;
  const double h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
  const double d00 = 6.0 * s2 - 6.0 * s, d10 = 3.0 * s2 - 4.0 * s + 1.0;
  const double d01 = -6.0 * s2 + 6.0 * s, d11 = 3.0 * s2 - 2.0 * s;
  const bool moving = t_s > 0.0 && t_s < DurationS();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const double p0 = a.positions_rad[j], p1 = b.positions_rad[j];
    const double m0 = Tangent(keyframes, k, j), m1 = Tangent(keyframes, k + 1, j);
    q_rad[j] = h00 * p0 + h10 * h * m0 + h01 * p1 + h11 * h * m1;
    qdot_radps[j] = moving ? (d00 * p0 + d01 * p1) / h + d10 * m0 + d11 * m1 : 0.0;
  }
}

void KickMotion::Validate(const std::string& file) const {
  const auto fail = [&](const std::string& field, const std::string& problem) {
    throw InputError(file + ": " + field + ": " + problem);
  };
  if (name.empty()) fail("name", "must not be empty");
  // The ball lies at the robot's foot: farther than a robot may be long is no kick.
  const std::string within = "must be within " + FormatNumber(kMaxRobotLengthM) + " m of the robot";
  if (!(std::abs(p_R_ball.x()) <= kMaxRobotLengthM))
    fail("ball_x_m", within + ", got " + FormatNumber(p_R_ball.x()));
  if (!(std::abs(p_R_ball.y()) <= kMaxRobotLengthM))
    fail("ball_y_m", within + ", got " + FormatNumber(p_R_ball.y()));
  if (joints.empty()) fail("joints", "must list at least one joint");
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const std::string field = "joints[" + std::to_string(j) + "]";
    if (joints[j].empty()) fail(field, "must be a non-empty joint name");
    for (std::size_t i = 0; i < j; ++i) {
      if (joints[i] == joints[j]) fail(field, "duplicate '" + joints[j] + "'");
    }
  }
  if (keyframes.size() < 2) {
    fail("keyframes", "must list at least 2 keyframes, got " + std::to_string(keyframes.size()));
  }
  for (std::size_t k = 0; k < keyframes.size(); ++k) {
    const KickKeyframe& key = keyframes[k];
    const std::string time_field = KeyframeField(k, "time_s");
    if (!std::isfinite(key.time_s))
      fail(time_field, "must be finite, got " + FormatNumber(key.time_s));
    if (k == 0 && key.time_s != 0.0) fail(time_field, "must be 0, got " + FormatNumber(key.time_s));
    if (key.time_s > kMaxKickTimeLimitS) {
      fail(time_field, "must be at most " + FormatNumber(kMaxKickTimeLimitS) +
                           " s (the longest kick phase a physics file's steps.max_kick_time_s "
                           "may time), got " + FormatNumber(key.time_s));
    }
    if (k > 0 && !(key.time_s > keyframes[k - 1].time_s)) {
      fail(time_field, "must be greater than the previous keyframe's " +
                           FormatNumber(keyframes[k - 1].time_s) + ", got " +
                           FormatNumber(key.time_s));
    }
    if (key.positions_rad.size() != joints.size()) {
      fail(KeyframeField(k, "positions_deg"), "must have " + std::to_string(joints.size()) +
                                                  " entries (one per joint), got " +
                                                  std::to_string(key.positions_rad.size()));
    }
    for (std::size_t j = 0; j < joints.size(); ++j) {
      if (!std::isfinite(key.positions_rad[j])) {
        fail(KeyframeField(k, "positions_deg[" + std::to_string(j) + "]"),
             "must be finite, got " + FormatNumber(key.positions_rad[j]));
      }
    }
  }
}

KickMotion LoadKickMotion(const std::filesystem::path& file) {
  const JsonDocument doc = JsonDocument::Load(file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys(
      {"name", "stance", "balance", "ball_x_m", "ball_y_m", "joints", "keyframes"});
  KickMotion motion;
  motion.name = root.String("name");
  if (root.Has("stance")) motion.stance = ReadStance(root.Object("stance"));
  if (root.Has("balance")) motion.balance = ReadBalance(root.Object("balance"));
  motion.p_R_ball = Vec2(root.Number("ball_x_m"), root.Number("ball_y_m"));
  motion.joints = root.StringArray("joints");
  if (!root.Has("keyframes")) root.Fail("keyframes", "missing");
  for (const JsonObject& item : root.ObjectArray("keyframes")) {
    item.RejectUnknownKeys({"time_s", "positions_deg"});
    KickKeyframe key;
    key.time_s = item.Number("time_s");
    for (double position_deg : item.NumberArray("positions_deg")) {
      key.positions_rad.push_back(position_deg * kDegToRad);  // files say degrees
    }
    motion.keyframes.push_back(std::move(key));
  }
  motion.Validate(file.string());
  return motion;
}

}  // namespace foresight
