// A set of situations for the fidelity comparison (models/fidelity/*.json):
//   {
//     "name": "default",
//     "rotations_deg": [-180, -150, ..., 150],   // candidate turns around the ball, every kick
//     "situations": [{"file": "situations/open_centre.json", "class": "open_field"}, ...]
//   }
// Situation files are named relative to the set file. "class" groups the aggregates (open
// field, near the opponent goal, ...).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "models/situation.h"

namespace foresight {

struct FidelityCase {
  std::string situation_class;
  std::filesystem::path file;
  std::string shown_file;  // as reports show it (DisplayPath): the same bytes in every checkout
  Situation situation;
};

struct FidelitySet {
  std::string name;
  std::filesystem::path file;
  std::vector<double> rotations_rad;
  std::vector<FidelityCase> cases;
};

// `set` is a file, or a bare name found as MODELS/fidelity/<name>.json. `overrides` apply to every
// situation (a kick model, the coarse rebounds). Only the cases of `situation_class` are kept
// when it is not empty. Throws InputError on bad input (also a class no case has).
FidelitySet LoadFidelitySet(const std::string& set, const std::filesystem::path& models_dir,
                            const SituationOverrides& overrides = {},
                            const std::string& situation_class = {});

}  // namespace foresight
