#include "models/evaluation_params.h"

#include <algorithm>
#include <cmath>

#include "common/checks.h"
#include "common/error.h"
#include "common/geometry.h"
#include "common/json_reader.h"

namespace foresight {

// Plausibility bounds of the potential (assumption): its lengths are field-sized (metres); a
// scale or width under a centimetre, or lengths and weights beyond a thousand, are unit errors
// or garbage that make the value subnormal, infinite or NaN (a subnormal scale crashed decide).
constexpr double kMinPotentialLengthM = 0.01;
constexpr double kMaxPotentialLengthM = 1e3;
constexpr double kMaxPotentialWeight = 1e3;
// Plausibility bound of the coarse roll's contacts per kick (assumption): every rebound costs the
// ball (1 - e) of its normal speed, so a roll that touches more than a hundred things is garbage.
constexpr int kMaxCoarseContacts = 100;

int RotationSearchParams::CoarseSamples(int samples) const {
  // The tolerance keeps share * N that should be whole (1/3 * 30) from rounding up.
  const int n = static_cast<int>(std::ceil(coarse_sample_share * samples - 1e-9));
  return std::clamp(n, 1, std::max(samples, 1));
}

void EvaluationParams::Validate() const {
  RequirePositive("potential.linear_x_scale_m", potential.linear_x_scale_m);
  RequireInRange("potential.linear_x_scale_m", potential.linear_x_scale_m, kMinPotentialLengthM,
                 kMaxPotentialLengthM);
  for (std::size_t i = 0; i < potential.gaussians.size(); ++i) {
    const GaussianTerm& g = potential.gaussians[i];
    const std::string at = "potential.gaussians[" + std::to_string(i) + "].";
    RequireInRange(at + "weight", g.weight, -kMaxPotentialWeight, kMaxPotentialWeight);
    RequireInRange(at + "centre_x_m", g.centre_x_m, -kMaxPotentialLengthM, kMaxPotentialLengthM);
    RequireInRange(at + "centre_y_m", g.centre_y_m, -kMaxPotentialLengthM, kMaxPotentialLengthM);
    RequirePositive(at + "sigma_x_m", g.sigma_x_m);
    RequireInRange(at + "sigma_x_m", g.sigma_x_m, kMinPotentialLengthM, kMaxPotentialLengthM);
    RequirePositive(at + "sigma_y_m", g.sigma_y_m);
    RequireInRange(at + "sigma_y_m", g.sigma_y_m, kMinPotentialLengthM, kMaxPotentialLengthM);
  }
  RequirePositive("goal_value", goal_value);
  RequireInRange("goal_value", goal_value, 0.0, 1e6);
  RequireInRange("max_out_share", max_out_share, 0.0, 1.0);
  RequireInRange("samples", samples, 1, kMaxSamples);
  RequireInRange("naoth_rule.min_acceptable_share", naoth_rule.min_acceptable_share, 0.0, 1.0);
  RequireInRange("naoth_rule.goal_preference_share", naoth_rule.goal_preference_share, 0.0, 1.0);
  RequireInRange("rotation_search.grid_step_deg", rotation_search.grid_step_rad * kRadToDeg, 0.1,
                 90.0);
  RequireInRange("rotation_search.refine_levels", rotation_search.refine_levels, 0, 20);
  RequireInRange("rotation_search.refine_candidates", rotation_search.refine_candidates, 1, 100);
  RequireInRange("rotation_search.coarse_sample_share", rotation_search.coarse_sample_share, 0.01,
                 1.0);
  RequireInRange("rebounds.max_contacts", rebounds.max_contacts, 1, kMaxCoarseContacts);
}

EvaluationParams LoadEvaluationParams(const std::filesystem::path& file) {
  JsonDocument doc = JsonDocument::Load(file);
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"name", "potential", "goal_value", "max_out_share", "samples",
                          "naoth_rule", "rotation_search", "rebounds"});
  EvaluationParams params;
  params.name = root.String("name");
  JsonObject potential = root.Object("potential");
  potential.RejectUnknownKeys({"linear_x_scale_m", "gaussians"});
  params.potential.linear_x_scale_m = potential.Number("linear_x_scale_m");
  for (const JsonObject& item : potential.ObjectArray("gaussians")) {
    item.RejectUnknownKeys({"weight", "centre_x_m", "centre_y_m", "sigma_x_m", "sigma_y_m"});
    params.potential.gaussians.push_back({item.Number("weight"), item.Number("centre_x_m"),
                                          item.Number("centre_y_m"), item.Number("sigma_x_m"),
                                          item.Number("sigma_y_m")});
  }
  params.goal_value = root.Number("goal_value");
  params.max_out_share = root.Number("max_out_share");
  params.samples = root.Integer("samples");

  JsonObject naoth = root.Object("naoth_rule");
  naoth.RejectUnknownKeys({"min_acceptable_share", "goal_preference_share"});
  params.naoth_rule.min_acceptable_share = naoth.Number("min_acceptable_share");
  params.naoth_rule.goal_preference_share = naoth.Number("goal_preference_share");

  JsonObject search = root.Object("rotation_search");
  search.RejectUnknownKeys(
      {"grid_step_deg", "refine_levels", "refine_candidates", "coarse_sample_share"});
  params.rotation_search.grid_step_rad = search.Number("grid_step_deg") * kDegToRad;
  params.rotation_search.refine_levels = search.Integer("refine_levels");
  params.rotation_search.refine_candidates = search.Integer("refine_candidates");
  params.rotation_search.coarse_sample_share = search.Number("coarse_sample_share");

  JsonObject rebounds = root.Object("rebounds");
  rebounds.RejectUnknownKeys({"enabled", "max_contacts"});
  params.rebounds.enabled = rebounds.Bool("enabled");
  params.rebounds.max_contacts = rebounds.Integer("max_contacts");

  WithFile(file.string(), [&] { params.Validate(); });
  return params;
}

}  // namespace foresight
