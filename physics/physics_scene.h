// The immutable model of one physics scene (the MuJoCo split: this is the model, each trial
// builds its own Bullet world from it): field, carpet and materials, the robot type, and the
// other robots standing as static obstacles.
//
// Goals in F (for the goal at side s = +1 opponent, -1 own): posts are z-axis cylinders of
// post_radius at (s * post_centre_x, +-post_centre_y) up to net_height; the crossbar joins their
// tops; the side nets, the back net and the roof are boxes of net_thickness whose inner faces lie
// on the coarse model's net lines (y = +-post_centre_y, x = s * (post_centre_x + net_depth)).
#pragma once

#include <optional>
#include <vector>

#include "models/field_lines.h"
#include "models/field_spec.h"
#include "models/physics_params.h"
#include "models/robot_spec.h"
#include "models/situation.h"
#include "physics/settled_stance.h"

namespace foresight {

class BulletWorld;  // physics/bullet_world.h; Bullet stays private to physics/

// A circle in the carpet's plane; inside it the ball rolls with the small time step.
struct NearZone {
  Vec2 centre{0.0, 0.0};
  double radius_m = 0.0;
};

struct PhysicsScene {
  const FieldSpec* field = nullptr;
  PhysicsParams params;
  FieldLines lines;
  const Robot* robot = nullptr;        // the kicking robot's type; obstacles are of it too
  std::vector<Pose2> obstacle_poses;   // robots standing still, root frame on the carpet
  std::vector<NearZone> near_zones;    // goals and obstacles, grown by the ball's radius
  std::vector<double> standing_q_rad;  // the robot's standing joint positions
  // Per robot motion, on a floating base, the stance after the motion's weight shift
  // (settled_stance.h); empty for a fixed base and for motions without a balance.
  SettledStances settled_stances;
  // The carpet ends (field.carpet_length_m x carpet_width_m) where boards stop a real ball: a
  // trial ends when the ball's centre leaves it, the ball resting there (it crossed a line, so
  // it is out or in a goal already). The engine checks roll on an unbounded carpet instead.
  bool carpet_has_edge = true;
};

// Whether the ball's centre at p_F lies on the carpet.
bool WithinCarpet(const PhysicsScene& scene, const Vec2& p_F);

// Builds the scene of a situation: the obstacles stand where the situation puts them, facing
// the ball. `robot` may be null when the situation has no obstacles and no kick is simulated.
// The robot's settled stances (floating base) are computed here unless `settled` gives them
// (SettleStances of the same robot and params: a caller building many scenes settles once).
PhysicsScene MakePhysicsScene(const FieldSpec& field, const PhysicsParams& params,
                              const Robot* robot, const std::vector<Obstacle>& obstacles,
                              const Vec2& p_F_ball, const SettledStances* settled = nullptr);

// Adds carpet, goals and obstacle robots to a world.
void AddStatics(BulletWorld& world, const PhysicsScene& scene);

// The step near posts, nets and robots for a ball moving at speed_mps: near_time_step_s, or
// shorter so that one step carries the ball at most max_overlap_m into what it hits.
double NearTimeStep(const StepParams& steps, double speed_mps);

// Time step for a ball at p_F moving at speed_mps (3D): small near goals and obstacles (and in
// the air), and there short enough that the ball overlaps a post or net by at most
// steps.max_overlap_m before it bounces; large on open carpet.
double RollTimeStep(const PhysicsScene& scene, const Vec2& p_F, double speed_mps, bool on_carpet);

}  // namespace foresight
