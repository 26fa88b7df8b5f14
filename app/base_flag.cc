#include "app/base_flag.h"

#include <algorithm>

#include "common/error.h"
#include "report/provenance.h"

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
  std::vector<std::filesystem::path> read;  // each file once: a run of many situations repeats it
  std::vector<std::string> bases;
  for (const std::filesystem::path& file : physics_files) {
    if (std::ranges::find(read, file) != read.end()) continue;
    read.push_back(file);
    bases.emplace_back(RobotBaseName(LoadPhysicsParams(file).robot.base));
  }
  return JoinDistinct(bases);
}

void AddBaseOption(CLI::App& command, std::string& text) {
  command.add_option("--base", text,
                     "The kicking robot's base: fixed (bolted, the fast approximation) or floating "
                     "(standing on its feet); default: the physics file's robot.base");
}

}  // namespace foresight
