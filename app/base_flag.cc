#include "app/base_flag.h"

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

void AddBaseOption(CLI::App& command, std::string& text) {
  command.add_option("--base", text,
                     "The kicking robot's base: fixed (bolted, the fast approximation) or floating "
                     "(standing on its feet); default: the physics file's robot.base");
}

}  // namespace foresight
