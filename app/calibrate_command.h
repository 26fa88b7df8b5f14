// `foresight calibrate`: fits a robot's kick noise model from physics trials (or from a CSV of
// real kicks) and writes it as a kick-model file the planner reads.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli_values.h"
#include "common/checks.h"
#include "report/output_set.h"
#include "report/shard_file.h"
#include "validation/calibration.h"
#include "validation/calibration_report.h"

namespace foresight {

inline constexpr char kDefaultFitTrials[] = "400";

struct CalibrateOptions {
  std::string robot;
  std::string kick;  // one kick, or --all
  bool all = false;
  std::string trials = "1000";
  std::string seed = std::to_string(CalibrationSettings{}.seed);
  std::string threads = "0";
  std::string out_file;
  std::string report_dir;
  std::string situation_file;  // default: MODELS/calibration/<robot>.json
  std::string kicks_file;      // the committed model to start from (default: the situation's)
  std::string physics_file;
  std::string base;  // --base: empty, the physics file's
  std::string variation_file;  // --variation: replaces robot.json's trial_variation
  std::string from_csv;
  bool fit_variation = false;     // with from_csv: fit the physical causes, not the kick model
  // Physics trials per kick and run of that fit; empty: not given (kDefaultFitTrials).
  std::string fit_trials;
  // The defaults of the fit are CalibrationSettings' (shown by --help).
  // The settings struct's default in the shortest form that reads back to it ("0.95").
  std::string confidence = FormatNumber(CalibrationSettings{}.confidence);
  std::string resamples = std::to_string(CalibrationSettings{}.resamples);
  std::string shard;  // "I/N": only that shard, --out is then its folder (app/shard_output.h)
};

void AddCalibrateCommand(CLI::App& app, CalibrateOptions& options);
int RunCalibrate(const CalibrateOptions& options, const std::string& models_dir);

// The calibration (physics or --from-csv) and its fit, without writing anything (the Python
// module's calibrate); options.out_file and report_dir may be empty.
CalibrationRun CalibrateInMemory(const CalibrateOptions& options,
                                 const std::filesystem::path& models,
                                 const std::vector<ShardPart>* parts = nullptr);

// `foresight merge` of a sharded physics calibration into `out_dir`: what
// `calibrate --report DIR --out DIR/ROBOT_calibrated.json` writes.
int MergeCalibrationCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                            const std::string& out_dir, const std::filesystem::path& models);

}  // namespace foresight
