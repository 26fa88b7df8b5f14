#include "validation/physics_checks.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "common/json_reader.h"
#include "report/svg_writer.h"

namespace foresight {

namespace {

struct KindKeys {
  const char* kind;
  std::vector<std::string> text;
  std::vector<std::string> number;
};

const std::vector<KindKeys>& Kinds() {
  static const std::vector<KindKeys> kinds = {
      {"free_roll", {"field"}, {"speed_mps", "heading_deg", "max_error_rel", "max_lateral_m"}},
      {"no_tunnelling", {"field", "target"}, {"speed_mps", "max_penetration_m"}},
      {"kick_direction", {"robot", "kick", "kicks"}, {"trials", "max_error_deg"}},
      {"calibration_band", {"robot", "kicks"}, {"trials", "seed", "band_rel", "band_deg"}},
      {"fidelity_floor", {"situations", "kicks"}, {"trials", "min_tau_b", "max_regret"}},
  };
  return kinds;
}

CheckSpec ReadCheck(const JsonObject& item, const std::string& where) {
  CheckSpec spec;
  spec.where = where;
  spec.name = item.String("name");
  spec.kind = item.String("kind");
  const KindKeys* keys = nullptr;
  for (const KindKeys& k : Kinds()) {
    if (spec.kind == k.kind) keys = &k;
  }
  if (!keys) {
    item.Fail("kind", "unknown kind '" + spec.kind +
                          "' (one of: free_roll, no_tunnelling, kick_direction, "
                          "calibration_band, fidelity_floor)");
  }
  for (const std::string& key : item.Keys()) {
    bool known = key == "name" || key == "kind" || key == "notes";
    for (const std::string& k : keys->text) known = known || k == key;
    for (const std::string& k : keys->number) known = known || k == key;
    if (!known) item.Fail(key, "unknown key for a " + spec.kind + " check");
  }
  for (const std::string& k : keys->text) spec.text[k] = item.String(k);
  for (const std::string& k : keys->number) spec.number[k] = item.Number(k);
  if (spec.number.count("trials")) {
    const double trials = spec.number["trials"];
    if (trials < 2 || trials > 100000 || trials != std::floor(trials)) {
      item.Fail("trials", "must be a whole number in [2, 100000], got " + std::to_string(trials));
    }
  }
  if (spec.number.count("speed_mps") && !(spec.number["speed_mps"] > 0.0)) {
    item.Fail("speed_mps", "must be > 0");
  }
  if (spec.number.count("seed")) {
    const double seed = spec.number["seed"];
    if (seed < 0 || seed > 9007199254740992.0 || seed != std::floor(seed)) {
      item.Fail("seed", "must be a whole number in [0, 2^53], got " + std::to_string(seed));
    }
  }
  if (spec.text.count("target")) {
    const std::string& t = spec.text["target"];
    if (t != "post" && t != "back_net" && t != "side_net") {
      item.Fail("target", "must be post, back_net or side_net, got '" + t + "'");
    }
  }
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
  std::vector<CheckResult> results;
  for (const CheckSpec& spec : suite.checks) {
    const auto start = std::chrono::steady_clock::now();
    CheckResult result = RunCheck(spec, models_dir, threads);
    result.name = spec.name;
    result.kind = spec.kind;
    result.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (on_result) on_result(result);
    results.push_back(std::move(result));
  }
  return results;
}

std::string JUnitXml(const std::string& suite_name, const std::vector<CheckResult>& results) {
  int failures = 0;
  double time = 0.0;
  for (const CheckResult& r : results) {
    failures += !r.passed;
    time += r.time_s;
  }
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
  out += "  <testsuite name=\"" + SvgWriter::Escape(suite_name) + "\" tests=\"" +
         std::to_string(results.size()) + "\" failures=\"" + std::to_string(failures) +
         "\" errors=\"0\" time=\"" + Seconds(time) + "\">\n";
  for (const CheckResult& r : results) {
    out += "    <testcase classname=\"foresight.check." + SvgWriter::Escape(r.kind) + "\" name=\"" +
           SvgWriter::Escape(r.name) + "\" time=\"" + Seconds(r.time_s) + "\">\n";
    if (r.passed) {
      out += "      <system-out>" + SvgWriter::Escape(r.detail) + "</system-out>\n";
    } else {
      out += "      <failure message=\"" + SvgWriter::Escape(r.detail) + "\"/>\n";
    }
    out += "    </testcase>\n";
  }
  return out + "  </testsuite>\n</testsuites>\n";
}

}  // namespace foresight
