#include "cbr/case_reach.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cbr/own_situation.h"
#include "common/enum_names.h"
#include "common/geometry.h"
#include "common/error.h"
#include "planner/kick_reach.h"

namespace foresight {
namespace {

constexpr EnumNames<ReachFault, 3> kFaultNames{{{
    {ReachFault::kBeyondReach, "beyond_reach"},
    {ReachFault::kPassShort, "pass_short"},
    {ReachFault::kLeavesField, "leaves_field"},
}}};

// How far beyond a side line the ball rests when kick `t` is launched z sd of direction to either
// side of its aim and rolls its mean roll (<= 0: inside the field).
double BeyondSideLine(const FuzzyTrajectory& t, const KickSpec& spec, double mean_roll_m, double z,
                      double half_width_m) {
  const double aim = std::atan2(t.u.y(), t.u.x());
  const double spread = z * spec.sigma_direction_rad;
  // |y| is largest at an end of the spread, or at +-90 deg when the spread holds it.
  double out = -half_width_m;
  for (double direction : {aim - spread, aim + spread, kPi / 2.0, -kPi / 2.0}) {
    if (std::abs(WrapAngle(direction - aim)) > spread + 1e-12) continue;
    const double y = t.start_F.y() + mean_roll_m * std::sin(direction);
    out = std::max(out, std::abs(y) - half_width_m);
  }
  return out;
}

}  // namespace

std::string_view ReachFaultName(ReachFault fault) {
  return kFaultNames.Name(fault);
}

std::vector<ReachFinding> CheckCaseReach(const Case& c, const KickModel& kicks,
                                         const RetrievalParams& params) {
  if (!params.reach_sigmas) {
    throw InputError("reach_sigmas: the retrieval parameters must set it to check kick reach");
  }
  RetrievalParams to_targets = params;  // the lengths the case asks for: no cut
  to_targets.default_kick.reach_m = 0.0;
  for (KickTrajectory& k : to_targets.kicks) k.reach_m = 0.0;
  const double a = kicks.rolling_deceleration_mps2;
  const double contact_m = params.opponent_radius_m + params.ball_radius_m;
  std::vector<ReachFinding> out;
  const CaseBallPath path = OwnBallPath(c, to_targets);
  for (int i = 0; i < path.count; ++i) {
    const FuzzyTrajectory& t = path.trajectories[static_cast<std::size_t>(i)];
    const KickSpec& spec =
        kicks.kicks[static_cast<std::size_t>(kicks.Find(t.kick->kick).value())];
    ReachFinding f;
    f.trajectory = i;
    f.action = t.action;
    f.kick = spec.name;
    f.length_m = t.length_m;
    f.mean_roll_m = MeanRollDistance(spec, a);
    f.reach_m = RollDistanceAtSigmas(spec, a, *params.reach_sigmas);
    if (f.length_m > f.reach_m) {
      f.fault = ReachFault::kBeyondReach;
      out.push_back(f);
    } else if (t.action == ActionType::kPass && f.length_m - contact_m > f.mean_roll_m) {
      f.fault = ReachFault::kPassShort;
      out.push_back(f);
    } else if (t.action == ActionType::kKick && !IsShot(*t.kick, params.goal_x_m)) {
      f.out_m = BeyondSideLine(t, spec, f.mean_roll_m, *params.reach_sigmas, params.half_width_m);
      if (f.out_m > 0.0) {
        f.fault = ReachFault::kLeavesField;
        out.push_back(f);
      }
    }
  }
  return out;
}

std::string DescribeFinding(const ReachFinding& f, const RetrievalParams& params) {
  const double contact_m = params.opponent_radius_m + params.ball_radius_m;
  char text[256];
  if (f.fault == ReachFault::kBeyondReach) {
    std::snprintf(text, sizeof text,
                  "%s %s (trajectory %d) of %.2f m is beyond the kick's reach %.2f m at %g sd "
                  "(mean roll %.2f m)",
                  std::string(ActionTypeName(f.action)).c_str(), f.kick.c_str(), f.trajectory,
                  f.length_m, f.reach_m, params.reach_sigmas.value_or(0.0), f.mean_roll_m);
  } else if (f.fault == ReachFault::kLeavesField) {
    std::snprintf(text, sizeof text,
                  "kick %s (trajectory %d): launched %g sd of its direction off its aim, its mean "
                  "roll %.2f m rests %.2f m beyond the side line",
                  f.kick.c_str(), f.trajectory, params.reach_sigmas.value_or(0.0), f.mean_roll_m,
                  f.out_m);
  } else {
    std::snprintf(text, sizeof text,
                  "pass %s (trajectory %d) of %.2f m: the mean roll %.2f m stops %.2f m short "
                  "of the receiver's body",
                  f.kick.c_str(), f.trajectory, f.length_m, f.mean_roll_m,
                  f.length_m - contact_m - f.mean_roll_m);
  }
  return text;
}

}  // namespace foresight
