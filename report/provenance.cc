#include "report/provenance.h"

#include <algorithm>

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
