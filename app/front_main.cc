// The `foresight` executable a robot or a script calls: it runs `decide` itself and hands every
// other command to foresight-full (app/main.cc), which it replaces by exec. Why two: a process
// pays the dynamic loader for every shared library it links, about 3 ms for Bullet, assimp,
// urdfdom and theirs (docs/PERFORMANCE.md, "A process that starts fast"), and `decide` uses none
// of them; this executable links only what `decide` uses (--as-needed, app/CMakeLists.txt).
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>

#include "app/cli_main.h"
#include "app/decide_command.h"

namespace {

int RunDecideOnly(int argc, char** argv) {
  CLI::App app;
  std::string models_dir;
  foresight::AddTopLevelOptions(app, models_dir);
  foresight::DecideOptions decide;
  foresight::AddDecideCommand(app, decide);
  if (const auto parsed = foresight::ParseCommandLine(app, argc, argv)) return *parsed;
  return foresight::RunReportingErrors([&] { return foresight::RunDecide(decide, models_dir); });
}

// foresight-full beside this executable (the build tree) or where it is installed.
std::filesystem::path FullExecutable() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path dir = error ? std::filesystem::path(".") : self.parent_path();
  for (const std::filesystem::path& candidate :
       {dir / "foresight-full", dir / FORESIGHT_FULL_FROM_BIN / "foresight-full"}) {
    if (std::filesystem::exists(candidate, error)) return candidate;
  }
  return dir / "foresight-full";
}

}  // namespace

int main(int argc, char** argv) {
  if (foresight::FirstCommandWord(argc, argv) == "decide") return RunDecideOnly(argc, argv);
  const std::filesystem::path full = FullExecutable();
  execv(full.c_str(), argv);
  std::cerr << "foresight: internal error: cannot run " << full.string() << ": "
            << std::strerror(errno) << " (an incomplete install?)\n";
  return foresight::kExitInternal;
}
