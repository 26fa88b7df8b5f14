// The opponents' configurations and the scenarios of the passing experiment (Ros et al. 2009,
// sec. 5.1.2-5.1.4, Figs. 11 and 12), read from models/match/<config>.json and
// models/match/scenarios/*.json.
//
// Everything is written for attackers that attack the goal at +x (the yellow one; cyan is at
// -x) and opponents that defend it; Mirrored() gives the same game towards the other goal.
//
// A configuration: the opponents (a role, "goalie" or "defender", and a home region: a box the
// robot's centre never leaves), the end rules (a goalie's touch ends the trial as "block"; in 2D
// the ball entering the penalty area ends it as "to goal"; the time limit), the default number
// of trials and the scenario files. A scenario: the ball, the two attackers' poses (A, B) and
// every opponent's pose, which must lie in its home region.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/geometry.h"
#include "match/match_params.h"
#include "models/field_box.h"
#include "models/field_spec.h"

namespace foresight {

enum class OpponentRole : std::uint8_t { kGoalie, kDefender };

struct OpponentSpec {
  std::string name;  // "D", "G", "MD"
  OpponentRole role = OpponentRole::kDefender;
  FieldBox region;
};

struct Scenario {
  std::string name;
  Vec2 p_F_ball{0.0, 0.0};
  std::vector<Pose2> attackers;  // A, B
  std::vector<Pose2> opponents;  // in the configuration's order
};

// Which goalie plays. kRos2009: the paper's (sec. 5.1.2: every opponent, the goalie included,
// stays in its home region, goes for a ball inside it and clears it, and otherwise stands at the
// region's boundary facing the ball; match/opponent_team.h). kRunswift2005: rUNSWift 2005's
// competition goalie (match/goalie.h), a stronger keeper.
enum class GoalieModel : std::uint8_t { kRos2009, kRunswift2005 };
std::string_view GoalieModelName(GoalieModel model);  // "ros2009", "runswift2005"
// The model called `name`, or nothing.
std::optional<GoalieModel> GoalieModelNamed(std::string_view name);

// How the goalie plays. `model` chooses it; the figures below are the rUNSWift goalie's
// (match/goalie.h): it sees the ball latency_s late (vision and decision), stands on the line
// from the ball to its goal's centre guard_distance_m in front of the goal line (as far as its
// region allows), walks there at most at walk_speed_mps, and blocks a ball its block would stop
// that arrives within block_earliest_s, at most once every block_refractory_s.
struct GoalieParams {
  GoalieModel model = GoalieModel::kRos2009;
  double latency_s = 0.0;
  double guard_distance_m = 0.0;
  double walk_speed_mps = 0.0;
  double block_earliest_s = 0.0;
  double block_refractory_s = 0.0;
};

struct MatchConfig {
  std::filesystem::path file;
  std::string name;  // "dg", "2d"
  std::vector<OpponentSpec> opponents;
  std::string clear_kick;  // the kick the opponents clear the ball with
  // Kicks a defender may clear with when they send the ball away from its goal without turning
  // (e.g. head kicks to the side for a defender facing its own goal).
  std::vector<std::string> clear_side_kicks;
  // A clearance's mean direction keeps this many of its kick's direction sd inside the half of
  // the plane away from the defender's own goal.
  double clear_direction_margin_sd = 0.0;
  // A holder turns with the ball while a body stands within clear_free_distance_m and
  // clear_free_cone_rad of its kick's line (at most until the ball-holding rule makes it kick).
  double clear_free_distance_m = 0.0;
  double clear_free_cone_rad = 0.0;
  bool penalty_area_ends_trial = false;
  double time_limit_s = 0.0;
  // true: the time limit is only a safety cap the paper's protocol does not have (DG: "no
  // timeout"); reports count the trials it ended apart. false: the paper's timeout (2D).
  bool time_limit_is_safety_cap = false;
  GoalieParams goalie;  // read when an opponent is a goalie
  int default_trials = 0;
  std::vector<Scenario> scenarios;  // scenario 1..n in order

  // Checks the regions against the penalty area (defenders keep their whole body out of it,
  // a goalie's centre stays in it) and every scenario's opponents against their regions.
  void Validate(const FieldSpec& field, const SimulationParams& sim,
                const RobotParams& robot) const;
  // The same configuration for attackers attacking the goal at -x: every x negated and every
  // heading mirrored, y kept (a mirror in the y axis).
  MatchConfig Mirrored() const;
  bool HasGoalie() const;
  // The opponents' names in order ("D", "G"): how reports name them.
  std::vector<std::string> OpponentNames() const;
};

// `reference` is a bare name in MODELS/match/ ("dg") or a path ending in ".json"; scenario
// references inside are resolved from the config file's folder.
MatchConfig LoadMatchConfig(const std::string& reference, const std::filesystem::path& models_dir,
                            const FieldSpec& field, const SimulationParams& sim,
                            const RobotParams& robot);

// The penalty area of the goal at x = sign * half length: the box x in [half - depth, half],
// |y| <= half width (mirrored for sign -1).
FieldBox PenaltyArea(const FieldSpec& field, const SimulationParams& sim, double sign);

}  // namespace foresight
