// foresight_mirror_motion --robot NAME --in FILE --name KICK --out FILE [--like FILE] [--models DIR]
//
// Writes the mirror image of the kick motion in --in (tools/motion_mirror.h) as kick KICK: the
// kick with the other foot. The file written takes its notes and layout from --like (default:
// --in), every figure of the motion from the mirror; --out may be the --like file itself (how
// the shipped side_kick_right.json is remade from side_kick_left.json). Both motions are checked
// against the robot as its shipped ones are. Bad input: one line "foresight_mirror_motion:
// problem" and exit status 2, nothing written.
#include <filesystem>
#include <iostream>
#include <string>

#include "common/error.h"
#include "common/input_log.h"
#include "models/model_paths.h"
#include "report/output_set.h"
#include "tools/motion_mirror.h"
#include "tools/motion_search_output.h"
#include "tools/tool_main.h"

namespace foresight {
namespace {

constexpr const char* kUsage =
    "usage: foresight_mirror_motion --robot NAME --in FILE --name KICK --out FILE [--like FILE] "
    "[--models DIR]";

struct Arguments {
  std::string robot, name;
  std::filesystem::path in, out, like, models;
};

Arguments Parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) throw InputError("unknown argument or no value: '" + arg + "' (" + kUsage + ")");
    const std::string value = argv[++i];
    if (arg == "--robot") a.robot = value;
    else if (arg == "--name") a.name = value;
    else if (arg == "--in") a.in = value;
    else if (arg == "--out") a.out = value;
    else if (arg == "--like") a.like = value;
    else if (arg == "--models") a.models = value;
    else throw InputError("unknown argument '" + arg + "' (" + kUsage + ")");
  }
  for (const auto& [flag, given] : {std::pair{"--robot", !a.robot.empty()},
                                    std::pair{"--name", !a.name.empty()},
                                    std::pair{"--in", !a.in.empty()},
                                    std::pair{"--out", !a.out.empty()}}) {
    if (!given) throw InputError(std::string(flag) + ": required (" + kUsage + ")");
  }
  if (a.like.empty()) a.like = a.in;
  return a;
}

int Run(int argc, char** argv) {
  const Arguments args = Parse(argc, argv);
  const std::filesystem::path models = args.models.empty() ? DefaultModelsDir() : args.models;
  InputLog::Allow(args.like);  // --out may be the --like file (which the robot reads too)
  const Robot robot = LoadRobot(args.robot, models);
  OutputSet outputs;  // checked before anything is made
  outputs.AddInput("--in", args.in);
  outputs.AddFile("--out", args.out);
  const KickMotion source = LoadKickMotion(args.in);
  LoadKickMotion(args.like);  // the template must be a motion file too
  const KickMotion mirrored = MirrorMotion(robot, source, args.name);
  // The mirror must pass the checks a shipped motion passes (limits, speeds, the weight shift).
  CheckRobotKickMotion(robot, mirrored, "the mirror of " + args.in.string());
  const std::string text = MotionFileText(args.like, mirrored);
  outputs.Put("--out", text);
  outputs.Commit();
  std::cout << "wrote " << args.out.string() << " (" << args.name << ", the mirror of "
            << source.name << ")\n";
  return 0;
}

}  // namespace
}  // namespace foresight

int main(int argc, char** argv) {
  return foresight::ToolMain("foresight_mirror_motion", [&] { return foresight::Run(argc, argv); });
}
