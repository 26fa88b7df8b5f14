#include "common/json_reader.h"

#include "common/data_file.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/checks.h"
#include "common/error.h"

namespace foresight {

std::string QuoteJson(const nlohmann::json& value) {
  constexpr std::size_t kMaxChars = 60;
  const auto escaped = [](const nlohmann::json& v) {
    return v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  if (value.is_object()) return "an object with " + std::to_string(value.size()) + " keys";
  if (value.is_array()) return "an array of " + std::to_string(value.size()) + " items";
  if (!value.is_string()) return escaped(value);
  const std::string& text = value.get_ref<const std::string&>();
  if (text.size() <= kMaxChars) return escaped(value);
  return escaped(nlohmann::json(text.substr(0, kMaxChars))) + "... (" +
         std::to_string(text.size()) + " bytes)";
}

JsonObject::JsonObject(const nlohmann::json* value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(std::move(path)) {
  if (!value_->is_object()) {
    throw InputError(file_ + ": " + (path_.empty() ? std::string("top level") : path_) +
                     ": must be a JSON object");
  }
}

std::string JsonObject::PathOf(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void JsonObject::Fail(std::string_view key, std::string_view problem) const {
  throw InputError(file_ + ": " + PathOf(key) + ": " + std::string(problem));
}

bool JsonObject::Has(std::string_view key) const {
  return value_->contains(key);
}

const nlohmann::json& JsonObject::Get(std::string_view key) const {
  auto it = value_->find(key);
  if (it == value_->end()) Fail(key, "missing");
  return *it;
}

double JsonObject::Number(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_number()) Fail(key, "must be a number, got " + QuoteJson(v));
  double number = v.get<double>();
  if (!std::isfinite(number)) Fail(key, "must be finite, got " + FormatNumber(number));
  return number;
}

double JsonObject::NumberOr(std::string_view key, double fallback) const {
  return Has(key) ? Number(key) : fallback;
}

int JsonObject::Integer(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_number_integer()) Fail(key, "must be an integer, got " + QuoteJson(v));
  auto number = v.get<long long>();
  if (number < -(1LL << 31) || number >= (1LL << 31)) Fail(key, "out of range: " + QuoteJson(v));
  return static_cast<int>(number);
}

std::string JsonObject::String(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_string()) Fail(key, "must be a string, got " + QuoteJson(v));
  return v.get<std::string>();
}

std::string JsonObject::StringOr(std::string_view key, std::string fallback) const {
  return Has(key) ? String(key) : fallback;
}

bool JsonObject::Bool(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_boolean()) Fail(key, "must be true or false, got " + QuoteJson(v));
  return v.get<bool>();
}

bool JsonObject::BoolOr(std::string_view key, bool fallback) const {
  if (!Has(key)) return fallback;
  const nlohmann::json& v = Get(key);
  if (!v.is_boolean()) Fail(key, "must be true or false, got " + QuoteJson(v));
  return v.get<bool>();
}

JsonObject JsonObject::Object(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_object()) Fail(key, "must be a JSON object, got " + QuoteJson(v));
  return JsonObject(&v, file_, PathOf(key));
}

std::vector<JsonObject> JsonObject::ObjectArray(std::string_view key) const {
  std::vector<JsonObject> items;
  if (!Has(key)) return items;
  const nlohmann::json& v = Get(key);
  if (!v.is_array()) Fail(key, "must be an array, got " + QuoteJson(v));
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::string item_path = PathOf(key) + "[" + std::to_string(i) + "]";
    if (!v[i].is_object()) {
      throw InputError(file_ + ": " + item_path + ": must be a JSON object, got " +
                       QuoteJson(v[i]));
    }
    items.emplace_back(&v[i], file_, item_path);
  }
  return items;
}

const nlohmann::json& JsonObject::GetArray(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_array()) Fail(key, "must be an array, got " + QuoteJson(v));
  return v;
}

std::vector<std::string> JsonObject::StringArray(std::string_view key) const {
  const nlohmann::json& v = GetArray(key);
  std::vector<std::string> items;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string item_key = std::string(key) + "[" + std::to_string(i) + "]";
    if (!v[i].is_string()) Fail(item_key, "must be a string, got " + QuoteJson(v[i]));
    items.push_back(v[i].get<std::string>());
  }
  return items;
}

std::vector<double> JsonObject::NumberArray(std::string_view key) const {
  const nlohmann::json& v = GetArray(key);
  std::vector<double> items;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string item_key = std::string(key) + "[" + std::to_string(i) + "]";
    if (!v[i].is_number()) Fail(item_key, "must be a number, got " + QuoteJson(v[i]));
    const double number = v[i].get<double>();
    if (!std::isfinite(number)) Fail(item_key, "must be finite, got " + FormatNumber(number));
    items.push_back(number);
  }
  return items;
}

std::vector<std::string> JsonObject::Keys() const {
  std::vector<std::string> keys;
  for (const auto& [key, unused] : value_->items()) keys.push_back(key);
  return keys;
}

void JsonObject::RejectUnknownKeys(std::initializer_list<std::string_view> known) const {
  RejectUnknownKeys(std::span<const std::string_view>(known.begin(), known.size()));
}

void JsonObject::RejectUnknownKeys(std::span<const std::string_view> known) const {
  for (const auto& [key, unused] : value_->items()) {
    if (key == "notes") continue;
    bool is_known = false;
    for (std::string_view k : known) is_known = is_known || key == k;
    if (!is_known) Fail(key, "unknown field");
  }
}

JsonDocument JsonDocument::Parse(std::string_view text, std::string origin) {
  JsonDocument doc;
  doc.origin_ = std::move(origin);
  doc.tree_ = ParseStrictJson(text, doc.origin_);
  return doc;
}

JsonDocument JsonDocument::Load(const std::filesystem::path& file) {
  return Parse(ReadDataFile(file, kMaxJsonBytes), file.string());
}

JsonObject JsonDocument::Root() const {
  return JsonObject(&tree_, origin_, "");
}

void RequireSources(const JsonObject& root, std::initializer_list<std::string_view> figures) {
  RequireSources(root, std::span<const std::string_view>(figures.begin(), figures.size()));
}

void RequireSources(const JsonObject& root, std::span<const std::string_view> figures) {
  const JsonObject sources = root.Object("sources");
  sources.RejectUnknownKeys(figures);
  for (std::string_view figure : figures) {
    if (!sources.Has(figure)) sources.Fail(figure, "missing: every figure needs a source");
    if (sources.String(figure).empty()) sources.Fail(figure, "must not be empty");
  }
}

}  // namespace foresight
