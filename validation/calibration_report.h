// What a calibration run writes: JSON (the contract), CSV (one row per observed kick, and one
// per fitted kick), a self-contained HTML page, and a short text for the terminal.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "models/kick_model.h"
#include "physics/motion_clearance.h"
#include "physics/trial.h"
#include "report/provenance.h"
#include "validation/calibration.h"

namespace foresight {

// The observations behind one fitted kick; `draws` (physics only) are the physical causes each
// trial drew, in the same order.
struct CalibratedKick {
  KickCalibration fit;
  std::vector<KickObservation> observations;
  std::vector<TrialDraw> draws;
  int missed = 0;  // physics trials in which the robot did not touch the ball
  int fell = 0;    // physics trials in which the robot fell (not in the fit either)
  int blocked = 0;  // physics trials whose stance was blocked (floating base; not in the fit)
  std::optional<MotionClearance> clearance;  // physics only: the motion's lowest point
};

struct CalibrationRun {
  // Inputs: "situation", "physics" (both "" for a CSV), "base_kicks", "out" (the model written).
  RunProvenance provenance;
  std::string robot;
  std::string source;       // "physics" or the CSV file
  int trials_per_kick = 0;  // physics only
  CalibrationSettings settings;
  std::optional<double> carpet_deceleration_mps2;  // physics: the carpet's truth
  int speeds_from_rest = 0;                        // CSV: speeds derived from rest positions
  KickModel base;
  KickModel fitted;
  std::vector<CalibratedKick> kicks;
  std::optional<DecelerationFit> deceleration;  // pooled over all kicks
};

// Plain statements of what does not fit (for text and HTML): an empty list means none.
std::vector<std::string> CalibrationWarnings(const CalibrationRun& run);

std::string CalibrationText(const CalibrationRun& run);
// "yes (AD p = 0.512)", "no (AD p = 0.012)" or "n/a (all values equal)" at `level`.
std::string NormalityText(const NormalityTest& test, double level);
nlohmann::ordered_json CalibrationJson(const CalibrationRun& run);
std::string CalibrationObservationsCsv(const CalibrationRun& run);
std::string CalibrationSummaryCsv(const CalibrationRun& run);

}  // namespace foresight
