#include "common/checks.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "common/error.h"

namespace foresight {

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

namespace {
[[noreturn]] void Fail(std::string_view field, std::string_view requirement, double value) {
  throw InputError(std::string(field) + ": must be " + std::string(requirement) + ", got " +
                   FormatNumber(value));
}
}  // namespace

void RequireFinite(std::string_view field, double value) {
  if (!std::isfinite(value)) Fail(field, "a finite number", value);
}

void RequirePositive(std::string_view field, double value) {
  RequireFinite(field, value);
  if (!(value > 0.0)) Fail(field, "> 0", value);
}

void RequireNonNegative(std::string_view field, double value) {
  RequireFinite(field, value);
  if (!(value >= 0.0)) Fail(field, ">= 0", value);
}

void RequireInRange(std::string_view field, double value, double lo, double hi) {
  RequireFinite(field, value);
  if (!(value >= lo && value <= hi)) {
    Fail(field, "in [" + FormatNumber(lo) + ", " + FormatNumber(hi) + "]", value);
  }
}

}  // namespace foresight
