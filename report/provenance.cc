#include "report/provenance.h"

#include <algorithm>
#include <cstdio>

#include "common/data_file.h"
#include "common/error.h"
#include "report/report_format.h"

namespace foresight {

void RunProvenance::SetInput(std::string_view key, std::string value) {
  const auto it = std::ranges::find(inputs, key, &RunInput::key);
  if (it != inputs.end()) {
    it->value = std::move(value);
  } else {
    inputs.push_back({std::string(key), std::move(value)});
  }
}

const std::string& RunProvenance::Input(std::string_view key) const {
  static const std::string kNone;
  const auto it = std::ranges::find(inputs, key, &RunInput::key);
  return it != inputs.end() ? it->value : kNone;
}

std::string ContentHash(const std::filesystem::path& file) {
  if (file.empty()) return "";
  // Read as every reader reads (a FIFO or a device is refused, never blocks; 16 MiB at most).
  std::uint64_t hash = 14695981039346656037ULL;  // FNV-1a 64-bit offset basis
  for (const char c : ReadDataFile(file)) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;  // FNV-1a 64-bit prime
  }
  char text[32];
  std::snprintf(text, sizeof text, "fnv1a64:%016llx", static_cast<unsigned long long>(hash));
  return text;
}

std::string JoinDistinct(const std::vector<std::string>& values) {
  std::vector<std::string> seen;
  std::string joined;
  for (const std::string& v : values) {
    if (std::ranges::find(seen, v) != seen.end()) continue;
    seen.push_back(v);
    joined += (joined.empty() ? "" : ", ") + v;
  }
  return joined;
}

void AddInputsJson(nlohmann::ordered_json& json, const RunProvenance& provenance) {
  for (const RunInput& input : provenance.inputs) json[input.key] = input.value;
}

nlohmann::ordered_json InputsJson(const RunProvenance& provenance) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  AddInputsJson(json, provenance);
  return json;
}

std::vector<std::pair<std::string, std::string>> ProvenanceRows(const RunProvenance& provenance) {
  return {{"version", provenance.version}, {"run time", Fixed(provenance.run_time_s, 1) + " s"}};
}

}  // namespace foresight
