#include "cbr/retrieval_params.h"

#include <algorithm>
#include <cmath>

#include "common/checks.h"
#include "common/enum_names.h"
#include "common/error.h"
#include "common/geometry.h"
#include "common/json_reader.h"
#include "models/kick_model.h"
#include "planner/kick_reach.h"

namespace foresight {
namespace {

constexpr EnumNames<CostFunction, 3> kCostNames{{{
    {CostFunction::kSum, "sum"},
    {CostFunction::kMax, "max"},
    {CostFunction::kMaxThenSum, "max_then_sum"},
}}};

constexpr EnumNames<RankCriterion, 3> kCriterionNames{{{
    {RankCriterion::kConditions, "conditions"},
    {RankCriterion::kTeammates, "teammates"},
    {RankCriterion::kBandThenCost, "band_then_cost"},
}}};

constexpr EnumNames<TrajectoryWidths, 2> kWidthNames{{{
    {TrajectoryWidths::kData, "data"},
    {TrajectoryWidths::kKickModel, "kick_model"},
}}};

// A corridor wider than the field (`width_m`) or a kick longer than its diagonal (`diagonal_m`)
// says nothing a field-wide one does not: such values are typing errors, and their arithmetic
// overflows (1e308 widths made the corridor's membership, and `cbr retrieve --json`, non-finite).
void ValidateKick(const std::string& at, const KickTrajectory& k, double width_m,
                  double diagonal_m) {
  if (k.kick.empty()) throw InputError(at + "kick: must not be empty");
  RequirePositive(at + "r_min_m", k.r_min_m);
  RequireInRange(at + "r_min_m", k.r_min_m, 0.0, width_m);
  RequirePositive(at + "r_max_m", k.r_max_m);
  RequireInRange(at + "r_max_m", k.r_max_m, 0.0, width_m);
  RequireInRange(at + "reach_m", k.reach_m, 0.0, diagonal_m);
  RequireInRange(at + "sigma_direction_deg", k.sigma_direction_rad * kRadToDeg, 0.0, 45.0);
}

// A kick's widths; `name` empty: the default entry, which names no kick.
KickTrajectory ReadKick(const JsonObject& item, std::string name) {
  if (name.empty()) {
    item.RejectUnknownKeys({"r_min_m", "r_max_m", "reach_m", "sigma_direction_deg"});
    name = "default";
  } else {
    item.RejectUnknownKeys({"kick", "r_min_m", "r_max_m", "reach_m", "sigma_direction_deg"});
  }
  KickTrajectory k;
  k.kick = std::move(name);
  k.r_min_m = item.Number("r_min_m");
  k.r_max_m = item.Number("r_max_m");
  k.reach_m = item.NumberOr("reach_m", 0.0);
  k.sigma_direction_rad = item.NumberOr("sigma_direction_deg", 0.0) * kDegToRad;
  return k;
}

}  // namespace

std::string_view CostFunctionName(CostFunction cost) {
  return kCostNames.Name(cost);
}
std::optional<CostFunction> ParseCostFunction(std::string_view name) {
  return kCostNames.Parse(name);
}
std::optional<RankCriterion> ParseRankCriterion(std::string_view name) {
  return kCriterionNames.Parse(name);
}
std::string CostFunctionNames() {
  return kCostNames.List();
}
std::string RankCriterionNames() {
  return kCriterionNames.List();
}
std::string_view RankCriterionName(RankCriterion criterion) {
  return kCriterionNames.Name(criterion);
}
std::string_view TrajectoryWidthsName(TrajectoryWidths widths) {
  return kWidthNames.Name(widths);
}

const KickTrajectory& RetrievalParams::TrajectoryFor(std::string_view kick) const {
  for (const KickTrajectory& k : kicks) {
    if (k.kick == kick) return k;
  }
  return default_kick;
}

void RetrievalParams::Validate() const {
  RequireInRange("thr_ball", thr_ball, 1e-9, 1.0);
  RequirePositive("goal_x_m", goal_x_m);
  RequirePositive("half_width_m", half_width_m);
  const double width_m = 2.0 * half_width_m;
  const double diagonal_m = 2.0 * std::hypot(goal_x_m, half_width_m);
  RequirePositive("thr_cost_m", thr_cost_m);
  RequireInRange("thr_cost_m", thr_cost_m, 0.0, diagonal_m);  // no walk is longer on the field
  RequireInRange("thr_trajectory", thr_trajectory, 1e-9, 1.0);
  RequireInRange("thr_opponent", thr_opponent, 1e-9, 1.0);
  RequireInRange("bands.H", band_lower[0], 0.0, 1.0);
  RequireInRange("bands.h", band_lower[1], 0.0, band_lower[0]);
  RequireInRange("bands.l", band_lower[2], 0.0, band_lower[1]);
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (order[i] == order[j]) {
        throw InputError("order: must name each of " + kCriterionNames.List() + " once, got " +
                         std::string(RankCriterionName(order[i])) + " twice");
      }
    }
  }
  RequireInRange("width_sigmas", width_sigmas, 0.0, 5.0);
  if (reach_sigmas) RequireInRange("reach_sigmas", *reach_sigmas, -5.0, 5.0);
  RequireNonNegative("opponent_radius_m", opponent_radius_m);
  RequireNonNegative("ball_radius_m", ball_radius_m);
  ValidateKick("default_kick.", default_kick, width_m, diagonal_m);
  for (std::size_t i = 0; i < kicks.size(); ++i) {
    const std::string at = "kicks[" + std::to_string(i) + "].";
    ValidateKick(at, kicks[i], width_m, diagonal_m);
    for (std::size_t j = 0; j < i; ++j) {
      if (kicks[j].kick == kicks[i].kick) {
        throw InputError(at + "kick: \"" + kicks[i].kick + "\" appears twice");
      }
    }
  }
}

namespace {
// The entry of kick `name`, added with the default widths when there is none.
KickTrajectory& EntryFor(const std::string& name, RetrievalParams* params) {
  auto it = std::find_if(params->kicks.begin(), params->kicks.end(),
                         [&](const KickTrajectory& k) { return k.kick == name; });
  if (it != params->kicks.end()) return *it;
  KickTrajectory k = params->default_kick;
  k.kick = name;
  params->kicks.push_back(k);
  return params->kicks.back();
}
}  // namespace

void UseKickModelWidths(const KickModel& model, RetrievalParams* params) {
  for (const KickSpec& spec : model.kicks) {
    EntryFor(spec.name, params).sigma_direction_rad = spec.sigma_direction_rad;
  }
  params->widths = TrajectoryWidths::kKickModel;
}

void UseKickModelReach(const KickModel& model, RetrievalParams* params) {
  if (!params->reach_sigmas) return;
  for (const KickSpec& spec : model.kicks) {
    KickTrajectory& entry = EntryFor(spec.name, params);
    entry.reach_m =
        RollDistanceAtSigmas(spec, model.rolling_deceleration_mps2, *params->reach_sigmas);
    entry.roll_m = RollDistanceAtSigmas(spec, model.rolling_deceleration_mps2, 0.0);
  }
}

RetrievalParams LoadRetrievalParams(const std::filesystem::path& file, const FieldSpec& field) {
  JsonDocument doc = JsonDocument::Load(file);
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"thr_ball", "thr_cost_m", "thr_trajectory", "thr_opponent", "bands",
                          "cost", "order", "widths", "width_sigmas", "default_kick", "kicks",
                          "free_path", "opponent_similarity", "reach_sigmas"});
  RetrievalParams p;
  p.thr_ball = root.Number("thr_ball");
  p.thr_cost_m = root.Number("thr_cost_m");
  p.thr_trajectory = root.Number("thr_trajectory");
  p.thr_opponent = root.Number("thr_opponent");
  JsonObject bands = root.Object("bands");
  bands.RejectUnknownKeys({"H", "h", "l"});
  p.band_lower = {bands.Number("H"), bands.Number("h"), bands.Number("l")};
  const std::string cost = root.String("cost");
  if (auto parsed = kCostNames.Parse(cost)) {
    p.cost = *parsed;
  } else {
    root.Fail("cost", "must be one of " + kCostNames.List() + ", got \"" + cost + "\"");
  }
  const std::vector<std::string> order = root.StringArray("order");
  if (order.size() != p.order.size()) {
    root.Fail("order", "must list " + kCriterionNames.List() + " in some order, got " +
                           std::to_string(order.size()) + " items");
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    auto parsed = kCriterionNames.Parse(order[i]);
    if (!parsed) {
      root.Fail("order", "items must be " + kCriterionNames.List() + ", got \"" + order[i] + "\"");
    }
    p.order[i] = *parsed;
  }
  const std::string widths = root.String("widths");
  if (auto parsed = kWidthNames.Parse(widths)) {
    p.widths = *parsed;
  } else {
    root.Fail("widths", "must be one of " + kWidthNames.List() + ", got \"" + widths + "\"");
  }
  p.width_sigmas = root.Number("width_sigmas");
  p.free_path = root.BoolOr("free_path", true);
  p.opponent_similarity = root.BoolOr("opponent_similarity", true);
  if (root.Has("reach_sigmas")) p.reach_sigmas = root.Number("reach_sigmas");
  p.goal_x_m = field.HalfLength();
  p.half_width_m = field.HalfWidth();
  p.opponent_radius_m = field.default_obstacle_radius_m;
  p.ball_radius_m = field.ball.radius_m;
  p.default_kick = ReadKick(root.Object("default_kick"), "");
  for (const JsonObject& item : root.ObjectArray("kicks")) {
    p.kicks.push_back(ReadKick(item, item.String("kick")));
  }
  WithFile(file.string(), [&] { p.Validate(); });
  return p;
}

}  // namespace foresight
