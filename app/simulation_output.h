// What `foresight simulate` shows of a physics run: a text summary, JSON (the contract: one
// record per trial plus the summary), an SVG of the rest positions and a CSV of trajectories.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "models/robot_spec.h"
#include "models/situation.h"
#include "physics/physics_runs.h"

namespace foresight {

struct SimulationRun {
  std::filesystem::path situation_file;
  const Situation* situation = nullptr;
  const Robot* robot = nullptr;
  std::filesystem::path physics_file;
  std::filesystem::path variation_file;  // --variation; empty: robot.json's trial_variation
  RobotBase base = RobotBase::kFixed;
  std::filesystem::path models_dir;
  std::string kick;
  double rotation_rad = 0.0;
  std::uint64_t seed = 0;
  DrawnState state;
  std::vector<TrialResult> results;
  TrialSummary summary;
};

std::string SimulationText(const SimulationRun& run);
nlohmann::ordered_json SimulationJson(const SimulationRun& run);
std::string SimulationSvg(const SimulationRun& run);
// Columns: trial, t_s, x_m, y_m, z_m, vx_mps, vy_mps, vz_mps (F frame, time since the motion
// started).
std::string SimulationTraceCsv(const SimulationRun& run);
// The 3D viewer page of every trial (their scenes must have been recorded).
std::string SimulationViewHtml(const SimulationRun& run);

}  // namespace foresight
