// Small helpers shared by the commands' text, JSON and SVG output.
#pragma once

#include <filesystem>
#include <string>

#include "report/report_format.h"  // Format

namespace foresight {

// A data file as reports show it: relative to the models folder when inside it, so the same
// run gives the same bytes in every checkout.
std::string DisplayPath(const std::filesystem::path& file, const std::filesystem::path& models_dir);

}  // namespace foresight
