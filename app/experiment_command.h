// `foresight experiment stability|strategies|passing`: the first paper's two experiments
// (Mellmann & Schlotter, sec. V) and the second paper's passing trials (Ros et al. 2009, sec.
// 5.2), each writing JSON, CSV and SVG figures to a folder.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "report/shard_file.h"

namespace foresight {

struct StabilityOptions {
  std::string params;  // empty: "stability" (or "stability_quick" with --quick)
  bool quick = false;
  std::string kicks_file;
  std::string strategy;  // empty: the params file's
  std::string repeats;   // empty: the params file's
  std::string samples;   // empty: the params file's; "1-25,30-110/10" style
  std::string seed = "1";
  std::string threads = "0";
  std::string out_dir;
  std::string shard;  // "I/N": only that shard (app/shard_output.h); empty: the whole run
};

struct StrategiesOptions {
  std::string params = "strategies";
  std::string kicks_file;
  std::string starts;  // empty: the params file's
  bool physics = false;
  std::string physics_file;
  std::string coarse_rebounds;  // "on", "off" or empty (the evaluation file's)
  std::string seed = "1";
  std::string threads = "0";
  std::string out_dir;
  std::string shard;  // "I/N": only that shard (app/shard_output.h); empty: the whole run
};

struct PassingOptions {
  std::string params = "passing";
  std::string config;
  std::string team = "reactive";
  std::string scenarios;  // empty: all
  std::string trials;     // empty: the configuration's default
  bool mirror = false;
  bool physics = false;
  std::string physics_file;
  std::string kicks_file;  // replaces the simulation file's kick model
  std::string variants = "cbr_variants";  // experiment ablations: the CBR team's variants
  std::string seed = "1";
  std::string threads = "0";
  std::string out_dir;
};

struct ExperimentOptions {
  StabilityOptions stability;
  StrategiesOptions strategies;
  PassingOptions passing;
  PassingOptions ablations;  // the same inputs; the team is always the reactive one and the CBR variants
};

void AddExperimentCommand(CLI::App& app, ExperimentOptions& options);
// Runs the experiment subcommand that was given; 0 on success.
int RunExperimentCommand(const CLI::App& app, const ExperimentOptions& options,
                         const std::string& models_dir);

// `foresight merge` of the shards of `experiment stability` or `experiment strategies` into the
// report folder `out_dir`: the same files as the unsharded run.
bool IsExperimentShardCommand(const std::string& command);
int MergeExperimentShards(const std::vector<ShardPart>& parts, const std::string& out_dir,
                          const std::filesystem::path& models);

}  // namespace foresight
