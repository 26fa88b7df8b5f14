#include "experiments/experiment_params.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "common/checks.h"
#include "common/error.h"
#include "common/json_reader.h"
#include "models/model_paths.h"

namespace foresight {

namespace {

constexpr int kMaxSampless = 1000;

std::filesystem::path ParamsFile(const std::string& params, const std::filesystem::path& models) {
  return ResolveModelFile(params, DataFolder::kExperiments, std::filesystem::current_path(),
                          models);
}

JsonDocument LoadParamsFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError("--params: " + file.string() + " does not exist");
  }
  return JsonDocument::Load(file);
}

Situation LoadScene(const JsonObject& root, const std::filesystem::path& file,
                    const std::filesystem::path& models_dir, const SituationOverrides& overrides) {
  const std::filesystem::path situation_file = ResolveModelFile(
      root.String("situation"), DataFolder::kSituations, file.parent_path(), models_dir);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(situation_file, ec)) {
    root.Fail("situation", "refers to " + situation_file.string() + ", which does not exist");
  }
  return LoadSituation(situation_file, models_dir, overrides);
}

Strategy StrategyOf(const JsonObject& root, std::string_view key, const std::string& name) {
  const std::optional<Strategy> strategy = ParseStrategy(name);
  if (!strategy) root.Fail(key, "must be one of " + StrategyNames() + ", got '" + name + "'");
  return *strategy;
}

int WholeNumber(const JsonObject& root, std::string_view key, double value) {
  if (value != std::floor(value) || std::abs(value) > 1e9) {
    root.Fail(key, "must be a whole number, got " + FormatNumber(value));
  }
  return static_cast<int>(value);
}

int ParseInt(const std::string& field, const std::string& text) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) {
    throw InputError(field + ": '" + text + "' is not a whole number");
  }
  return value;
}

}  // namespace

void StabilityParams::Validate() const {
  RequireInRange("grid_step_m", grid_step_m, 0.05, 3.0);
  RequireInRange("heading_step_deg", heading_step_rad * kRadToDeg, 1.0, 360.0);
  RequireInRange("repeats", repeats, 2, 100000);
  if (sample_counts.size() > static_cast<std::size_t>(kMaxSampless)) {
    throw InputError("sample_counts: must list at most " + std::to_string(kMaxSampless) +
                     " counts, got " + std::to_string(sample_counts.size()));
  }
  RequireInRange("rotation_bin_deg", rotation_bin_rad * kRadToDeg, 0.1, 360.0);
  if (sample_counts.empty()) throw InputError("sample_counts: must list at least one count");
  for (std::size_t i = 0; i < sample_counts.size(); ++i) {
    RequireInRange("sample_counts", sample_counts[i], 1, kMaxSamples);
    if (i > 0 && sample_counts[i] <= sample_counts[i - 1]) {
      throw InputError("sample_counts: must be ascending without repeats, got " +
                       std::to_string(sample_counts[i]) + " after " +
                       std::to_string(sample_counts[i - 1]));
    }
  }
  if (!std::ranges::binary_search(sample_counts, map_samples)) {
    throw InputError("map_samples: must be one of sample_counts, got " +
                     std::to_string(map_samples));
  }
}

void StrategiesParams::Validate() const {
  if (strategies.empty()) throw InputError("strategies: must list at least one strategy");
  RequireInRange("starts", starts, 1, 10000000);
  RequireInRange("max_steps", max_steps, 1, 100000);
  RequireInRange("walk_speed_mps", walk_speed_mps, 0.001, 10.0);
  RequireInRange("turn_speed_deg_per_s", turn_speed_radps * kRadToDeg, 0.1, 3600.0);
  RequireInRange("turn_around_ball_speed_deg_per_s", turn_around_ball_speed_radps * kRadToDeg, 0.1,
                 3600.0);
  RequireInRange("example_start", example_start, 0, starts - 1);
  if (!situation.obstacles.empty()) {
    throw InputError("situation: must have no obstacles (the experiment runs on an empty field)");
  }
}

StabilityParams LoadStabilityParams(const std::string& params,
                                    const std::filesystem::path& models_dir,
                                    const SituationOverrides& overrides) {
  StabilityParams p;
  p.file = ParamsFile(params, models_dir);
  const JsonDocument doc = LoadParamsFile(p.file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"situation", "strategy", "grid_step_m", "heading_step_deg", "repeats",
                          "sample_counts", "map_samples", "rotation_bin_deg"});
  p.situation = LoadScene(root, p.file, models_dir, overrides);
  p.strategy = StrategyOf(root, "strategy", root.String("strategy"));
  p.grid_step_m = root.Number("grid_step_m");
  p.heading_step_rad = root.Number("heading_step_deg") * kDegToRad;
  p.repeats = WholeNumber(root, "repeats", root.Number("repeats"));
  for (double n : root.NumberArray("sample_counts")) {
    p.sample_counts.push_back(WholeNumber(root, "sample_counts", n));
  }
  p.map_samples = WholeNumber(root, "map_samples", root.Number("map_samples"));
  p.rotation_bin_rad = root.Number("rotation_bin_deg") * kDegToRad;
  WithFile(p.file.string(), [&] { p.Validate(); });
  return p;
}

StrategiesParams LoadStrategiesParams(const std::string& params,
                                      const std::filesystem::path& models_dir,
                                      const SituationOverrides& overrides) {
  StrategiesParams p;
  p.file = ParamsFile(params, models_dir);
  const JsonDocument doc = LoadParamsFile(p.file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"situation", "strategies", "starts", "max_steps", "walk_speed_mps",
                          "turn_speed_deg_per_s", "turn_around_ball_speed_deg_per_s",
                          "example_start"});
  p.situation = LoadScene(root, p.file, models_dir, overrides);
  for (const std::string& name : root.StringArray("strategies")) {
    const Strategy s = StrategyOf(root, "strategies", name);
    if (std::ranges::find(p.strategies, s) != p.strategies.end()) {
      root.Fail("strategies", "lists '" + name + "' twice");
    }
    p.strategies.push_back(s);
  }
  p.starts = WholeNumber(root, "starts", root.Number("starts"));
  p.max_steps = WholeNumber(root, "max_steps", root.Number("max_steps"));
  p.walk_speed_mps = root.Number("walk_speed_mps");
  p.turn_speed_radps = root.Number("turn_speed_deg_per_s") * kDegToRad;
  p.turn_around_ball_speed_radps = root.Number("turn_around_ball_speed_deg_per_s") * kDegToRad;
  p.example_start = WholeNumber(root, "example_start", root.NumberOr("example_start", 0.0));
  WithFile(p.file.string(), [&] { p.Validate(); });
  return p;
}

std::vector<int> ParseSampleCounts(const std::string& field, const std::string& text) {
  std::vector<int> counts;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string item = text.substr(begin, comma - begin);
    const std::size_t dash = item.find('-'), slash = item.find('/');
    if (dash == std::string::npos) {
      if (slash != std::string::npos)
        throw InputError(field + ": '" + item + "': a step needs a range lo-hi");
      counts.push_back(ParseInt(field, item));
    } else {
      const int lo = ParseInt(field, item.substr(0, dash));
      const int hi = ParseInt(
          field,
          item.substr(dash + 1, slash == std::string::npos ? std::string::npos : slash - dash - 1));
      const int step = slash == std::string::npos ? 1 : ParseInt(field, item.substr(slash + 1));
      if (step < 1 || hi < lo) {
        throw InputError(field + ": '" + item + "' must be lo-hi with lo <= hi and a step >= 1");
      }
      if (hi > kMaxSamples) {
        throw InputError(field + ": '" + item + "' goes beyond " + std::to_string(kMaxSamples) +
                         " samples");
      }
      for (int n = lo; n <= hi; n += step) counts.push_back(n);
    }
    if (counts.size() > static_cast<std::size_t>(kMaxSampless)) {
      throw InputError(field + ": more than " + std::to_string(kMaxSampless) + " sample counts");
    }
    begin = comma + 1;
  }
  return counts;
}

}  // namespace foresight
