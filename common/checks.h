// Range checks used by the Validate() functions of all parameter structs. Each throws an
// InputError "field: must be ..., got VALUE" naming the field, so the loader can prefix the file.
#pragma once

#include <string_view>

namespace foresight {

void RequireFinite(std::string_view field, double value);
void RequirePositive(std::string_view field, double value);
void RequireNonNegative(std::string_view field, double value);
void RequireInRange(std::string_view field, double value, double lo, double hi);

// Formats a double the way every message of the project does (shortest round-trip form).
std::string FormatNumber(double value);

}  // namespace foresight
