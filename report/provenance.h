// Where a report's numbers came from: the program's version, the seed, what the run read and how
// long it took. Every report carries one RunProvenance; the writers below put its pieces into the
// JSON and the HTML header. The reports' key orders differ and the JSON is a contract, so each
// report places the pieces itself (inputs together, in the order they were added).
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace foresight {

// One thing the run read, as displayed: a data file (relative to the models folder when inside
// it, so the same run gives the same bytes in every checkout) or a name; `key` is its JSON key.
struct RunInput {
  std::string key;
  std::string value;
};

struct RunProvenance {
  std::string version;
  std::uint64_t seed = 0;
  double run_time_s = 0.0;
  std::vector<RunInput> inputs;  // in the report's order

  // Replaces the input `key`, or appends it when there is none yet.
  void SetInput(std::string_view key, std::string value);
  // The input's value; "" when the run has no such input.
  const std::string& Input(std::string_view key) const;
};

// The file's bytes as "fnv1a64:" and 16 hex digits (FNV-1a, 64 bit): which version of a data
// file a report used, beside its path. Not a security hash. An empty path (data that came from
// memory, not a file) gives ""; a file that cannot be read throws InputError.
std::string ContentHash(const std::filesystem::path& file);

// The distinct values in order of first appearance, joined with ", " (the files a run of several
// situations read).
std::string JoinDistinct(const std::vector<std::string>& values);

// Appends every input to the JSON object `json` as "key": value, in order.
void AddInputsJson(nlohmann::ordered_json& json, const RunProvenance& provenance);
// The inputs as a JSON object of their own.
nlohmann::ordered_json InputsJson(const RunProvenance& provenance);

// The last rows of an HTML report's key-value header: "version" and "run time" (in s, 1 decimal).
std::vector<std::pair<std::string, std::string>> ProvenanceRows(const RunProvenance& provenance);

}  // namespace foresight
