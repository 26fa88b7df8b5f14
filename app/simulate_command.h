// `foresight simulate`: physics trials of one kick from a situation file.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <string>

#include "physics/physics_runs.h"
#include "physics/physics_setup.h"

namespace foresight {

struct SimulateOptions {
  std::string situation_file;
  std::string kick;
  std::string kicks_file;    // replaces the situation's kick model when given
  std::string physics_file;  // default: MODELS/physics/<field>.json
  std::string base;          // --base; empty: the physics file's
  std::string variation_file;  // --variation: replaces robot.json's trial_variation
  std::string trials = "100";
  std::string seed = "1";
  std::string threads = "0";  // 0: all cores
  std::string rotation_deg = "0";
  bool json = false;
  std::string svg_file;
  std::string trace_file;
  std::string view_file;          // --view: the 3D viewer page
  std::string view_rate_hz;  // --view-rate: its frames per simulated second (empty: 100)
};

void AddSimulateCommand(CLI::App& app, SimulateOptions& options);

// Runs the command; bad input throws InputError. Returns the exit code.
int RunSimulate(const SimulateOptions& options, const std::string& models_dir);

// The command's trials before they run: the physics set-up and the request, every flag checked
// (the Python module's simulate runs them the same way).
struct SimulationPlan {
  std::unique_ptr<PhysicsSetup> setup;
  KickTrialsRequest request;
};
SimulationPlan PlanSimulation(const SimulateOptions& options, const std::filesystem::path& models);

}  // namespace foresight
