// The seam between the coarse model (planner/) and physics (physics/): an OutcomeSimulator is
// built for one static scene (field, obstacles, carpet) and takes one concrete state (a drawn
// robot pose and ball position) and one
// concrete action (a kick, a rotation around the ball, a drawn launch) and says where the ball
// comes to rest, how that counts, when, and what it touched first. Evaluation, decision and
// fidelity are written once against this interface.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "common/geometry.h"
#include "models/field_spec.h"
#include "models/situation.h"

namespace foresight {

// How a simulated kick ends (the first field boundary the ball's path crosses decides).
enum class Category : std::uint8_t { kInfield, kOppGoal, kOwnGoal, kOut };
inline constexpr int kCategoryCount = 4;

// The first thing the ball touched; kNone when it stopped by rolling resistance.
enum class Contact : std::uint8_t { kNone, kPost, kNet, kObstacle, kRobot };
inline constexpr int kContactCount = 5;

// Whether the outcome is what the action asked for. A physics trial can go wrong in ways the
// coarse model cannot: the robot's foot missed the ball (it then lies where it was), the
// ball did not come to rest within the time limit (it is reported where it was then), or the
// robot, standing on its own feet, fell during the kick (the ball is reported where it rested), or
// it could not take its stance at all because a post, net or obstacle robot stood where it must
// (blocked: the kick was not played and the ball lies untouched). Such outcomes still count as what
// physically happened; the status lets a reader count them. New statuses go at the end: files
// store a status by its index (report/shard_file.h) and Python by its code.
enum class OutcomeStatus : std::uint8_t { kOk, kMissed, kNotSettled, kFell, kBlocked };
inline constexpr int kOutcomeStatusCount = 5;

std::string_view CategoryName(Category category);
std::string_view ContactName(Contact contact);
std::string_view OutcomeStatusName(OutcomeStatus status);
std::optional<OutcomeStatus> ParseOutcomeStatus(std::string_view name);  // nullopt: no status

// The static scene a simulator is built for. Non-owning: the field and obstacles must outlive it.
struct Scene {
  const FieldSpec* field = nullptr;
  std::span<const Obstacle> obstacles;
  double rolling_deceleration_mps2 = 0.0;
  CoarseRebounds rebounds;  // the coarse model's contacts (physics has its own materials)
};

// One drawn state: where the kicking robot stands and where the ball lies, both in F.
struct DrawnState {
  Pose2 robot;
  Vec2 p_F_ball{0.0, 0.0};
};

// One concrete action. kick_index == kNoKick (models/kick_model.h) is the `none` action (the ball
// stays). The robot first turns around the ball by rotation_rad (the ball stays put, the robot's
// heading changes by it), then kicks. launch_* are the coarse model's drawn launch in the turned
// robot frame (and the kick's launch offset, models/kick_model.h); a physics simulator ignores them
// and draws its physical perturbations from `stream` instead.
struct ConcreteAction {
  int kick_index = kNoKick;
  double rotation_rad = 0.0;
  double launch_speed_mps = 0.0;
  double launch_direction_rad = 0.0;
  double launch_offset_m = 0.0;  // the kick's: free rolling starts this far along the launch
  std::uint64_t stream = 0;
};

struct Outcome {
  Vec2 p_F_rest{0.0, 0.0};
  Category category = Category::kInfield;
  Contact first_contact = Contact::kNone;
  double time_s = 0.0;  // from the launch until the ball rests
  OutcomeStatus status = OutcomeStatus::kOk;
};

// Whether two outcomes are the same bit for bit (doubles by their bits, models/outcome.cc checks
// at compile time that every field is compared): a trial played again must give its bytes.
bool SameBits(const Outcome& a, const Outcome& b);

// How many of a set of outcomes ended with each status (physics trials that missed the ball or
// did not settle are counted, not dropped: a reader must see them).
struct StatusCounts {
  int missed = 0;
  int not_settled = 0;
  int fell = 0;     // the kicking robot fell (a floating base)
  int blocked = 0;  // the kicking robot could not take its stance (a floating base)
  void Add(const StatusCounts& other);
};
StatusCounts CountStatuses(std::span<const Outcome> outcomes);
// "2 missed the ball, 0 did not settle, 0 fell, 1 blocked"
std::string StatusCountsText(const StatusCounts& counts);

class OutcomeSimulator {
 public:
  virtual ~OutcomeSimulator() = default;
  // Must be safe to call concurrently from several threads.
  virtual Outcome Simulate(const DrawnState& state, const ConcreteAction& action) const = 0;
};

}  // namespace foresight
