#include "cbr/case_reach.h"

#include <cstdio>

#include "cbr/own_situation.h"
#include "common/enum_names.h"
#include "common/error.h"
#include "planner/kick_reach.h"

namespace foresight {
namespace {

constexpr EnumNames<ReachFault, 2> kFaultNames{{{
    {ReachFault::kBeyondReach, "beyond_reach"},
    {ReachFault::kPassShort, "pass_short"},
}}};

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
