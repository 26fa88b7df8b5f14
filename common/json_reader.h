// Reading the project's JSON files with messages that name the file, the field and the value.
//
// JsonObject wraps one JSON object together with the file it came from and its path inside that
// file ("kicks[1]"), so every accessor can fail with "FILE: kicks[1].speed_mps: ...". Numbers
// are checked for finiteness where they enter; unknown keys are rejected (a typo must not
// silently fall back to a default). A top-level "notes" string is allowed everywhere for
// provenance.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/strict_json.h"

namespace foresight {

// A value as an error message quotes it: short, escaped, on one line. Strings are quoted and cut
// after 60 bytes, numbers and literals as written, objects and arrays by their size only (a
// message never embeds a whole tree: a deeply nested value would overflow the stack).
std::string QuoteJson(const nlohmann::json& value);

class JsonObject {
 public:
  JsonObject(const nlohmann::json* value, std::string file, std::string path);

  bool Has(std::string_view key) const;
  double Number(std::string_view key) const;
  double NumberOr(std::string_view key, double fallback) const;
  int Integer(std::string_view key) const;
  std::string String(std::string_view key) const;
  std::string StringOr(std::string_view key, std::string fallback) const;
  bool Bool(std::string_view key) const;                   // true or false, nothing else
  bool BoolOr(std::string_view key, bool fallback) const;  // ... or absent
  JsonObject Object(std::string_view key) const;
  std::vector<JsonObject> ObjectArray(std::string_view key) const;  // empty if the key is absent
  // Arrays of plain values; each item is checked ("FILE: PATH.key[2]: must be a number, ...").
  std::vector<std::string> StringArray(std::string_view key) const;
  std::vector<double> NumberArray(std::string_view key) const;  // finite numbers
  // The object's keys in the order nlohmann keeps them (sorted), "notes" included.
  std::vector<std::string> Keys() const;

  // Throws if the object has a key outside `known` (and "notes").
  void RejectUnknownKeys(std::initializer_list<std::string_view> known) const;
  void RejectUnknownKeys(std::span<const std::string_view> known) const;

  // "FILE: PATH.key: problem" as an InputError.
  [[noreturn]] void Fail(std::string_view key, std::string_view problem) const;

  const std::string& file() const { return file_; }
  // Path of a key below this object, e.g. "kicks[1].speed_mps".
  std::string PathOf(std::string_view key) const;

 private:
  const nlohmann::json& Get(std::string_view key) const;
  const nlohmann::json& GetArray(std::string_view key) const;

  const nlohmann::json* value_;
  std::string file_;
  std::string path_;
};

// A parsed JSON document that owns its tree; Root() is the top-level object.
class JsonDocument {
 public:
  // Reads and parses `file`; a missing file, a directory, a device or pipe, a file over
  // kMaxJsonBytes or what ParseStrictJson refuses (common/strict_json.h) is an InputError.
  static JsonDocument Load(const std::filesystem::path& file);
  // Parses text that did not come from a file; `origin` names it in messages.
  static JsonDocument Parse(std::string_view text, std::string origin);

  JsonObject Root() const;
  // The whole parsed tree (for formats read by their own code, e.g. report/shard_file.h).
  const nlohmann::json& Tree() const { return tree_; }

 private:
  nlohmann::json tree_;
  std::string origin_;
};

// Throws unless `root` has a "sources" object with a non-empty string for every key in
// `figures` (and nothing else): "FILE: sources.walk_speed_mps: ...". Every number a data file
// chooses names where it comes from, or "assumption: why".
void RequireSources(const JsonObject& root, std::initializer_list<std::string_view> figures);
void RequireSources(const JsonObject& root, std::span<const std::string_view> figures);

}  // namespace foresight
