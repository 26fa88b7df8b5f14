#include "report/json_text.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "common/checks.h"
#include "report/report_format.h"

namespace foresight {

namespace {

void RequireFinite(double value, std::string_view what) {
  if (!std::isfinite(value)) {
    throw std::domain_error("JSON cannot hold " + FormatNumber(value) + " (" + std::string(what) +
                            ")");
  }
}

}  // namespace

std::string JsonString(std::string_view text) {
  return nlohmann::json(std::string(text))
      .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string JsonNumber(double value, std::string_view what) {
  RequireFinite(value, what);
  return FormatNumber(value);
}

std::string JsonFixed(double value, int decimals, std::string_view what) {
  RequireFinite(value, what);
  return Fixed(value, decimals);
}

long long JsonRounded(double value, std::string_view what) {
  RequireFinite(value, what);
  // 2^63: the first double beyond a long long.
  if (std::abs(value) >= 9223372036854775808.0) {
    throw std::domain_error("JSON integer out of range: " + FormatNumber(value) + " (" +
                            std::string(what) + ")");
  }
  return std::llround(value);
}

std::string ScriptSafeJson(std::string json) {
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at + 3)) {
    json.replace(at, 2, "<\\/");
  }
  return json;
}

}  // namespace foresight
