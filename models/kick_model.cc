#include "models/kick_model.h"

#include "models/checks.h"
#include "models/error.h"
#include "models/geometry.h"
#include "models/json_reader.h"

namespace foresight {

std::optional<int> KickModel::Find(const std::string& name) const {
  for (std::size_t i = 0; i < kicks.size(); ++i) {
    if (kicks[i].name == name) return static_cast<int>(i);
  }
  return std::nullopt;
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
    RequireInRange(at + "speed_mps", kick.speed_mps, 0.0, 50.0);
    RequireInRange(at + "sigma_speed_mps", kick.sigma_speed_mps, 0.0, 50.0);
    RequireInRange(at + "direction_deg", kick.direction_rad * kRadToDeg, -180.0, 180.0);
    RequireInRange(at + "sigma_direction_deg", kick.sigma_direction_rad * kRadToDeg, 0.0, 180.0);
  }
}

KickModel LoadKickModel(const std::filesystem::path& file) {
  JsonDocument doc = JsonDocument::Load(file);
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"robot", "rolling_deceleration_mps2", "kicks"});
  KickModel model;
  model.robot = root.String("robot");
  model.rolling_deceleration_mps2 = root.Number("rolling_deceleration_mps2");
  for (const JsonObject& item : root.ObjectArray("kicks")) {
    item.RejectUnknownKeys(
        {"name", "speed_mps", "sigma_speed_mps", "direction_deg", "sigma_direction_deg"});
    KickSpec kick;
    kick.name = item.String("name");
    kick.speed_mps = item.Number("speed_mps");
    kick.sigma_speed_mps = item.Number("sigma_speed_mps");
    kick.direction_rad = item.Number("direction_deg") * kDegToRad;  // files say degrees
    kick.sigma_direction_rad = item.Number("sigma_direction_deg") * kDegToRad;
    model.kicks.push_back(kick);
  }
  WithFile(file.string(), [&] { model.Validate(); });
  return model;
}

}  // namespace foresight
