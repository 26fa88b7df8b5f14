// The calibration report as one HTML page (validation/calibration_report.h has the run).
#pragma once

#include <string>

#include "validation/calibration_report.h"

namespace foresight {

std::string CalibrationHtml(const CalibrationRun& run);

}  // namespace foresight
