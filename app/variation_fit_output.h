// What `foresight calibrate --fit-variation` prints and writes: the fitted causes as the
// trial_variation block of a robot.json, and the fit beside the observed spreads.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "validation/variation_fit.h"

namespace foresight {

// {"robot", "source", "trial_variation": {... robot.json's keys ...}, "fit": {...}}.
nlohmann::json VariationFitJson(const std::string& robot, const std::string& source,
                                const VariationFit& fit);

// A table per kick: observed, placement alone, playback alone and fitted sigma_v / sigma_alpha.
std::string VariationFitText(const VariationFit& fit);

}  // namespace foresight
