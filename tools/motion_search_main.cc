// foresight_motion_search SETTINGS.json --out DIR [--threads N] [--models DIR]
//
// Searches a kick motion's keyframes and weight shift in the project's physics
// (tools/motion_search.h), prints each round's best candidates and writes DIR/search.json (every
// candidate) and DIR/best_<rank>.json (the best `keep` candidates as motion files). Bad input:
// one line "foresight_motion_search: FILE: FIELD: problem" and exit status 2, nothing written.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include "common/error.h"
#include "models/model_paths.h"
#include "report/atomic_file.h"
#include "tools/motion_search.h"
#include "tools/motion_search_output.h"

namespace foresight {
namespace {

constexpr const char* kUsage =
    "usage: foresight_motion_search SETTINGS.json --out DIR [--threads N] [--models DIR]";

struct Arguments {
  std::filesystem::path settings, out, models;
  int threads = 0;
};

Arguments Parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw InputError(arg + ": needs a value (" + kUsage + ")");
      return argv[++i];
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
  if (std::filesystem::exists(args.out) && !std::filesystem::is_directory(args.out)) {
    throw InputError("--out: '" + args.out.string() + "' is not a directory");
  }
  MotionSearchRun run;
  run.settings = &settings;
  run.setup = setup.get();
  run.threads = args.threads;
  run.round_done = [&](int round, const MotionSearchResult& result) {
    std::cout << RoundText(round, result, settings.keep) << std::flush;
  };
  const MotionSearchResult result = RunMotionSearch(run);
  // Everything is made before anything is written.
  const int motion_index = *setup->robot.FindMotion(settings.kick);
  const std::filesystem::path start_file =
      setup->robot.spec.kick_motion_files[static_cast<std::size_t>(motion_index)].second;
  std::vector<std::string> motion_files;
  for (int k = 0; k < settings.keep && k < static_cast<int>(result.best.size()); ++k) {
    const SearchCandidate& c = result.candidates[static_cast<std::size_t>(result.best[k])];
    motion_files.push_back(MotionFileText(start_file, c.motion));
  }
  const std::string search = SearchJson(settings, result).dump(2) + "\n";
  std::filesystem::create_directories(args.out);
  WriteFileAtomically(args.out / "search.json", search);
  for (std::size_t k = 0; k < motion_files.size(); ++k) {
    WriteFileAtomically(args.out / ("best_" + std::to_string(k + 1) + ".json"), motion_files[k]);
  }
  std::cout << "wrote " << (args.out / "search.json").string() << " and " << motion_files.size()
            << " motion file(s)\n";
  return 0;
}

}  // namespace
}  // namespace foresight

int main(int argc, char** argv) {
  try {
    return foresight::Run(argc, argv);
  } catch (const foresight::InputError& e) {
    std::cerr << "foresight_motion_search: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "foresight_motion_search: " << e.what() << "\n";
    return 2;
  }
}
