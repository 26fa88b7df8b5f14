#include "common/json_reader.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/checks.h"
#include "common/error.h"

namespace foresight {

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
  if (!v.is_number()) Fail(key, "must be a number, got " + v.dump());
  double number = v.get<double>();
  if (!std::isfinite(number)) Fail(key, "must be finite, got " + FormatNumber(number));
  return number;
}

double JsonObject::NumberOr(std::string_view key, double fallback) const {
  return Has(key) ? Number(key) : fallback;
}

int JsonObject::Integer(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_number_integer()) Fail(key, "must be an integer, got " + v.dump());
  auto number = v.get<long long>();
  if (number < -(1LL << 31) || number >= (1LL << 31)) Fail(key, "out of range: " + v.dump());
  return static_cast<int>(number);
}

std::string JsonObject::String(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_string()) Fail(key, "must be a string, got " + v.dump());
  return v.get<std::string>();
}

std::string JsonObject::StringOr(std::string_view key, std::string fallback) const {
  return Has(key) ? String(key) : fallback;
}

JsonObject JsonObject::Object(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_object()) Fail(key, "must be a JSON object, got " + v.dump());
  return JsonObject(&v, file_, PathOf(key));
}

std::vector<JsonObject> JsonObject::ObjectArray(std::string_view key) const {
  std::vector<JsonObject> items;
  if (!Has(key)) return items;
  const nlohmann::json& v = Get(key);
  if (!v.is_array()) Fail(key, "must be an array, got " + v.dump());
  for (std::size_t i = 0; i < v.size(); ++i) {
    std::string item_path = PathOf(key) + "[" + std::to_string(i) + "]";
    if (!v[i].is_object()) {
      throw InputError(file_ + ": " + item_path + ": must be a JSON object, got " + v[i].dump());
    }
    items.emplace_back(&v[i], file_, item_path);
  }
  return items;
}

const nlohmann::json& JsonObject::GetArray(std::string_view key) const {
  const nlohmann::json& v = Get(key);
  if (!v.is_array()) Fail(key, "must be an array, got " + v.dump());
  return v;
}

std::vector<std::string> JsonObject::StringArray(std::string_view key) const {
  const nlohmann::json& v = GetArray(key);
  std::vector<std::string> items;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string item_key = std::string(key) + "[" + std::to_string(i) + "]";
    if (!v[i].is_string()) Fail(item_key, "must be a string, got " + v[i].dump());
    items.push_back(v[i].get<std::string>());
  }
  return items;
}

std::vector<double> JsonObject::NumberArray(std::string_view key) const {
  const nlohmann::json& v = GetArray(key);
  std::vector<double> items;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string item_key = std::string(key) + "[" + std::to_string(i) + "]";
    if (!v[i].is_number()) Fail(item_key, "must be a number, got " + v[i].dump());
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
  for (const auto& [key, unused] : value_->items()) {
    if (key == "notes") continue;
    bool is_known = false;
    for (std::string_view k : known) is_known = is_known || key == k;
    if (!is_known) Fail(key, "unknown field");
  }
}

namespace {

// nlohmann reports a byte offset; people want line and column.
std::string LineAndColumn(std::string_view text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// ", field \"x_m\"" when the text just before `at` is `"x_m":`, else "".
std::string KeyBefore(std::string_view text, std::size_t at) {
  const auto colon = text.rfind(':', at);
  if (colon == std::string_view::npos) return "";
  const auto close = text.rfind('"', colon);
  if (close == std::string_view::npos || close == 0) return "";
  const auto open = text.rfind('"', close - 1);
  if (open == std::string_view::npos) return "";
  return ", field \"" + std::string(text.substr(open + 1, close - open - 1)) + "\"";
}

// "syntax error while parsing value - invalid literal; last read: 'x'" without the prefix.
std::string ParseProblem(const nlohmann::json::parse_error& e) {
  std::string what = e.what();
  auto colon = what.find(": ", what.find("parse error"));
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

}  // namespace

JsonDocument JsonDocument::Parse(std::string_view text, std::string origin) {
  JsonDocument doc;
  doc.origin_ = std::move(origin);
  try {
    doc.tree_ = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(doc.origin_ + ": invalid JSON at " + LineAndColumn(text, e.byte) + ": " +
                     ParseProblem(e));
  } catch (const nlohmann::json::exception& e) {
    // e.g. out_of_range.406 "number overflow parsing '1e999'": locate the quoted token.
    std::string what = e.what();
    const auto bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    std::string where;
    const auto open = what.find('\''), close = what.rfind('\'');
    if (open != std::string::npos && close > open) {
      const auto at = text.find(what.substr(open + 1, close - open - 1));
      if (at != std::string_view::npos)
        where = " at " + LineAndColumn(text, at + 2) + KeyBefore(text, at);
    }
    throw InputError(doc.origin_ + ": invalid JSON" + where + ": " + what);
  }
  return doc;
}

JsonDocument JsonDocument::Load(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(file.string() + ": cannot read file");
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw InputError(file.string() + ": is a directory");
  return Parse(buffer.str(), file.string());
}

JsonObject JsonDocument::Root() const {
  return JsonObject(&tree_, origin_, "");
}

}  // namespace foresight
