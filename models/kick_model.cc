#include "models/kick_model.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "common/checks.h"
#include "common/error.h"
#include "common/geometry.h"
#include "common/json_reader.h"

namespace foresight {

// Plausibility bound of a launch offset (assumption): kicks slide a few centimetres before they
// roll (physics: about 5 cm); half a metre is a unit error. It cannot be negative: free rolling
// does not start behind where the ball lay.
constexpr double kMaxLaunchOffsetM = 0.5;

std::optional<int> KickModel::Find(const std::string& name) const {
  for (std::size_t i = 0; i < kicks.size(); ++i) {
    if (kicks[i].name == name) return static_cast<int>(i);
  }
  return std::nullopt;
}

std::string KickModel::NameOf(int kick_index) const {
  if (kick_index == kNoKick) return "none";
  return kicks.at(static_cast<std::size_t>(kick_index)).name;
}

std::string KickModel::Names() const {
  std::string names;
  for (const KickSpec& k : kicks) names += (names.empty() ? "" : ", ") + k.name;
  return names;
}

void KickModel::Validate() const {
  RequireInRange("rolling_deceleration_mps2", rolling_deceleration_mps2, 1e-3, 100.0);
  if (kicks.empty()) throw InputError("kicks: must list at least one kick");
  for (std::size_t i = 0; i < kicks.size(); ++i) {
    const KickSpec& kick = kicks[i];
    const std::string at = "kicks[" + std::to_string(i) + "].";
    if (kick.name.empty() || kick.name == "none") {
      throw InputError(at + "name: must be a non-empty name other than 'none', got '" + kick.name +
                       "'");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (kicks[j].name == kick.name) throw InputError(at + "name: duplicate '" + kick.name + "'");
    }
    RequireInRange(at + "speed_mps", kick.speed_mps, 0.0, kMaxKickSpeedMps);
    RequireInRange(at + "sigma_speed_mps", kick.sigma_speed_mps, 0.0, kMaxKickSpeedMps);
    RequireInRange(at + "direction_deg", kick.direction_rad * kRadToDeg, -180.0, 180.0);
    RequireInRange(at + "sigma_direction_deg", kick.sigma_direction_rad * kRadToDeg, 0.0, 180.0);
    RequireInRange(at + "launch_offset_m", kick.launch_offset_m, 0.0, kMaxLaunchOffsetM);
  }
}

namespace {

KickModel ReadKickModel(const JsonDocument& doc) {
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"robot", "rolling_deceleration_mps2", "kicks", "sources"});
  KickModel model;
  model.robot = root.String("robot");
  model.rolling_deceleration_mps2 = root.Number("rolling_deceleration_mps2");
  for (const JsonObject& item : root.ObjectArray("kicks")) {
    item.RejectUnknownKeys({"name", "speed_mps", "sigma_speed_mps", "direction_deg",
                            "sigma_direction_deg", "launch_offset_m"});
    KickSpec kick;
    kick.name = item.String("name");
    kick.speed_mps = item.Number("speed_mps");
    kick.sigma_speed_mps = item.Number("sigma_speed_mps");
    kick.direction_rad = item.Number("direction_deg") * kDegToRad;  // files say degrees
    kick.sigma_direction_rad = item.Number("sigma_direction_deg") * kDegToRad;
    kick.launch_offset_m = item.NumberOr("launch_offset_m", 0.0);  // the paper's models: none
    model.kicks.push_back(kick);
  }
  // A model from published figures names the source of each kick and of the deceleration.
  if (root.Has("sources")) {
    std::vector<std::string_view> figures{"rolling_deceleration_mps2"};
    for (const KickSpec& kick : model.kicks) figures.push_back(kick.name);
    RequireSources(root, figures);
  }
  WithFile(root.file(), [&] { model.Validate(); });
  return model;
}

}  // namespace

KickModel LoadKickModel(const std::filesystem::path& file) {
  return ReadKickModel(JsonDocument::Load(file));
}

KickModel ParseKickModel(std::string_view text, const std::string& origin) {
  return ReadKickModel(JsonDocument::Parse(text, origin));
}

namespace {

std::string Rounded(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string s = buffer;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

std::string Quoted(std::string_view text) {
  return nlohmann::json(std::string(text)).dump();
}

}  // namespace

std::string KickModelJson(const KickModel& model, std::string_view notes) {
  std::string out = "{\n  \"robot\": " + Quoted(model.robot) + ",\n";
  if (!notes.empty()) out += "  \"notes\": " + Quoted(notes) + ",\n";
  out += "  \"rolling_deceleration_mps2\": " +
         Rounded(model.rolling_deceleration_mps2, kKickFileSpeedDecimals) + ",\n";
  out += "  \"kicks\": [\n";
  for (std::size_t i = 0; i < model.kicks.size(); ++i) {
    const KickSpec& k = model.kicks[i];
    out += "    {\"name\": " + Quoted(k.name) +
           ", \"speed_mps\": " + Rounded(k.speed_mps, kKickFileSpeedDecimals) +
           ", \"sigma_speed_mps\": " + Rounded(k.sigma_speed_mps, kKickFileSpeedDecimals) +
           ", \"direction_deg\": " + Rounded(k.direction_rad * kRadToDeg, kKickFileAngleDecimals) +
           ", \"sigma_direction_deg\": " +
           Rounded(k.sigma_direction_rad * kRadToDeg, kKickFileAngleDecimals);
    // Written only when there is one, so models without it keep their bytes (0.1 mm).
    if (k.launch_offset_m != 0.0)
      out += ", \"launch_offset_m\": " + Rounded(k.launch_offset_m, kKickFileSpeedDecimals);
    out += "}";
    out += i + 1 < model.kicks.size() ? ",\n" : "\n";
  }
  return out + "  ]\n}\n";
}

}  // namespace foresight
