#include "physics/impact_probe.h"

#include <algorithm>
#include <cmath>

#include "common/enum_names.h"
#include "physics/trial.h"

namespace foresight {

namespace {

constexpr EnumNames<ImpactTarget, 3> kTargetNames{{{
    {ImpactTarget::kPost, "post"},
    {ImpactTarget::kBackNet, "back_net"},
    {ImpactTarget::kSideNet, "side_net"},
}}};

// Where the target's surface is: a point on it, its outward normal n (towards the ball), and
// the clearance of a ball centred at p (negative: overlapping).
struct TargetFace {
  Vec2 p_F_surface;
  Vec2 n_F;
  double Clearance(const Vec2& p_F, double radius_m) const {
    return (p_F - p_F_surface).dot(n_F) - radius_m;
  }
};

TargetFace FaceOf(const PhysicsScene& scene, ImpactTarget target) {
  const GoalSpec& g = scene.field->goal;
  switch (target) {
    case ImpactTarget::kPost:  // the near post's front, on the line through its centre
      return {Vec2(g.post_centre_x_m - g.post_radius_m, g.post_centre_y_m), Vec2(-1.0, 0.0)};
    case ImpactTarget::kBackNet:  // from inside the goal, a little off its centre line
      return {Vec2(g.post_centre_x_m + g.net_depth_m, 0.1 * g.post_centre_y_m), Vec2(-1.0, 0.0)};
    case ImpactTarget::kSideNet:  // from outside, halfway along its depth
      return {Vec2(g.post_centre_x_m + 0.5 * g.net_depth_m,
                   g.post_centre_y_m + scene.params.materials.net_thickness_m),
              Vec2(0.0, 1.0)};
  }
  return {};
}

}  // namespace

std::string_view ImpactTargetName(ImpactTarget target) { return kTargetNames.Name(target); }
std::optional<ImpactTarget> ParseImpactTarget(std::string_view name) {
  return kTargetNames.Parse(name);
}
std::string ImpactTargetNames() { return kTargetNames.List(); }

double TargetRestitution(const PhysicsScene& scene, ImpactTarget target) {
  const BallPairs& e = scene.params.materials.restitution;
  return target == ImpactTarget::kPost ? e.post : e.net;
}

double GapAtPhase(const PhysicsScene& scene, double speed_mps, double phase) {
  constexpr double kBaseGapM = 0.01;
  return kBaseGapM + phase * speed_mps * NearTimeStep(scene.params.steps, speed_mps);
}

ImpactResult FireAt(const PhysicsScene& scene, ImpactTarget target, double speed_mps,
                    double gap_m) {
  const double r = scene.field->ball.radius_m;
  const TargetFace face = FaceOf(scene, target);
  const Vec2 start = face.p_F_surface + (r + gap_m) * face.n_F;
  const Vec2 n = face.n_F;
  const double heading = std::atan2(-n.y(), -n.x());
  const TrialResult trial = RunRollTrial(scene, RollingBall(start, r, speed_mps, heading), 1, true);
  ImpactResult result;
  result.touched = trial.outcome.first_contact != Contact::kNone;
  const double top_z = scene.field->goal.net_height_m;
  bool bounced = false;
  for (std::size_t i = 0; i < trial.trace.size(); ++i) {
    const TracePoint& p = trial.trace[i];
    if (p.p_F.z() > top_z) continue;  // over the goal: nothing to hit
    result.penetration_m = std::max(result.penetration_m, -face.Clearance(p.p_F.head<2>(), r));
    const double away_mps = p.v_F.head<2>().dot(n);
    if (!bounced && away_mps > 0.0 && i > 0) {
      bounced = true;
      result.rebound_mps = away_mps;
      result.approach_mps = -trial.trace[i - 1].v_F.head<2>().dot(n);
    }
  }
  if (!bounced && !trial.trace.empty()) {
    result.approach_mps = -trial.trace.back().v_F.head<2>().dot(n);
  }
  return result;
}

}  // namespace foresight
