#include "validation/physics_checks.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string_view>
#include <variant>

#include "common/error.h"
#include "common/json_reader.h"
#include "common/one_line.h"
#include "report/svg_writer.h"

namespace foresight {

namespace {

// A number the spec must give whole, as the whole number it is: JSON has only doubles.
double WholeNumber(const JsonObject& item, std::string_view key, double value, double lo, double hi,
                   const std::string& range) {
  if (value < lo || value > hi || value != std::floor(value)) {
    item.Fail(key, "must be a whole number in " + range + ", got " + std::to_string(value));
  }
  return value;
}

int Trials(const JsonObject& item, double value) {
  // Built with += : GCC 12 warns (-Wrestrict, a false positive) on "[" + std::to_string(...).
  std::string range = "[";
  range += std::to_string(kMinCheckTrials);
  range += ", ";
  range += std::to_string(kMaxCheckTrials);
  range += "]";
  return static_cast<int>(
      WholeNumber(item, "trials", value, kMinCheckTrials, kMaxCheckTrials, range));
}

ImpactTarget Target(const JsonObject& item, const std::string& text) {
  if (const std::optional<ImpactTarget> t = ParseImpactTarget(text)) return *t;
  item.Fail("target", "must be one of " + ImpactTargetNames() + ", got '" + text + "'");
}

int Phases(const JsonObject& item, double value) {
  return static_cast<int>(WholeNumber(item, "phases", value, 1, kMaxCheckPhases,
                                      "[1, " + std::to_string(kMaxCheckPhases) + "]"));
}

// Each reader takes the strings first, then the numbers, then turns them into their types: a
// spec with several faults reports the first in that order.
CheckKind ReadFreeRoll(const JsonObject& item) {
  FreeRollCheck c;
  c.field = item.String("field");
  c.speed_mps = item.Number("speed_mps");
  c.heading_deg = item.Number("heading_deg");
  c.max_error_rel = item.Number("max_error_rel");
  c.max_lateral_m = item.Number("max_lateral_m");
  return c;
}

CheckKind ReadNoTunnelling(const JsonObject& item) {
  NoTunnellingCheck c;
  c.field = item.String("field");
  const std::string target = item.String("target");
  c.speed_mps = item.Number("speed_mps");
  const double phases = item.Number("phases");
  c.max_penetration_steps = item.Number("max_penetration_steps");
  c.target = Target(item, target);
  c.phases = Phases(item, phases);
  return c;
}

CheckKind ReadRebound(const JsonObject& item) {
  ReboundCheck c;
  c.field = item.String("field");
  const std::string target = item.String("target");
  c.speeds_mps = item.NumberArray("speeds_mps");
  const double phases = item.Number("phases");
  c.max_error_rel = item.Number("max_error_rel");
  c.min_error_mps = item.Number("min_error_mps");
  c.target = Target(item, target);
  c.phases = Phases(item, phases);
  return c;
}

CheckKind ReadRobotRebound(const JsonObject& item) {
  RobotReboundCheck c;
  c.field = item.String("field");
  c.robot = item.String("robot");
  c.link = item.String("link");
  c.speeds_mps = item.NumberArray("speeds_mps");
  c.max_error_rel = item.Number("max_error_rel");
  return c;
}

CheckKind ReadKickDirection(const JsonObject& item) {
  KickDirectionCheck c;
  c.robot = item.String("robot");
  c.kick = item.String("kick");
  c.kicks = item.String("kicks");
  const double trials = item.Number("trials");
  c.max_error_deg = item.Number("max_error_deg");
  c.trials = Trials(item, trials);
  return c;
}

CheckKind ReadCalibrationBand(const JsonObject& item) {
  CalibrationBandCheck c;
  c.robot = item.String("robot");
  c.kicks = item.String("kicks");
  const double trials = item.Number("trials");
  const double seed = item.Number("seed");
  c.band_rel = item.Number("band_rel");
  c.band_deg = item.Number("band_deg");
  c.trials = Trials(item, trials);
  c.seed =
      static_cast<std::uint64_t>(WholeNumber(item, "seed", seed, 0.0, kMaxCheckSeed, "[0, 2^53]"));
  return c;
}

CheckKind ReadFidelityFloor(const JsonObject& item) {
  FidelityFloorCheck c;
  c.situations = item.String("situations");
  c.kicks = item.String("kicks");
  const double trials = item.Number("trials");
  c.min_tau_b = item.Number("min_tau_b");
  c.max_regret = item.Number("max_regret");
  c.trials = Trials(item, trials);
  return c;
}

struct KindReader {
  std::string_view kind;
  std::vector<std::string_view> keys;  // besides name, kind and notes
  CheckKind (*read)(const JsonObject& item);
};

const std::vector<KindReader>& Readers() {
  static const std::vector<KindReader> readers = {
      {FreeRollCheck::kKind,
       {"field", "speed_mps", "heading_deg", "max_error_rel", "max_lateral_m"},
       ReadFreeRoll},
      {NoTunnellingCheck::kKind,
       {"field", "target", "speed_mps", "phases", "max_penetration_steps"},
       ReadNoTunnelling},
      {ReboundCheck::kKind,
       {"field", "target", "speeds_mps", "phases", "max_error_rel", "min_error_mps"},
       ReadRebound},
      {RobotReboundCheck::kKind,
       {"field", "robot", "link", "speeds_mps", "max_error_rel"},
       ReadRobotRebound},
      {KickDirectionCheck::kKind,
       {"robot", "kick", "kicks", "trials", "max_error_deg"},
       ReadKickDirection},
      {CalibrationBandCheck::kKind,
       {"robot", "kicks", "trials", "seed", "band_rel", "band_deg"},
       ReadCalibrationBand},
      {FidelityFloorCheck::kKind,
       {"situations", "kicks", "trials", "min_tau_b", "max_regret"},
       ReadFidelityFloor},
  };
  return readers;
}

const KindReader& ReaderOf(const JsonObject& item, const std::string& kind) {
  std::string kinds;
  for (const KindReader& r : Readers()) {
    if (r.kind == kind) return r;
    kinds += (kinds.empty() ? "" : ", ") + std::string(r.kind);
  }
  item.Fail("kind", "unknown kind '" + kind + "' (one of: " + kinds + ")");
}

// Validate()'s "field: problem" as the JSON reader words it: "FILE: checks[i].field: problem".
void ValidateAt(const JsonObject& item, const CheckKind& kind) {
  try {
    std::visit([](const auto& check) { check.Validate(); }, kind);
  } catch (const InputError& e) {
    throw InputError(item.file() + ": " + item.PathOf(e.what()));
  }
}

CheckSpec ReadCheck(const JsonObject& item, const std::string& where) {
  CheckSpec spec;
  spec.where = where;
  spec.name = item.String("name");
  const std::string kind = item.String("kind");
  const KindReader& reader = ReaderOf(item, kind);
  for (const std::string& key : item.Keys()) {
    bool known = key == "name" || key == "kind" || key == "notes";
    for (std::string_view k : reader.keys) known = known || k == key;
    if (!known) item.Fail(key, "unknown key for a " + kind + " check");
  }
  spec.kind = reader.read(item);
  ValidateAt(item, spec.kind);
  return spec;
}

std::string Seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", s);
  return buffer;
}

}  // namespace

CheckSuite LoadCheckSuite(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError("--spec: " + file.string() + " does not exist");
  }
  JsonDocument doc = JsonDocument::Load(file);
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"name", "checks"});
  CheckSuite suite;
  suite.file = file;
  suite.name = root.StringOr("name", file.stem().string());
  const std::vector<JsonObject> items = root.ObjectArray("checks");
  for (std::size_t i = 0; i < items.size(); ++i) {
    suite.checks.push_back(
        ReadCheck(items[i], file.string() + ": checks[" + std::to_string(i) + "]"));
    suite.checks.back().dir = file.parent_path();
    for (std::size_t j = 0; j + 1 < suite.checks.size(); ++j) {
      if (suite.checks[j].name == suite.checks.back().name) {
        items[i].Fail("name", "duplicate check name '" + suite.checks.back().name + "'");
      }
    }
  }
  if (suite.checks.empty()) root.Fail("checks", "must list at least one check");
  return suite;
}

std::vector<CheckResult> RunChecks(const CheckSuite& suite, const std::filesystem::path& models_dir,
                                   int threads,
                                   const std::function<void(const CheckResult&)>& on_result) {
  // Every check's files and names before the first check runs.
  for (const CheckSpec& spec : suite.checks) {
    try {
      PrepareCheck(spec, models_dir);
    } catch (const InputError& e) {
      throw InputError(spec.where + " (check '" + spec.name + "'): " + e.what());
    }
  }
  std::vector<CheckResult> results;
  for (const CheckSpec& spec : suite.checks) {
    const auto start = std::chrono::steady_clock::now();
    CheckResult result;
    try {
      result = RunCheck(spec, models_dir, threads);
    } catch (const InputError& e) {
      throw InputError(spec.where + " (check '" + spec.name + "'): " + e.what());
    }
    result.name = spec.name;
    result.kind = std::string(KindName(spec.kind));
    result.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (on_result) on_result(result);
    results.push_back(std::move(result));
  }
  return results;
}

namespace {

// A name or text from the spec in an XML attribute or element: printable first (control
// characters are not valid XML 1.0, not even as references), then escaped.
std::string XmlText(const std::string& text) { return SvgWriter::Escape(PrintableName(text)); }

}  // namespace

std::string JUnitXml(const std::string& suite_name, const std::vector<CheckResult>& results,
                     const std::vector<std::pair<std::string, std::string>>& properties) {
  int failures = 0;
  double time = 0.0;
  for (const CheckResult& r : results) {
    failures += !r.passed;
    time += r.time_s;
  }
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
  out += "  <testsuite name=\"" + XmlText(suite_name) + "\" tests=\"" +
         std::to_string(results.size()) + "\" failures=\"" + std::to_string(failures) +
         "\" errors=\"0\" time=\"" + Seconds(time) + "\">\n";
  if (!properties.empty()) {
    out += "    <properties>\n";
    for (const auto& [name, value] : properties) {
      out += "      <property name=\"" + XmlText(name) + "\" value=\"" + XmlText(value) + "\"/>\n";
    }
    out += "    </properties>\n";
  }
  for (const CheckResult& r : results) {
    out += "    <testcase classname=\"foresight.check." + XmlText(r.kind) + "\" name=\"" +
           XmlText(r.name) + "\" time=\"" + Seconds(r.time_s) + "\">\n";
    if (r.passed) {
      out += "      <system-out>" + XmlText(r.detail) + "</system-out>\n";
    } else {
      out += "      <failure message=\"" + XmlText(r.detail) + "\"/>\n";
    }
    out += "    </testcase>\n";
  }
  return out + "  </testsuite>\n</testsuites>\n";
}

}  // namespace foresight
