#include "report/shard_file.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "common/checks.h"
#include "common/data_file.h"
#include "common/error.h"
#include "common/json_reader.h"

namespace foresight {

namespace {

std::string ReadShardText(const std::filesystem::path& dir, const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(dir.string() + ": no such shard folder (the --out of a run with --shard)");
  }
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError(dir.string() + ": no " + std::string(kShardFileName) +
                     " (not the --out of a run with --shard)");
  }
  return ReadDataFile(file, kMaxShardBytes);
}

ShardPart ParsePart(const std::filesystem::path& dir) {
  ShardPart part;
  part.file = dir / kShardFileName;
  const JsonDocument doc = JsonDocument::Parse(ReadShardText(dir, part.file), part.file.string());
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"foresight_shard", "command", "foresight_version", "shard", "items",
                          "run_time_s", "settings", "results"});
  if (root.Integer("foresight_shard") != kShardFormat) {
    root.Fail("foresight_shard", "format " + std::to_string(root.Integer("foresight_shard")) +
                                     " is not this foresight's (" + std::to_string(kShardFormat) +
                                     "); run the shard again with this foresight");
  }
  ShardHeader& h = part.header;
  h.command = root.String("command");
  h.version = root.String("foresight_version");
  h.shard = ParseShard(part.file.string() + ": shard", root.String("shard"));
  h.items = root.Integer("items");
  h.run_time_s = root.Number("run_time_s");
  if (!(h.run_time_s >= 0.0 && h.run_time_s <= kMaxShardRunTime_s)) {
    root.Fail("run_time_s", "must be in [0, " + FormatNumber(kMaxShardRunTime_s) + "], got " +
                                FormatNumber(h.run_time_s));
  }
  const nlohmann::json& tree = doc.Tree();
  if (!tree["settings"].is_object()) root.Fail("settings", "must be an object");
  h.settings = nlohmann::ordered_json(tree["settings"]);
  if (!tree["results"].is_array()) root.Fail("results", "must be an array");
  part.results = tree["results"];
  const int owned = h.shard.OwnedCount(h.items);
  if (static_cast<int>(part.results.size()) != owned) {
    root.Fail("results", std::to_string(part.results.size()) + " items, but shard " +
                             h.shard.Text() + " of " + std::to_string(h.items) + " has " +
                             std::to_string(owned));
  }
  return part;
}

// "FILE: WHAT is 'X', but FIRST has 'Y'" when `a` and `b` differ.
void RequireSame(const ShardPart& part, const ShardPart& first, const std::string& what,
                 const std::string& a, const std::string& b) {
  if (a != b) {
    throw InputError(part.file.string() + ": " + what + " is '" + a + "', but " +
                     first.file.string() + " has '" + b + "' (shards of different runs)");
  }
}

// A setting as the flag was given: strings without their JSON quotes.
std::string SettingText(const nlohmann::ordered_json& settings, const std::string& key) {
  if (!settings.contains(key)) return "(absent)";
  const auto& value = settings[key];
  return value.is_string() ? value.get<std::string>() : value.dump();
}

void RequireSameSettings(const ShardPart& part, const ShardPart& first) {
  const auto& mine = part.header.settings;
  const auto& theirs = first.header.settings;
  for (const auto& [key, value] : theirs.items()) {
    if (!mine.contains(key) || mine[key] != value) {
      RequireSame(part, first, "setting " + key, SettingText(mine, key), SettingText(theirs, key));
    }
  }
  for (const auto& [key, value] : mine.items()) {
    if (!theirs.contains(key)) RequireSame(part, first, "setting " + key, value.dump(), "(absent)");
  }
}

}  // namespace

std::string ShardFileText(const ShardHeader& header, const nlohmann::json& results) {
  nlohmann::ordered_json j;
  j["foresight_shard"] = kShardFormat;
  j["command"] = header.command;
  j["foresight_version"] = header.version;
  j["shard"] = header.shard.Text();
  j["items"] = header.items;
  j["run_time_s"] = header.run_time_s;
  j["settings"] = header.settings;
  // One item per line: readable, and small enough (no indentation inside an item).
  std::string text = j.dump(1);
  text.resize(text.size() - 2);  // "\n}"
  text += ",\n \"results\": [";
  for (std::size_t i = 0; i < results.size(); ++i) {
    text += (i == 0 ? "\n  " : ",\n  ") + results[i].dump();
  }
  text += results.empty() ? "]\n}\n" : "\n ]\n}\n";
  return text;
}

std::vector<ShardPart> ReadShardParts(const std::vector<std::filesystem::path>& dirs,
                                      const std::string& version) {
  if (dirs.empty()) throw InputError("merge: no shard folders given");
  std::vector<ShardPart> parts;
  for (const auto& dir : dirs) parts.push_back(ParsePart(dir));
  const ShardPart& first = parts.front();
  if (first.header.version != version) {
    throw InputError(first.file.string() + ": made by foresight " + first.header.version +
                     ", this is " + version + " (merge with the version that ran the shards)");
  }
  std::map<int, const ShardPart*> by_index;
  for (const ShardPart& part : parts) {
    RequireSame(part, first, "command", part.header.command, first.header.command);
    RequireSame(part, first, "foresight_version", part.header.version, first.header.version);
    RequireSame(part, first, "the shard count", std::to_string(part.header.shard.count),
                std::to_string(first.header.shard.count));
    RequireSame(part, first, "the item count", std::to_string(part.header.items),
                std::to_string(first.header.items));
    RequireSameSettings(part, first);
    const auto [at, fresh] = by_index.emplace(part.header.shard.index, &part);
    if (!fresh) {
      throw InputError(part.file.string() + ": shard " + part.header.shard.Text() +
                       " is given twice (also " + at->second->file.string() + ")");
    }
  }
  const int count = first.header.shard.count;
  std::string missing;
  for (int i = 0; i < count; ++i) {
    if (!by_index.contains(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
  }
  if (!missing.empty()) {
    throw InputError("merge: shard(s) " + missing + " of this '" + first.header.command +
                     "' run (0 .. " + std::to_string(count - 1) + ") missing; " +
                     std::to_string(parts.size()) + " folders given");
  }
  std::vector<ShardPart> ordered;
  for (const auto& [index, part] : by_index) ordered.push_back(*part);
  return ordered;
}

nlohmann::json ExactJson(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

ShardValue::ShardValue(const nlohmann::json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

void ShardValue::Fail(const std::string& problem) const {
  throw InputError(file_ + ": " + path_ + ": " + problem);
}

ShardValue ShardValue::operator[](std::string_view key) const {
  if (!value_->is_object()) Fail("must be an object");
  const auto it = value_->find(key);
  const std::string path = path_ + "." + std::string(key);
  if (it == value_->end()) ShardValue(*value_, file_, path).Fail("missing");
  return ShardValue(*it, file_, path);
}

ShardValue ShardValue::At(std::size_t index) const {
  if (index >= Size()) Fail("has no item " + std::to_string(index));
  return ShardValue((*value_)[index], file_, path_ + "[" + std::to_string(index) + "]");
}

std::size_t ShardValue::Size() const {
  if (!value_->is_array()) Fail("must be an array");
  return value_->size();
}

double ShardValue::Double() const {
  if (value_->is_number()) return value_->get<double>();
  if (value_->is_string()) {
    const std::string s = value_->get<std::string>();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
  }
  Fail("must be a number, got " + QuoteJson(*value_));
}

long long ShardValue::Integer() const {
  if (!value_->is_number_integer()) Fail("must be an integer, got " + QuoteJson(*value_));
  return value_->get<long long>();
}

int ShardValue::Int() const {
  const long long v = Integer();
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    Fail("out of range: " + QuoteJson(*value_));
  return static_cast<int>(v);
}

double ShardValue::Finite() const {
  const double x = Double();
  if (!std::isfinite(x)) Fail("must be a finite number, got " + QuoteJson(*value_));
  return x;
}

double ShardValue::InRange(double lo, double hi) const {
  const double x = Double();
  if (!(x >= lo && x <= hi)) {
    Fail("must be in [" + FormatNumber(lo) + ", " + FormatNumber(hi) + "], got " +
         QuoteJson(*value_));
  }
  return x;
}

int ShardValue::Count() const {
  const int n = Int();
  if (n < 0) Fail("must be 0 or more, got " + std::to_string(n));
  return n;
}

int ShardValue::IntInRange(int lo, int hi) const {
  const int n = Int();
  if (n < lo || n > hi) {
    Fail("must be " + std::to_string(lo) + " .. " + std::to_string(hi) + ", got " +
         std::to_string(n));
  }
  return n;
}

bool ShardValue::Bool() const {
  if (!value_->is_boolean()) Fail("must be true or false, got " + QuoteJson(*value_));
  return value_->get<bool>();
}

std::string ShardValue::String() const {
  if (!value_->is_string()) Fail("must be a string, got " + QuoteJson(*value_));
  return value_->get<std::string>();
}

ShardValue ResultsOf(const ShardPart& part) {
  return ShardValue(part.results, part.file.string(), "results");
}

namespace {

// No ball rolls for an hour (assumption: the simulators stop far sooner; physics at
// max_roll_time_s, models/physics_params.h).
constexpr double kMaxOutcomeTime_s = 3600.0;

// An enum stored by its number, checked to be one of its `count` values.
template <typename Enum>
Enum ShardEnum(const ShardValue& value, int count) {
  const int n = value.Int();
  if (n < 0 || n >= count) value.Fail("must be 0 .. " + std::to_string(count - 1));
  return static_cast<Enum>(n);
}

}  // namespace

nlohmann::json OutcomeShardJson(const Outcome& o) {
  return {ExactJson(o.p_F_rest.x()),         ExactJson(o.p_F_rest.y()),
          static_cast<int>(o.category),      static_cast<int>(o.first_contact),
          ExactJson(o.time_s),               static_cast<int>(o.status)};
}

Outcome ReadShardOutcome(const ShardValue& value) {
  if (value.Size() != 6) value.Fail("must be [x, y, category, contact, time, status]");
  Outcome o;
  o.p_F_rest = {value.At(0).Finite(), value.At(1).Finite()};
  o.category = ShardEnum<Category>(value.At(2), kCategoryCount);
  o.first_contact = ShardEnum<Contact>(value.At(3), static_cast<int>(Contact::kRobot) + 1);
  o.time_s = value.At(4).InRange(0.0, kMaxOutcomeTime_s);
  o.status = ShardEnum<OutcomeStatus>(value.At(5), kOutcomeStatusCount);
  return o;
}

nlohmann::json OutcomesShardJson(const std::vector<Outcome>& outcomes) {
  nlohmann::json list = nlohmann::json::array();
  for (const Outcome& o : outcomes) list.push_back(OutcomeShardJson(o));
  return list;
}

std::vector<Outcome> ReadShardOutcomes(const ShardValue& value) {
  std::vector<Outcome> outcomes;
  for (std::size_t i = 0; i < value.Size(); ++i) outcomes.push_back(ReadShardOutcome(value.At(i)));
  return outcomes;
}

}  // namespace foresight
