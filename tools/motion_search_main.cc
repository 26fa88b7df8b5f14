// foresight_motion_search SETTINGS.json --out DIR [--threads N] [--models DIR]
//
// Searches a kick motion's keyframes and weight shift in the project's physics
// (tools/motion_search.h), prints each round's best candidates and writes DIR/search.json (every
// candidate) and DIR/best_<rank>.json (the best `keep` candidates as motion files). DIR is a
// report folder (report/report_folder.h), checked before the search and replaced whole after it
// (no best_<rank>.json of an earlier, larger run remains; a user's own files stay). Bad input:
// one line "foresight_motion_search: error: FILE: FIELD: problem" and exit status 2, nothing
// written.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>

#include "common/error.h"
#include "models/model_paths.h"
#include "report/output_set.h"
#include "tools/motion_search.h"
#include "tools/motion_search_output.h"
#include "tools/tool_main.h"

namespace foresight {
namespace {

constexpr const char* kUsage =
    "usage: foresight_motion_search SETTINGS.json --out DIR [--threads N] [--models DIR]";

struct Arguments {
  std::filesystem::path settings, out, models;
  int threads = 0;
};

// As the foresight command: a flag's value may not be empty ('' is never "not given") and a
// flag may be given once (a second --out would silently win).
Arguments Parse(int argc, char** argv) {
  Arguments a;
  std::set<std::string> given;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw InputError(arg + ": needs a value (" + kUsage + ")");
      if (!given.insert(arg).second) throw InputError(arg + ": given twice");
      const std::string text = argv[++i];
      if (text.empty()) {
        throw InputError(arg + ": empty value (leave the flag out for its default)");
      }
      return text;
    };
    if (arg == "--out") {
      a.out = value();
    } else if (arg == "--models") {
      a.models = value();
    } else if (arg == "--threads") {
      const std::string text = value();
      char* end = nullptr;
      const long threads = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || threads < 0 || threads > 1024) {
        throw InputError("--threads: must be an integer in [0, 1024], got '" + text + "'");
      }
      a.threads = static_cast<int>(threads);
    } else if (!arg.empty() && arg[0] != '-' && a.settings.empty()) {
      a.settings = arg;
    } else {
      throw InputError("unknown argument '" + arg + "' (" + kUsage + ")");
    }
  }
  if (a.settings.empty()) throw InputError(std::string("no settings file (") + kUsage + ")");
  if (a.out.empty()) throw InputError(std::string("--out: required (") + kUsage + ")");
  return a;
}

int Run(int argc, char** argv) {
  const Arguments args = Parse(argc, argv);
  const std::filesystem::path models = args.models.empty() ? DefaultModelsDir() : args.models;
  const MotionSearchSettings settings = LoadMotionSearchSettings(args.settings, models);
  const auto setup = LoadSearchSetup(settings, models);
  OutputSet outputs;  // checked before the search, written as one commit after it
  outputs.AddInput("the settings file", args.settings);
  if (!settings.start_file.empty()) outputs.AddInput("the start motion", settings.start_file);
  outputs.AddFolder("--out", args.out);
  MotionSearchRun run;
  run.settings = &settings;
  run.setup = setup.get();
  run.threads = args.threads;
  run.round_done = [&](int round, const MotionSearchResult& result) {
    std::cout << RoundText(round, result, settings.keep) << std::flush;
  };
  const MotionSearchResult result = RunMotionSearch(run);
  // Everything is made before anything is written.
  // The motion files written keep everything but the keyframes and the shift from the start's.
  const int motion_index = *setup->robot.FindMotion(settings.kick);
  const std::filesystem::path start_file =
      !settings.start_file.empty()
          ? settings.start_file
          : setup->robot.spec.kick_motion_files[static_cast<std::size_t>(motion_index)].second;
  std::vector<ReportFile> files = {{"search.json", SearchJson(settings, result).dump(2) + "\n"}};
  for (int k = 0; k < settings.keep && k < static_cast<int>(result.best.size()); ++k) {
    const SearchCandidate& c = result.candidates[static_cast<std::size_t>(result.best[k])];
    files.push_back(
        {"best_" + std::to_string(k + 1) + ".json", MotionFileText(start_file, c.motion)});
  }
  outputs.Put("--out", files);
  outputs.Commit();
  std::cout << "wrote " << (args.out / "search.json").string() << " and " << files.size() - 1
            << " motion file(s)\n";
  return 0;
}

}  // namespace
}  // namespace foresight

int main(int argc, char** argv) {
  return foresight::ToolMain("foresight_motion_search", [&] { return foresight::Run(argc, argv); });
}
