// A ball fired head-on at a part of the goal, and what the impact did: how deep the ball got
// into the part (tunnelling) and how fast it came back (restitution). The `rebound` and
// `no_tunnelling` checks and the contact tests use it.
//
// The ball rolls along the part's inward normal n from `gap_m` in front of it; the phase of the
// contact within a time step is set by the gap. Rebound ratio = the normal speed just after the
// first step in which the ball moves away, over the normal speed just before: the contact's
// coefficient of restitution as realised by the solver (materials say what it should be).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "physics/physics_scene.h"

namespace foresight {

enum class ImpactTarget { kPost, kBackNet, kSideNet };
// "post", "back_net", "side_net": the check spec's words.
std::string_view ImpactTargetName(ImpactTarget target);
std::optional<ImpactTarget> ParseImpactTarget(std::string_view name);
std::string ImpactTargetNames();  // "post, back_net, side_net"

struct ImpactResult {
  double penetration_m = 0.0;   // deepest overlap with the target over the whole trial
  double approach_mps = 0.0;    // normal speed into the target just before the bounce
  double rebound_mps = 0.0;     // normal speed away from it just after (0: it did not bounce)
  bool touched = false;         // the trial reported a contact with a post or net
};

// The restitution the scene's materials give the ball against `target`.
double TargetRestitution(const PhysicsScene& scene, ImpactTarget target);

// The start gap that puts the contact at `phase` (in [0, 1)) of the near time step at this speed:
// 1 cm plus that share of one step's travel.
double GapAtPhase(const PhysicsScene& scene, double speed_mps, double phase);

ImpactResult FireAt(const PhysicsScene& scene, ImpactTarget target, double speed_mps, double gap_m);

}  // namespace foresight
