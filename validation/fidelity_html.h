// The fidelity report as one HTML page with inline SVG (validation/fidelity_report.h has the run).
#pragma once

#include <string>

#include "validation/fidelity_report.h"

namespace foresight {

std::string FidelityHtml(const FidelityRun& run);

}  // namespace foresight
