#include "validation/fidelity_set.h"

#include <cmath>

#include "common/error.h"
#include "common/geometry.h"
#include "common/json_reader.h"
#include "models/model_paths.h"

namespace foresight {

namespace {

std::filesystem::path SetFile(const std::string& set, const std::filesystem::path& models_dir) {
  if (set.size() > 5 && set.ends_with(".json")) return set;
  return DataFile(models_dir, DataFolder::kFidelity, set);
}

}  // namespace

namespace {

void KeepClass(const std::string& situation_class, FidelitySet& set) {
  std::vector<FidelityCase> kept;
  std::string classes;
  for (FidelityCase& c : set.cases) {
    if (classes.find("'" + c.situation_class + "'") == std::string::npos) {
      classes += (classes.empty() ? "'" : ", '") + c.situation_class + "'";
    }
    if (c.situation_class == situation_class) kept.push_back(std::move(c));
  }
  if (kept.empty()) {
    throw InputError("--class: no situation of class '" + situation_class + "' in " +
                     set.file.string() + " (classes: " + classes + ")");
  }
  set.cases = std::move(kept);
}

}  // namespace

FidelitySet LoadFidelitySet(const std::string& set, const std::filesystem::path& models_dir,
                            const SituationOverrides& overrides,
                            const std::string& situation_class) {
  FidelitySet result;
  result.file = SetFile(set, models_dir);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(result.file, ec)) {
    throw InputError("--situations: " + result.file.string() + " does not exist");
  }
  JsonDocument doc = JsonDocument::Load(result.file);
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"name", "rotations_deg", "situations"});
  result.name = root.StringOr("name", result.file.stem().string());
  for (double deg : root.NumberArray("rotations_deg")) {
    if (deg < -180.0 || deg > 180.0) {
      root.Fail("rotations_deg", "must lie in [-180, 180], got " + std::to_string(deg));
    }
    for (double earlier : result.rotations_rad) {
      if (std::abs(WrapAngle(earlier - deg * kDegToRad)) < 1e-9) {
        root.Fail("rotations_deg", "lists the turn " + std::to_string(deg) + " deg twice");
      }
    }
    result.rotations_rad.push_back(deg * kDegToRad);
  }
  if (result.rotations_rad.empty()) root.Fail("rotations_deg", "must list at least one rotation");
  for (const JsonObject& item : root.ObjectArray("situations")) {
    item.RejectUnknownKeys({"file", "class"});
    FidelityCase c;
    c.situation_class = item.String("class");
    c.file = result.file.parent_path() / item.String("file");
    if (!std::filesystem::is_regular_file(c.file, ec)) {
      item.Fail("file", "refers to " + c.file.string() + ", which does not exist");
    }
    c.shown_file = DisplayPath(c.file, models_dir);
    c.situation = LoadSituation(c.file, models_dir, overrides);
    result.cases.push_back(std::move(c));
  }
  if (result.cases.empty()) root.Fail("situations", "must list at least one situation");
  if (!situation_class.empty()) KeepClass(situation_class, result);
  return result;
}

}  // namespace foresight
