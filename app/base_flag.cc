#include "app/base_flag.h"

#include <algorithm>

#include "common/error.h"

namespace foresight {

std::optional<RobotBase> ParseBaseFlag(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const std::optional<RobotBase> base = ParseRobotBase(text);
  if (!base) {
    throw InputError("--base: must be one of " + RobotBaseList() + ", got '" + text + "'");
  }
  return base;
}

std::string BaseUsed(const std::optional<RobotBase>& flag,
                     const std::vector<std::filesystem::path>& physics_files) {
  if (flag) return std::string(RobotBaseName(*flag));
  std::vector<RobotBase> bases;
  for (const std::filesystem::path& file : physics_files) {
    const RobotBase base = LoadPhysicsParams(file).robot.base;
    if (std::find(bases.begin(), bases.end(), base) == bases.end()) bases.push_back(base);
  }
  std::sort(bases.begin(), bases.end());
  std::string used;
  for (RobotBase base : bases)
    used += (used.empty() ? "" : ", ") + std::string(RobotBaseName(base));
  return used;
}

void AddBaseOption(CLI::App& command, std::string& text) {
  command.add_option("--base", text,
                     "The kicking robot's base: fixed (bolted, the fast approximation) or floating "
                     "(standing on its feet); default: the physics file's robot.base");
}

}  // namespace foresight
