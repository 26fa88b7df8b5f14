// What `foresight experiment passing` and `experiment ablations` share: their flags (which
// trials, how kicks are executed, where to), the inputs loaded and checked from them, the
// provenance of a run, and the flags as a shard records them (--shard I/N).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "experiments/passing.h"
#include "match/kick_executor.h"
#include "report/provenance.h"
#include "report/shard_file.h"

namespace foresight {

struct PassingOptions {
  std::string params = "passing";
  std::string config;
  std::string team = "reactive";  // experiment passing only
  std::string scenarios;  // empty: all
  std::string trials;     // empty: the configuration's default
  bool mirror = false;
  bool physics = false;
  std::string physics_file;
  std::string base;  // --base, with --physics; empty: the physics file's
  std::string kicks_file;  // replaces the simulation file's kick model
  std::string goalie;      // replaces the configuration's goalie model
  std::string variants = "cbr_variants";  // experiment ablations only: the CBR team's variants
  std::string seed = "1";
  std::string threads = "0";
  std::string out_dir;
  std::string shard;  // "I/N": only that shard (app/shard_output.h); empty: the whole run
};

// --config and the flags both commands have (--shard included).
void AddPassingRunOptions(CLI::App& cmd, PassingOptions& options);

// The inputs of a run, loaded and checked, and the executor of its kicks.
struct PassingInputs {
  PassingSetup setup;
  std::unique_ptr<KickExecutor> executor;
  std::string physics_file;  // empty without --physics
  std::string robot_base;    // the kicking robot's, as played; empty without --physics
};
// `team`: "reactive", "cbr" or "both" (the ablations play both).
PassingInputs LoadPassingInputs(const PassingOptions& options, const std::string& team,
                                const std::filesystem::path& models);

// The provenance of the trials of `team` (its parameter file `team_file`).
RunProvenance PassingProvenance(const PassingOptions& options, const PassingInputs& in,
                                const std::string& team, const std::string& team_file,
                                std::uint64_t seed, const std::filesystem::path& models);

// The flags of AddPassingRunOptions that decide the results, as a shard records them, and the
// options again from a shard (with `out_dir`); each command adds and reads its own flag.
nlohmann::ordered_json PassingSettings(const PassingOptions& options);
PassingOptions PassingOptionsOf(const ShardPart& part, const std::string& out_dir);

}  // namespace foresight
