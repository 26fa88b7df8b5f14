#include "common/json_reader.h"

#include <cmath>
#include <fstream>
#include <set>
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

// Strictness beyond the JSON grammar, checked while parsing: a bounded depth (so nothing
// downstream recurses without end), and no key twice in one object (nlohmann would keep the
// last silently, so a typo'd override would win unseen).
class StrictParse {
 public:
  explicit StrictParse(const std::string& origin) : origin_(origin) {}

  bool operator()(int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (depth > kMaxJsonDepth) {
      throw InputError(origin_ + ": invalid JSON: nested deeper than " +
                       std::to_string(kMaxJsonDepth) + " levels");
    }
    if (event == Event::object_start) keys_.emplace_back();
    if (event == Event::object_end && !keys_.empty()) keys_.pop_back();
    if (event == Event::key && !keys_.empty() &&
        !keys_.back().insert(parsed.get<std::string>()).second) {
      throw InputError(origin_ + ": invalid JSON: the key " + QuoteJson(parsed) +
                       " appears twice in one object");
    }
    return true;
  }

 private:
  const std::string& origin_;
  std::vector<std::set<std::string>> keys_;
};

}  // namespace

JsonDocument JsonDocument::Parse(std::string_view text, std::string origin) {
  JsonDocument doc;
  doc.origin_ = std::move(origin);
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    throw InputError(doc.origin_ + ": invalid JSON at " + LineAndColumn(text, nul + 1) +
                     ": a NUL byte (not a text file?)");
  }
  try {
    doc.tree_ = nlohmann::json::parse(text, StrictParse(doc.origin_));
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
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (std::filesystem::is_directory(status)) throw InputError(file.string() + ": is a directory");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw InputError(file.string() + ": is not a regular file (a device or a pipe?)");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open file");
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxJsonBytes) {
    throw InputError(file.string() + ": " + std::to_string(size) + " bytes, more than the " +
                     std::to_string(kMaxJsonBytes) + " a data file may have");
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(file.string() + ": cannot read file");
  return Parse(buffer.str(), file.string());
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
