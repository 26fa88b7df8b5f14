#include "validation/calibration_shard.h"

#include <algorithm>

#include "common/geometry.h"
#include "physics/trial.h"

namespace foresight {

namespace {

// What a physics trial can produce, with a wide margin (assumption: no robot kicks a ball at
// 50 m/s, no ball rolls 100 m or for an hour, no placement is off by a metre, no playback or
// carpet factor leaves [0.01, 10]). A shard value outside is damage or tampering, and would
// otherwise reach the fits (a sample of 1e308 gave a 63-digit deceleration).
constexpr double kMaxSpeed_mps = 50.0;
constexpr double kMaxDistance_m = 100.0;
constexpr double kMaxTime_s = 3600.0;
constexpr double kMaxPlacement_m = 1.0;
constexpr double kMinFactor = 0.01, kMaxFactor = 10.0;

nlohmann::json TrialJson(const KickObservation& o, const TrialDraw& d) {
  nlohmann::json rolling = nlohmann::json::array();
  for (const SpeedSample& s : o.rolling) {
    rolling.push_back(ExactJson(s.t_s));
    rolling.push_back(ExactJson(s.speed_mps));
  }
  return {ExactJson(o.launch_speed_mps),
          ExactJson(o.launch_direction_rad),
          o.has_roll_distance ? ExactJson(o.roll_distance_m) : nlohmann::json(nullptr),
          rolling,
          {ExactJson(d.placement_dx_m), ExactJson(d.placement_dy_m),
           ExactJson(d.placement_dtheta_rad), ExactJson(d.speed_factor),
           ExactJson(d.carpet_factor), d.placement_redraws},
          o.has_launch_offset ? ExactJson(o.launch_offset_m) : nlohmann::json(nullptr)};
}

void ReadTrial(const ShardValue& v, PhysicsKickTrials& kick, int trial) {
  if (v.Size() != 6) {
    v.Fail("must be [speed, direction, roll distance, rolling, draw, launch offset] or null");
  }
  KickObservation o;
  o.launch_speed_mps = v.At(0).InRange(0.0, kMaxSpeed_mps);
  o.launch_direction_rad = v.At(1).InRange(-kPi, kPi);  // wrapped by the trial
  o.has_roll_distance = !v.At(2).IsNull();
  if (o.has_roll_distance) o.roll_distance_m = v.At(2).InRange(0.0, kMaxDistance_m);
  const ShardValue rolling = v.At(3);
  if (rolling.Size() % 2 != 0) rolling.Fail("must be pairs of time and speed");
  for (std::size_t i = 0; i < rolling.Size(); i += 2) {
    o.rolling.push_back(
        {rolling.At(i).InRange(0.0, kMaxTime_s), rolling.At(i + 1).InRange(0.0, kMaxSpeed_mps)});
  }
  const ShardValue draw = v.At(4);
  if (draw.Size() != 6) draw.Fail("must be the 5 perturbations and the placement redraws");
  TrialDraw d{draw.At(0).InRange(-kMaxPlacement_m, kMaxPlacement_m),
              draw.At(1).InRange(-kMaxPlacement_m, kMaxPlacement_m),
              draw.At(2).InRange(-kPi, kPi),
              draw.At(3).InRange(kMinFactor, kMaxFactor),
              draw.At(4).InRange(kMinFactor, kMaxFactor),
              draw.At(5).IntInRange(0, kMaxPlacementDraws)};
  o.has_launch_offset = !v.At(5).IsNull();
  if (o.has_launch_offset) o.launch_offset_m = v.At(5).InRange(0.0, kMaxDistance_m);
  kick.observations.push_back(std::move(o));
  kick.draws.push_back(d);
  kick.trials.push_back(trial);
}

}  // namespace

nlohmann::json CalibrationShardResults(const PhysicsCalibration& calibration, const Shard& shard,
                                       int trials) {
  nlohmann::json items = nlohmann::json::array();
  std::vector<std::size_t> next(calibration.kicks.size(), 0);  // per kick, its next observation
  for (int k = 0; k < shard.OwnedCount(trials); ++k) {
    const int trial = shard.Item(k);
    nlohmann::json per_kick = nlohmann::json::array();
    for (std::size_t j = 0; j < calibration.kicks.size(); ++j) {
      const PhysicsKickTrials& kick = calibration.kicks[j];
      const std::size_t n = next[j];
      if (n < kick.trials.size() && kick.trials[n] == trial) {
        per_kick.push_back(TrialJson(kick.observations[n], kick.draws[n]));
        ++next[j];
      } else {
        const auto among = [trial](const std::vector<int>& trials) {
          return std::binary_search(trials.begin(), trials.end(), trial);
        };
        per_kick.push_back(among(kick.fell_trials)      ? nlohmann::json("fell")
                           : among(kick.blocked_trials) ? nlohmann::json("blocked")
                                                        : nlohmann::json(nullptr));  // missed
      }
    }
    items.push_back({{"trial", trial}, {"kicks", per_kick}});
  }
  return items;
}

void MergeCalibrationShards(PhysicsCalibration& plan, int trials,
                            const std::vector<ShardPart>& parts) {
  const int count = static_cast<int>(parts.size());
  for (int trial = 0; trial < trials; ++trial) {
    const ShardPart& part = parts[trial % count];  // ReadShardParts' order: shard i at i
    const ShardValue item = ResultsOf(part).At(static_cast<std::size_t>(trial / count));
    if (item["trial"].Int() != trial) item["trial"].Fail("must be " + std::to_string(trial));
    const ShardValue kicks = item["kicks"];
    if (kicks.Size() != plan.kicks.size()) kicks.Fail("must have one entry per kick");
    for (std::size_t j = 0; j < plan.kicks.size(); ++j) {
      if (kicks.At(j).IsNull()) {
        ++plan.kicks[j].missed;
      } else if (kicks.At(j).IsString()) {
        const std::string status = kicks.At(j).String();
        if (status == "fell") {
          ++plan.kicks[j].fell;
          plan.kicks[j].fell_trials.push_back(trial);
        } else if (status == "blocked") {
          ++plan.kicks[j].blocked;
          plan.kicks[j].blocked_trials.push_back(trial);
        } else {
          kicks.At(j).Fail("must be a trial, null, \"fell\" or \"blocked\"");
        }
      } else {
        ReadTrial(kicks.At(j), plan.kicks[j], trial);
      }
    }
  }
}

}  // namespace foresight
