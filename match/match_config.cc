#include "match/match_config.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/checks.h"
#include "common/error.h"
#include "common/one_line.h"
#include "models/model_paths.h"
#include "models/placement.h"

namespace foresight {

namespace {

Pose2 ReadPose(const JsonObject& o) {
  o.RejectUnknownKeys({"x_m", "y_m", "theta_deg"});
  const double theta_deg = o.Number("theta_deg");
  WithFile(o.file(), [&] { RequireInRange(o.PathOf("theta_deg"), theta_deg, -360.0, 360.0); });
  return Pose2{Vec2(o.Number("x_m"), o.Number("y_m")), WrapAngle(theta_deg * kDegToRad)};
}

// Where a match can start (models/placement.h): the ball on the field, clear of the posts and
// out of the goals; every robot on the field, clear of the posts and of every other robot.
void RequirePlayablePlacement(const Scenario& s, const FieldSpec& field, const RobotParams& robot) {
  RequireOnField(field, "ball", s.p_F_ball);
  RequireClearOfPosts(field, "ball", s.p_F_ball, field.ball.radius_m);
  RequireBallOutOfGoals(field, s.p_F_ball);
  std::vector<std::pair<std::string, Vec2>> bodies;
  for (std::size_t i = 0; i < s.attackers.size(); ++i)
    bodies.emplace_back("attackers[" + std::to_string(i) + "]", s.attackers[i].p_F);
  for (std::size_t i = 0; i < s.opponents.size(); ++i)
    bodies.emplace_back("opponents[" + std::to_string(i) + "]", s.opponents[i].p_F);
  const double r = robot.body_radius_m;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const auto& [name, p] = bodies[i];
    RequireOnField(field, name, p);
    RequireClearOfPosts(field, name, p, r);
    for (std::size_t j = 0; j < i; ++j) {
      if ((p - bodies[j].second).norm() < 2.0 * r) {
        throw InputError(name + ": position " + PointText(p) + " overlaps " + bodies[j].first +
                         " at " + PointText(bodies[j].second) + " (robots of radius " +
                         FormatNumber(r) + " m)");
      }
    }
  }
}

// A scenario's name is part of its output files' names (passing_example_<name>.svg): at most
// kMaxScenarioNameBytes letters, digits, '_', '-' and '.'.
constexpr std::size_t kMaxScenarioNameBytes = 64;
void RequireFileNamePart(const JsonObject& root, const std::string& name) {
  const bool usable =
      !name.empty() && name.size() <= kMaxScenarioNameBytes &&
      std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-' || c == '.';
      });
  if (!usable) {
    root.Fail("name", "must be 1-" + std::to_string(kMaxScenarioNameBytes) +
                          " letters, digits, '_', '-' or '.' (it names the output files), got '" +
                          PrintableName(name) + "'");
  }
}

Vec2 ReadPoint(const JsonObject& o) {
  o.RejectUnknownKeys({"x_m", "y_m"});
  return Vec2(o.Number("x_m"), o.Number("y_m"));
}

Scenario LoadScenario(const std::filesystem::path& file, int opponent_count,
                      const FieldSpec& field, const RobotParams& robot) {
  const JsonDocument doc = JsonDocument::Load(file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"name", "ball", "attackers", "opponents"});
  Scenario s;
  s.name = root.String("name");
  RequireFileNamePart(root, s.name);
  s.p_F_ball = ReadPoint(root.Object("ball"));
  for (const JsonObject& o : root.ObjectArray("attackers")) s.attackers.push_back(ReadPose(o));
  for (const JsonObject& o : root.ObjectArray("opponents")) s.opponents.push_back(ReadPose(o));
  if (s.attackers.size() != 2) root.Fail("attackers", "must list the two attackers A and B");
  if (static_cast<int>(s.opponents.size()) != opponent_count) {
    root.Fail("opponents", "must list " + std::to_string(opponent_count) +
                               " opponents, one per opponent of the configuration");
  }
  WithFile(file.string(), [&] { RequirePlayablePlacement(s, field, robot); });
  return s;
}

Pose2 MirrorPose(const Pose2& pose) {
  return Pose2{Vec2(-pose.p_F.x(), pose.p_F.y()), WrapAngle(kPi - pose.theta_rad)};
}

std::string RegionText(const FieldBox& r) {
  return "x [" + FormatNumber(r.x_min_m) + ", " + FormatNumber(r.x_max_m) + "], y [" +
         FormatNumber(r.y_min_m) + ", " + FormatNumber(r.y_max_m) + "]";
}

}  // namespace

std::string_view GoalieModelName(GoalieModel model) {
  return model == GoalieModel::kRos2009 ? "ros2009" : "runswift2005";
}

std::optional<GoalieModel> GoalieModelNamed(std::string_view name) {
  for (GoalieModel m : {GoalieModel::kRos2009, GoalieModel::kRunswift2005}) {
    if (GoalieModelName(m) == name) return m;
  }
  return std::nullopt;
}

FieldBox PenaltyArea(const FieldSpec& field, const SimulationParams& sim, double sign) {
  const FieldBox area{field.HalfLength() - sim.penalty_area_depth_m, field.HalfLength(),
                      -sim.penalty_area_half_width_m, sim.penalty_area_half_width_m};
  return sign > 0.0 ? area : area.MirroredX();
}

void MatchConfig::Validate(const FieldSpec& field, const SimulationParams& sim,
                           const RobotParams& robot) const {
  const FieldBox area = PenaltyArea(field, sim, 1.0);
  const double r = robot.body_radius_m;
  RequireInRange("time_limit_s", time_limit_s, 1.0, 3600.0);
  RequireInRange("clear_free_distance_m", clear_free_distance_m, 0.0, 5.0);
  RequireInRange("clear_free_cone_deg", clear_free_cone_rad * kRadToDeg, 0.0, 90.0);
  RequireInRange("clear_direction_margin_sd", clear_direction_margin_sd, 0.0, 5.0);
  if (HasGoalie()) {
    RequireInRange("goalie.latency_s", goalie.latency_s, 0.0, 2.0);
    RequireInRange("goalie.guard_distance_m", goalie.guard_distance_m, 0.0, 1.0);
    RequireInRange("goalie.walk_speed_mps", goalie.walk_speed_mps, 0.01, robot.walk_speed_mps);
    RequireInRange("goalie.block_earliest_s", goalie.block_earliest_s, robot.block_down_s, 10.0);
    RequireInRange("goalie.block_refractory_s", goalie.block_refractory_s, 0.0, 60.0);
  }
  RequireInRange("default_trials", default_trials, 1, 1000000);
  if (opponents.empty()) throw InputError("opponents: must list at least one opponent");
  for (std::size_t i = 0; i < opponents.size(); ++i) {
    const OpponentSpec& o = opponents[i];
    const FieldBox& g = o.region;
    const std::string at = "opponents[" + std::to_string(i) + "].region";
    if (g.x_min_m < -field.HalfLength() || g.x_max_m > field.HalfLength() ||
        g.y_min_m < -field.HalfWidth() || g.y_max_m > field.HalfWidth()) {
      throw InputError(at + ": must lie on the field, got " + RegionText(g));
    }
    if (o.role == OpponentRole::kGoalie &&
        !(area.Contains(Vec2(g.x_min_m, g.y_min_m)) && area.Contains(Vec2(g.x_max_m, g.y_max_m)))) {
      throw InputError(at + ": a goalie stays in the penalty area " + RegionText(area) + ", got " +
                       RegionText(g));
    }
    const bool body_may_enter = g.x_max_m + r > area.x_min_m && g.y_max_m + r > area.y_min_m &&
                                g.y_min_m - r < area.y_max_m;
    if (o.role == OpponentRole::kDefender && body_may_enter) {
      throw InputError(at + ": a defender's body (radius " + FormatNumber(r) +
                       " m) must stay out of the penalty area " + RegionText(area) + ", got " +
                       RegionText(g));
    }
  }
  for (std::size_t s = 0; s < scenarios.size(); ++s) {
    for (std::size_t i = 0; i < opponents.size(); ++i) {
      if (!opponents[i].region.Contains(scenarios[s].opponents[i].p_F)) {
        throw InputError("scenarios[" + std::to_string(s) + "] (" + scenarios[s].name +
                         "): opponent " + opponents[i].name + " starts outside its region " +
                         RegionText(opponents[i].region));
      }
    }
  }
}

bool MatchConfig::HasGoalie() const {
  return std::any_of(opponents.begin(), opponents.end(),
                     [](const OpponentSpec& o) { return o.role == OpponentRole::kGoalie; });
}

std::vector<std::string> MatchConfig::OpponentNames() const {
  std::vector<std::string> names;
  for (const OpponentSpec& o : opponents) names.push_back(o.name);
  return names;
}

MatchConfig MatchConfig::Mirrored() const {
  MatchConfig m = *this;
  for (OpponentSpec& o : m.opponents) o.region = o.region.MirroredX();
  for (Scenario& s : m.scenarios) {
    s.p_F_ball.x() = -s.p_F_ball.x();
    for (Pose2& p : s.attackers) p = MirrorPose(p);
    for (Pose2& p : s.opponents) p = MirrorPose(p);
  }
  return m;
}

MatchConfig LoadMatchConfig(const std::string& reference, const std::filesystem::path& models_dir,
                            const FieldSpec& field, const SimulationParams& sim,
                            const RobotParams& robot) {
  MatchConfig c;
  c.file = ResolveModelFile(reference, DataFolder::kMatch, ".", models_dir);
  const JsonDocument doc = JsonDocument::Load(c.file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"name", "notes", "sources", "opponents", "clear_kick",
                          "clear_side_kicks", "clear_direction_margin_sd", "clear_free_distance_m",
                          "clear_free_cone_deg", "penalty_area_ends_trial", "time_limit_s",
                          "time_limit_kind", "goalie", "default_trials", "scenarios"});
  std::vector<std::string_view> figures{"opponents",
                                        "clear_kick",
                                        "clear_side_kicks",
                                        "clear_direction_margin_sd",
                                        "clear_free_distance_m",
                                        "clear_free_cone_deg",
                                        "penalty_area_ends_trial",
                                        "time_limit_s",
                                        "time_limit_kind",
                                        "default_trials",
                                        "scenarios"};
  c.name = root.String("name");
  c.clear_kick = root.String("clear_kick");
  c.clear_side_kicks = root.StringArray("clear_side_kicks");
  c.clear_direction_margin_sd = root.Number("clear_direction_margin_sd");
  c.clear_free_distance_m = root.Number("clear_free_distance_m");
  c.clear_free_cone_rad = root.Number("clear_free_cone_deg") * kDegToRad;
  const std::string ends = root.String("penalty_area_ends_trial");
  if (ends != "yes" && ends != "no") root.Fail("penalty_area_ends_trial", "must be yes or no");
  c.penalty_area_ends_trial = ends == "yes";
  c.time_limit_s = root.Number("time_limit_s");
  const std::string kind = root.String("time_limit_kind");
  if (kind != "timeout" && kind != "safety_cap") {
    root.Fail("time_limit_kind", "must be timeout or safety_cap");
  }
  c.time_limit_is_safety_cap = kind == "safety_cap";
  c.default_trials = root.Integer("default_trials");
  for (const JsonObject& o : root.ObjectArray("opponents")) {
    o.RejectUnknownKeys({"name", "role", "region"});
    OpponentSpec spec;
    spec.name = o.String("name");
    const std::string role = o.String("role");
    if (role != "goalie" && role != "defender") o.Fail("role", "must be goalie or defender");
    spec.role = role == "goalie" ? OpponentRole::kGoalie : OpponentRole::kDefender;
    spec.region = ReadFieldBox(o.Object("region"));
    c.opponents.push_back(spec);
  }
  if (c.HasGoalie()) figures.push_back("goalie");
  RequireSources(root, figures);
  if (c.HasGoalie()) {
    const JsonObject g = root.Object("goalie");
    g.RejectUnknownKeys({"model", "latency_s", "guard_distance_m", "walk_speed_mps",
                         "block_earliest_s", "block_refractory_s"});
    const std::string model = g.String("model");
    const std::optional<GoalieModel> named = GoalieModelNamed(model);
    if (!named) g.Fail("model", "must be ros2009 or runswift2005, got '" + model + "'");
    c.goalie.model = *named;
    c.goalie.latency_s = g.Number("latency_s");
    c.goalie.guard_distance_m = g.Number("guard_distance_m");
    c.goalie.walk_speed_mps = g.Number("walk_speed_mps");
    c.goalie.block_earliest_s = g.Number("block_earliest_s");
    c.goalie.block_refractory_s = g.Number("block_refractory_s");
  }
  const auto names = root.StringArray("scenarios");
  if (names.empty()) root.Fail("scenarios", "must list at least one scenario");
  for (const std::string& name : names) {
    const std::string key = "scenarios[" + std::to_string(c.scenarios.size()) + "]";
    std::filesystem::path file;
    WithFile(c.file.string(), [&] {
      file = NamedFile(key, ResolveModelFile(name, DataFolder::kMatchScenarios,
                                             c.file.parent_path(), models_dir));
    });
    c.scenarios.push_back(
        LoadScenario(file, static_cast<int>(c.opponents.size()), field, robot));
    const std::size_t last = c.scenarios.size() - 1;
    for (std::size_t i = 0; i < last; ++i) {
      if (c.scenarios[i].name == c.scenarios[last].name) {
        root.Fail("scenarios", "scenarios[" + std::to_string(i) + "] and scenarios[" +
                                   std::to_string(last) + "] are both named '" +
                                   c.scenarios[last].name +
                                   "' (their output files would be the same)");
      }
    }
  }
  WithFile(c.file.string(), [&] { c.Validate(field, sim, robot); });
  return c;
}

}  // namespace foresight
