#include "cbr/case_base.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "common/error.h"
#include "common/json_reader.h"
#include "models/field_spec.h"
#include "models/kick_model.h"

namespace foresight {
namespace {

constexpr char kSettingsFile[] = "case_base.json";
constexpr double kSameM = 1e-6;

bool Same(const Vec2& a, const Vec2& b) {
  return (a - b).norm() <= kSameM;
}
bool Same(const Scope& a, const Scope& b) {
  return std::abs(a.tau_x_m - b.tau_x_m) <= kSameM && std::abs(a.tau_y_m - b.tau_y_m) <= kSameM;
}
bool Same(const CaseAction& a, const CaseAction& b) {
  if (a.type != b.type || a.kick != b.kick || a.at_goal != b.at_goal || a.teammate != b.teammate ||
      a.target_F.has_value() != b.target_F.has_value() ||
      a.heading_rad.has_value() != b.heading_rad.has_value()) {
    return false;
  }
  if (a.target_F && !Same(*a.target_F, *b.target_F)) return false;
  return !a.heading_rad || std::abs(WrapAngle(*a.heading_rad - *b.heading_rad)) <= 1e-9;
}
bool Same(const Case& a, const Case& b) {
  if (a.defending != b.defending || !Same(a.p_F_ball, b.p_F_ball) ||
      !Same(a.ball_scope, b.ball_scope) || a.teammates.size() != b.teammates.size() ||
      a.opponents.size() != b.opponents.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.teammates.size(); ++i) {
    const auto& ta = a.teammates[i];
    const auto& tb = b.teammates[i];
    if (ta.id != tb.id || !Same(ta.p_F, tb.p_F) || ta.actions.size() != tb.actions.size()) {
      return false;
    }
    for (std::size_t j = 0; j < ta.actions.size(); ++j) {
      if (!Same(ta.actions[j], tb.actions[j])) return false;
    }
  }
  // Opponents as a set: a mirror may list them in another order only if written so.
  for (const auto& oa : a.opponents) {
    const bool found = std::any_of(b.opponents.begin(), b.opponents.end(), [&](const auto& ob) {
      return Same(oa.p_F, ob.p_F) && Same(oa.scope, ob.scope);
    });
    if (!found) return false;
  }
  return true;
}

std::filesystem::path Resolve(const JsonObject& root, std::string_view key, DataFolder folder,
                              const std::filesystem::path& dir,
                              const std::filesystem::path& models_dir) {
  const auto file = ResolveModelFile(root.String(key), folder, dir, models_dir);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    root.Fail(key, "refers to " + file.string() + ", which does not exist");
  }
  return file;
}

KickMirrors ReadKickMirrors(const JsonObject& root, const KickModel& kicks) {
  KickMirrors mirrors;
  const JsonObject pairs = root.Object("kick_mirrors");
  for (const std::string& left : pairs.Keys()) {
    if (left == "notes") continue;
    const std::string right = pairs.String(left);
    for (const std::string& kick : {left, right}) {
      if (!kicks.Find(kick)) {
        pairs.Fail(left, "unknown kick '" + kick + "' (the " + kicks.robot + " has " +
                             kicks.Names() + ")");
      }
    }
    if (left == right || mirrors.count(left) || mirrors.count(right)) {
      pairs.Fail(left, "'" + left + "' <-> '" + right + "' must pair two kicks not paired yet");
    }
    mirrors[left] = right;
    mirrors[right] = left;
  }
  return mirrors;
}

std::vector<std::filesystem::path> CaseFilesIn(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const auto& p = entry.path();
    if (entry.is_regular_file() && p.extension() == ".json" && p.filename() != kSettingsFile) {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

CaseBase::CaseBase(const std::vector<Case>& hand_written, const KickMirrors& mirrors)
    : hand_written_(hand_written.size()) {
  for (const Case& c : hand_written) {
    for (CaseTransform t : {CaseTransform::kOriginal, CaseTransform::kMirrorY,
                            CaseTransform::kMirrorX, CaseTransform::kMirrorXY}) {
      Case copy = MirrorCase(c, t, mirrors);
      (copy.defending == DefendingGoal::kCyan ? cyan_ : yellow_).push_back(std::move(copy));
    }
  }
}

CaseBase CaseBase::WithoutMirrorY() const {
  CaseBase kept = *this;
  for (auto* list : {&kept.cyan_, &kept.yellow_}) {
    std::erase_if(*list, [](const Case& c) {
      return c.transform == CaseTransform::kMirrorY || c.transform == CaseTransform::kMirrorXY;
    });
  }
  return kept;
}

std::span<const Case> CaseBase::Defending(DefendingGoal goal) const {
  return goal == DefendingGoal::kCyan ? std::span<const Case>(cyan_)
                                      : std::span<const Case>(yellow_);
}

const Case* CaseBase::Find(const std::string& name) const {
  for (const auto* list : {&cyan_, &yellow_}) {
    for (const Case& c : *list) {
      if (c.name == name) return &c;
    }
  }
  return nullptr;
}

std::filesystem::path DefaultCaseBasePath(const std::filesystem::path& models_dir) {
  return DataFolderPath(models_dir, DataFolder::kCases);
}

LoadedCaseBase LoadCaseBase(const std::filesystem::path& path,
                            const std::filesystem::path& models_dir) {
  std::error_code ec;
  const bool is_folder = std::filesystem::is_directory(path, ec);
  const std::filesystem::path settings = is_folder ? path / kSettingsFile : path;
  if (!std::filesystem::is_regular_file(settings, ec)) {
    throw InputError(settings.string() + ": does not exist (a case base needs its settings file)");
  }
  const std::filesystem::path dir = settings.parent_path();
  const JsonDocument doc = JsonDocument::Load(settings);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"field", "kicks", "kick_mirrors", "configurations", "cases"});

  LoadedCaseBase loaded;
  loaded.rules.field = LoadFieldSpec(Resolve(root, "field", DataFolder::kFields, dir, models_dir));
  loaded.rules.kicks = LoadKickModel(Resolve(root, "kicks", DataFolder::kKicks, dir, models_dir));
  loaded.kick_mirrors = ReadKickMirrors(root, loaded.rules.kicks);
  if (root.Has("configurations")) {
    loaded.configurations = root.StringArray("configurations");
    for (const std::string& name : loaded.configurations) {
      if (name.empty()) root.Fail("configurations", "names must not be empty");
    }
  }

  std::vector<std::filesystem::path> files;
  if (root.Has("cases")) {
    for (const std::string& f : root.StringArray("cases")) files.push_back(dir / f);
  } else if (is_folder) {
    files = CaseFilesIn(path);
  } else {
    root.Fail("cases", "missing (a settings file given alone must list its case files)");
  }
  if (files.empty()) throw InputError(settings.string() + ": the case base has no cases");

  std::vector<Case> cases;
  std::set<std::string> names;
  for (const auto& file : files) {
    Case c = LoadCaseFile(file, loaded.rules);
    if (!names.insert(c.name).second) {
      throw InputError(file.string() + ": case " + c.name + ": name: used by another case file");
    }
    cases.push_back(std::move(c));
  }
  loaded.cases = CaseBase(cases, loaded.kick_mirrors);
  return loaded;
}

double BallScopeCoverage(const LoadedCaseBase& base, DefendingGoal goal, double x_min_m,
                         double x_max_m, double step_m) {
  const double half_width_m = base.rules.field.HalfWidth();
  int inside = 0, total = 0;
  for (double x = x_min_m; x <= x_max_m + 1e-9; x += step_m) {
    for (double y = -half_width_m; y <= half_width_m + 1e-9; y += step_m) {
      ++total;
      const auto cases = base.cases.Defending(goal);
      inside += std::any_of(cases.begin(), cases.end(), [&](const Case& c) {
        const double dx = (x - c.p_F_ball.x()) / c.ball_scope.tau_x_m;
        const double dy = (y - c.p_F_ball.y()) / c.ball_scope.tau_y_m;
        return dx * dx + dy * dy <= 1.0;
      });
    }
  }
  return total == 0 ? 0.0 : static_cast<double>(inside) / total;
}

std::vector<std::string> CheckCaseBase(const CaseBase& base) {
  std::vector<std::string> warnings;
  for (DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
    const auto cases = base.Defending(goal);
    // Grouped by the first case of each group: a case base of n copies of one case gives one
    // line, not n^2 / 2 (memory and output grow with the cases, not with the pairs).
    std::vector<bool> grouped(cases.size(), false);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (grouped[i]) continue;
      std::vector<std::size_t> group = {i};
      for (std::size_t j = i + 1; j < cases.size(); ++j) {
        if (!grouped[j] && Same(cases[i], cases[j])) {
          grouped[j] = true;
          group.push_back(j);
        }
      }
      if (group.size() < 2) continue;
      const std::size_t shown = std::min(group.size(), kMaxNamesPerOverlap);
      std::string names;
      for (std::size_t k = 0; k < shown; ++k) {
        const bool last = k + 1 == shown && shown == group.size();
        names += (k == 0 ? "" : last ? " and " : ", ") + cases[group[k]].name;
      }
      if (shown < group.size()) {
        names += " and " + std::to_string(group.size() - shown) + " more";
      }
      warnings.push_back(names + " are identical" +
                         (group.size() > 2 ? " (" + std::to_string(group.size()) + " cases)" : ""));
    }
  }
  return warnings;
}

void RequireCaseKicks(const CaseBase& base, const KickModel& kicks,
                      const std::filesystem::path& kicks_file) {
  for (const Case& c : base.Defending(DefendingGoal::kCyan)) {
    for (const CaseTeammate& tm : c.teammates) {
      for (const CaseAction& a : tm.actions) {
        if (a.kick.empty() || kicks.Find(a.kick)) continue;
        throw InputError(kicks_file.string() + ": kicks: no kick '" + a.kick + "', which case " +
                         c.name + " plays (the model has: " + kicks.Names() + ")");
      }
    }
  }
}

}  // namespace foresight
