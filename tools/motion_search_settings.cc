#include "tools/motion_search_settings.h"

#include <cmath>

#include "common/checks.h"
#include "common/geometry.h"
#include "common/json_reader.h"
#include "models/model_paths.h"

namespace foresight {

namespace {

// Bounds that keep a search finite and sane; a file asking for more is a typo, not a plan.
constexpr int kMaxCandidates = 100000;
constexpr int kMaxTrials = 100000;
constexpr int kMaxRounds = 100;

double NumberIn(const JsonObject& obj, std::string_view key, double lo, double hi) {
  const double value = obj.Number(key);
  if (!(value >= lo && value <= hi)) {
    obj.Fail(key, "must be in [" + FormatNumber(lo) + ", " + FormatNumber(hi) + "], got " +
                      FormatNumber(value));
  }
  return value;
}

int IntegerIn(const JsonObject& obj, std::string_view key, int lo, int hi) {
  const int value = obj.Integer(key);
  if (value < lo || value > hi) {
    obj.Fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                      std::to_string(value));
  }
  return value;
}

// A motion file named from the settings' folder; it must exist (its content is checked against
// the robot when the search loads it).
std::filesystem::path StartFile(const JsonObject& root, const std::filesystem::path& dir) {
  const std::filesystem::path start = root.String("start");
  if (start.empty() || start.extension() != ".json") {
    root.Fail("start", "must be a motion file (.json), got '" + start.string() + "'");
  }
  const std::filesystem::path file = start.is_absolute() ? start : dir / start;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    root.Fail("start", "no motion file " + file.string());
  }
  return file;
}

SearchRound ReadRound(const JsonObject& obj) {
  obj.RejectUnknownKeys({"candidates", "trials", "keyframe_sigma_deg", "time_sigma_rel",
                         "balance_sigma_deg", "max_tilt_deg"});
  SearchRound round;
  round.candidates = IntegerIn(obj, "candidates", 1, kMaxCandidates);
  round.trials = IntegerIn(obj, "trials", 1, kMaxTrials);
  round.keyframe_sigma_rad = NumberIn(obj, "keyframe_sigma_deg", 0.0, 90.0) * kDegToRad;
  round.time_sigma_rel = NumberIn(obj, "time_sigma_rel", 0.0, 0.5);
  round.balance_sigma_rad = NumberIn(obj, "balance_sigma_deg", 0.0, 45.0) * kDegToRad;
  if (obj.Has("max_tilt_deg")) round.max_tilt_rad = NumberIn(obj, "max_tilt_deg", 0.0, 90.0) * kDegToRad;
  return round;
}

SearchConstraints ReadConstraints(const JsonObject& obj) {
  obj.RejectUnknownKeys(
      {"min_clearance_m", "max_speed_share", "max_fall_share", "max_duration_s", "max_tilt_deg"});
  SearchConstraints c;
  c.min_clearance_m = NumberIn(obj, "min_clearance_m", -1.0, 1.0);
  c.max_speed_share = NumberIn(obj, "max_speed_share", 0.01, 1.0);
  c.max_fall_share = NumberIn(obj, "max_fall_share", 0.0, 1.0);
  c.max_duration_s = NumberIn(obj, "max_duration_s", 0.01, 60.0);
  if (obj.Has("max_tilt_deg")) c.max_tilt_rad = NumberIn(obj, "max_tilt_deg", 0.0, 90.0) * kDegToRad;
  return c;
}

SearchObjective ReadObjective(const JsonObject& obj) {
  obj.RejectUnknownKeys({"target_speed_mps", "target_direction_deg", "speed_sd_max_mps",
                         "sd_weight", "min_speed_mps", "low_weight", "direction_max_deg",
                         "direction_weight_per_deg", "miss_weight", "fall_weight"});
  SearchObjective o;
  o.target_speed_mps = NumberIn(obj, "target_speed_mps", 0.0, 20.0);
  o.target_direction_rad = NumberIn(obj, "target_direction_deg", -180.0, 180.0) * kDegToRad;
  o.speed_sd_max_mps = NumberIn(obj, "speed_sd_max_mps", 0.0, 20.0);
  o.sd_weight = NumberIn(obj, "sd_weight", 0.0, 1e6);
  o.min_speed_mps = NumberIn(obj, "min_speed_mps", 0.0, 20.0);
  o.low_weight = NumberIn(obj, "low_weight", 0.0, 1e6);
  o.direction_max_rad = NumberIn(obj, "direction_max_deg", 0.0, 180.0) * kDegToRad;
  // Per degree in the file, per radian in the code.
  o.direction_weight = NumberIn(obj, "direction_weight_per_deg", 0.0, 1e6) * kRadToDeg;
  o.miss_weight = NumberIn(obj, "miss_weight", 0.0, 1e6);
  o.fall_weight = NumberIn(obj, "fall_weight", 0.0, 1e6);
  return o;
}

}  // namespace

MotionSearchSettings LoadMotionSearchSettings(const std::filesystem::path& file,
                                              const std::filesystem::path& models_dir) {
  const JsonDocument doc = JsonDocument::Load(file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"notes", "situation", "kicks", "kick", "start", "base", "seed",
                          "rounds", "constraints", "objective", "keep"});
  if (root.String("notes").empty()) root.Fail("notes", "must say why the numbers are what they are");
  MotionSearchSettings s;
  s.file = file;
  const std::filesystem::path dir = file.parent_path();
  s.situation_file =
      ResolveModelFile(root.String("situation"), DataFolder::kCalibration, dir, models_dir);
  if (root.Has("kicks")) {
    s.kicks_file = ResolveModelFile(root.String("kicks"), DataFolder::kKicks, dir, models_dir);
  }
  s.kick = root.String("kick");
  if (s.kick.empty()) root.Fail("kick", "must name a kick");
  if (root.Has("start")) s.start_file = StartFile(root, dir);
  const std::string base = root.String("base");
  const std::optional<RobotBase> parsed = ParseRobotBase(base);
  if (!parsed) root.Fail("base", "must be one of " + RobotBaseList() + ", got '" + base + "'");
  s.base = *parsed;
  s.seed = static_cast<std::uint64_t>(IntegerIn(root, "seed", 0, 2147483647));
  for (const JsonObject& round : root.ObjectArray("rounds")) s.rounds.push_back(ReadRound(round));
  if (s.rounds.empty()) root.Fail("rounds", "must list at least one round");
  if (s.rounds.size() > static_cast<std::size_t>(kMaxRounds)) {
    root.Fail("rounds", "at most " + std::to_string(kMaxRounds) + " rounds, got " +
                            std::to_string(s.rounds.size()));
  }
  s.constraints = ReadConstraints(root.Object("constraints"));
  s.objective = ReadObjective(root.Object("objective"));
  s.keep = IntegerIn(root, "keep", 1, 1000);
  return s;
}

}  // namespace foresight
