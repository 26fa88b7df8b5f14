#include "models/physics_params.h"

#include <span>
#include <string_view>

#include "common/checks.h"
#include "common/enum_names.h"
#include "common/error.h"
#include "common/geometry.h"
#include "common/json_reader.h"

namespace foresight {

namespace {

inline constexpr EnumNames<RobotBase, 2> kRobotBaseNames{
    {{{RobotBase::kFixed, "fixed"}, {RobotBase::kFloating, "floating"}}}};

}  // namespace

std::string_view RobotBaseName(RobotBase base) { return kRobotBaseNames.Name(base); }
std::optional<RobotBase> ParseRobotBase(std::string_view name) {
  return kRobotBaseNames.Parse(name);
}
std::string RobotBaseList() { return kRobotBaseNames.List(); }

namespace {

// The pairs as the files name them.
struct PairKey {
  std::string_view key;
  double BallPairs::*value;
};
constexpr PairKey kPairKeys[] = {{"ball_carpet", &BallPairs::carpet},
                                 {"ball_post", &BallPairs::post},
                                 {"ball_net", &BallPairs::net},
                                 {"ball_foot", &BallPairs::foot},
                                 {"ball_robot", &BallPairs::robot}};

void ValidatePairs(const std::string& field, const BallPairs& pairs, double max) {
  for (const PairKey& p : kPairKeys) {
    RequireInRange(field + "." + std::string(p.key), pairs.*p.value, 0.0, max);
  }
}

}  // namespace

void PhysicsParams::Validate() const {
  RequireInRange("carpet.rolling_deceleration_mps2", carpet.rolling_deceleration_mps2, 1e-3, 10.0);
  RequireInRange("carpet.deceleration_sigma_rel", carpet.deceleration_sigma_rel, 0.0, 0.3);
  RequireInRange("carpet.patch_size_m", carpet.patch_size_m, 0.05, 100.0);
  RequireInRange("carpet.patch_sigma_rel", carpet.patch_sigma_rel, 0.0, 0.3);
  ValidatePairs("materials.restitution", materials.restitution, 1.0);
  ValidatePairs("materials.friction", materials.friction, 5.0);
  RequireInRange("materials.net_thickness_m", materials.net_thickness_m, 0.005, 0.5);
  RequireInRange("robot.friction", robot.friction, 0.0, 10.0);
  RequireInRange("robot.restitution", robot.restitution, 0.0, 1.0);
  RequireInRange("robot.fall_tilt_rad", robot.fall_tilt_rad, kDegToRad, 0.5 * kPi);
  RequireInRange("motors.position_gain", motors.position_gain, 0.0, 1.0);
  RequireInRange("motors.velocity_gain", motors.velocity_gain, 0.0, 10.0);
  RequireInRange("steps.kick_time_step_s", steps.kick_time_step_s, 1e-5, 0.01);
  RequireInRange("steps.near_time_step_s", steps.near_time_step_s, 1e-5, 0.01);
  RequireInRange("steps.max_overlap_m", steps.max_overlap_m, 1e-4, 0.02);
  RequireInRange("steps.free_time_step_s", steps.free_time_step_s, steps.near_time_step_s, 0.05);
  RequireInRange("steps.slow_time_step_s", steps.slow_time_step_s, steps.near_time_step_s,
                 steps.free_time_step_s);
  RequireInRange("steps.slow_speed_mps", steps.slow_speed_mps, 0.0, 2.0);
  RequireInRange("steps.max_kick_time_s", steps.max_kick_time_s, 0.1, kMaxKickTimeLimitS);
  RequireInRange("steps.max_roll_time_s", steps.max_roll_time_s, 1.0, 3600.0);
  RequireInRange("steps.rest_speed_mps", steps.rest_speed_mps, 1e-5, 0.1);
  RequireInRange("steps.min_launch_roll_m", steps.min_launch_roll_m, 0.0, 0.5);
  RequireInRange("steps.solver_iterations", steps.solver_iterations, 1, 1000);
  RequireInRange("steps.restitution_threshold_mps", steps.restitution_threshold_mps, 0.0, 0.5);
  RequireInRange("watch.still_time_s", watch.still_time_s, 0.01, 10.0);
  RequireInRange("watch.still_joint_speed_radps", watch.still_joint_speed_radps, 0.0, 1.0);
  RequireInRange("watch.still_base_speed_mps", watch.still_base_speed_mps, 0.0, 0.1);
  RequireInRange("watch.still_base_rate_radps", watch.still_base_rate_radps, 0.0, 1.0);
  RequireInRange("watch.still_tilt_rad", watch.still_tilt_rad, 0.0, robot.fall_tilt_rad);
  RequireInRange("watch.still_support_margin_m", watch.still_support_margin_m, 0.0, 0.1);
}

namespace {

CarpetParams ReadCarpet(const JsonObject& o) {
  o.RejectUnknownKeys({"rolling_deceleration_mps2", "deceleration_sigma_rel", "patch_size_m",
                       "patch_sigma_rel", "patch_seed"});
  CarpetParams c;
  c.rolling_deceleration_mps2 = o.Number("rolling_deceleration_mps2");
  c.deceleration_sigma_rel = o.Number("deceleration_sigma_rel");
  c.patch_size_m = o.Number("patch_size_m");
  c.patch_sigma_rel = o.Number("patch_sigma_rel");
  const int seed = o.Integer("patch_seed");
  if (seed < 0) o.Fail("patch_seed", "must be >= 0, got " + std::to_string(seed));
  c.patch_seed = static_cast<std::uint64_t>(seed);
  return c;
}

// {"ball_carpet": e, ..., "sources": {"ball_carpet": "why", ...}}: every pair needs its value
// and the reason for it.
BallPairs ReadPairs(const JsonObject& o) {
  o.RejectUnknownKeys({"ball_carpet", "ball_post", "ball_net", "ball_foot", "ball_robot", "sources"});
  const JsonObject sources = o.Object("sources");
  sources.RejectUnknownKeys({"ball_carpet", "ball_post", "ball_net", "ball_foot", "ball_robot"});
  BallPairs pairs;
  for (const PairKey& p : kPairKeys) {
    pairs.*p.value = o.Number(p.key);
    if (sources.String(p.key).empty()) sources.Fail(p.key, "must say where the value comes from");
  }
  return pairs;
}

MaterialParams ReadMaterials(const JsonObject& o) {
  o.RejectUnknownKeys({"restitution", "friction", "net_thickness_m"});
  MaterialParams m;
  m.restitution = ReadPairs(o.Object("restitution"));
  m.friction = ReadPairs(o.Object("friction"));
  m.net_thickness_m = o.Number("net_thickness_m");
  return m;
}

// {"base": "floating", "friction": mu, "restitution": e, "fall_tilt_deg": deg, "sources": {...}}:
// every value with the reason for it.
RobotContactParams ReadRobot(const JsonObject& o) {
  o.RejectUnknownKeys({"base", "friction", "restitution", "fall_tilt_deg", "sources"});
  RobotContactParams r;
  const std::string base = o.String("base");
  const std::optional<RobotBase> parsed = ParseRobotBase(base);
  if (!parsed) o.Fail("base", "must be one of " + RobotBaseList() + ", got '" + base + "'");
  r.base = *parsed;
  r.friction = o.Number("friction");
  r.restitution = o.Number("restitution");
  const double fall_tilt_deg = o.Number("fall_tilt_deg");
  if (!(fall_tilt_deg >= 1.0 && fall_tilt_deg <= 90.0)) {
    o.Fail("fall_tilt_deg", "must be in [1, 90], got " + FormatNumber(fall_tilt_deg));
  }
  r.fall_tilt_rad = fall_tilt_deg * kDegToRad;  // files: degrees
  const JsonObject sources = o.Object("sources");
  sources.RejectUnknownKeys({"base", "friction", "restitution", "fall_tilt_deg"});
  for (const char* key : {"base", "friction", "restitution", "fall_tilt_deg"}) {
    if (sources.String(key).empty()) sources.Fail(key, "must say where the value comes from");
  }
  return r;
}

// The fall watch after the launch: every value with the reason for it; tilts in degrees.
WatchParams ReadWatch(const JsonObject& o) {
  static constexpr std::string_view kKeys[] = {
      "still_time_s",          "still_joint_speed_radps", "still_base_speed_mps",
      "still_base_rate_radps", "still_tilt_deg",          "still_support_margin_m",
      "sources"};
  const std::span<const std::string_view> values(kKeys, std::size(kKeys) - 1);
  o.RejectUnknownKeys(std::span<const std::string_view>(kKeys));
  const JsonObject sources = o.Object("sources");
  sources.RejectUnknownKeys(values);
  for (std::string_view key : values) {
    if (sources.String(key).empty()) sources.Fail(key, "must say where the value comes from");
  }
  WatchParams w;
  w.still_time_s = o.Number("still_time_s");
  w.still_joint_speed_radps = o.Number("still_joint_speed_radps");
  w.still_base_speed_mps = o.Number("still_base_speed_mps");
  w.still_base_rate_radps = o.Number("still_base_rate_radps");
  w.still_tilt_rad = o.Number("still_tilt_deg") * kDegToRad;  // files: degrees
  w.still_support_margin_m = o.Number("still_support_margin_m");
  return w;
}

MotorParams ReadMotors(const JsonObject& o) {
  o.RejectUnknownKeys({"position_gain", "velocity_gain"});
  MotorParams m;
  m.position_gain = o.Number("position_gain");
  m.velocity_gain = o.Number("velocity_gain");
  return m;
}

StepParams ReadSteps(const JsonObject& o) {
  o.RejectUnknownKeys({"kick_time_step_s", "near_time_step_s", "max_overlap_m", "free_time_step_s",
                       "slow_speed_mps", "slow_time_step_s",
                       "max_kick_time_s", "max_roll_time_s", "rest_speed_mps",
                       "min_launch_roll_m", "solver_iterations", "restitution_threshold_mps"});
  StepParams s;
  s.kick_time_step_s = o.Number("kick_time_step_s");
  s.near_time_step_s = o.Number("near_time_step_s");
  s.max_overlap_m = o.Number("max_overlap_m");
  s.free_time_step_s = o.Number("free_time_step_s");
  s.slow_speed_mps = o.Number("slow_speed_mps");
  s.slow_time_step_s = o.Number("slow_time_step_s");
  s.max_kick_time_s = o.Number("max_kick_time_s");
  s.max_roll_time_s = o.Number("max_roll_time_s");
  s.rest_speed_mps = o.Number("rest_speed_mps");
  s.min_launch_roll_m = o.Number("min_launch_roll_m");
  s.solver_iterations = o.Integer("solver_iterations");
  s.restitution_threshold_mps = o.Number("restitution_threshold_mps");
  return s;
}

}  // namespace

PhysicsParams LoadPhysicsParams(const std::filesystem::path& file) {
  JsonDocument doc = JsonDocument::Load(file);
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"carpet", "robot", "watch", "motors", "materials", "steps"});
  PhysicsParams params;
  params.carpet = ReadCarpet(root.Object("carpet"));
  params.robot = ReadRobot(root.Object("robot"));
  params.motors = ReadMotors(root.Object("motors"));
  params.materials = ReadMaterials(root.Object("materials"));
  params.steps = ReadSteps(root.Object("steps"));
  params.watch = ReadWatch(root.Object("watch"));
  WithFile(file.string(), [&] { params.Validate(); });
  return params;
}

}  // namespace foresight
