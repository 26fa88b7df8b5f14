#include "physics/physics_scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "physics/bullet_convert.h"
#include "physics/carpet.h"
#include "physics/robot_kinematics.h"
#include "physics/robot_shapes.h"

namespace foresight {

namespace {

// How far an obstacle robot's collision shapes reach beyond its links' origins (feet, arms).
constexpr double kObstacleReachMarginM = 0.15;

double ObstacleReach(const PhysicsScene& scene) {
  const std::vector<Eigen::Isometry3d> poses = LinkPoses(scene.robot->model, scene.standing_q_rad);
  double reach = 0.0;
  for (const Eigen::Isometry3d& pose : poses)
    reach = std::max(reach, pose.translation().head<2>().norm());
  return reach + kObstacleReachMarginM;
}

void AddGoal(BulletWorld& world, const PhysicsScene& scene, double side) {
  const GoalSpec& g = scene.field->goal;
  const MaterialParams& m = scene.params.materials;
  const double t = m.net_thickness_m;
  const double h = g.net_height_m;
  const Material post{m.restitution.post, m.friction.post};
  const Material net{m.restitution.net, m.friction.net};
  auto* post_shape = world.Own(
      std::make_unique<btCylinderShapeZ>(btVector3(g.post_radius_m, g.post_radius_m, 0.5 * h)));
  for (double y_side : {1.0, -1.0}) {
    const btVector3 p(side * g.post_centre_x_m, y_side * g.post_centre_y_m, 0.5 * h);
    world.AddStatic(post_shape, btTransform(btQuaternion::getIdentity(), p), BodyTag::kPost, post);
  }
  auto* bar_shape = world.Own(std::make_unique<btCylinderShape>(
      btVector3(g.post_radius_m, g.post_centre_y_m, g.post_radius_m)));
  world.AddStatic(
      bar_shape,
      btTransform(btQuaternion::getIdentity(), btVector3(side * g.post_centre_x_m, 0, h)),
      BodyTag::kPost, post);
  const double x_mid = side * (g.post_centre_x_m + 0.5 * g.net_depth_m);
  auto* side_shape =
      world.Own(std::make_unique<btBoxShape>(btVector3(0.5 * g.net_depth_m, 0.5 * t, 0.5 * h)));
  for (double y_side : {1.0, -1.0}) {
    const btVector3 p(x_mid, y_side * (g.post_centre_y_m + 0.5 * t), 0.5 * h);
    world.AddStatic(side_shape, btTransform(btQuaternion::getIdentity(), p), BodyTag::kNet, net);
  }
  auto* back_shape =
      world.Own(std::make_unique<btBoxShape>(btVector3(0.5 * t, g.post_centre_y_m + t, 0.5 * h)));
  const double x_back = side * (g.post_centre_x_m + g.net_depth_m + 0.5 * t);
  world.AddStatic(back_shape,
                  btTransform(btQuaternion::getIdentity(), btVector3(x_back, 0, 0.5 * h)),
                  BodyTag::kNet, net);
  auto* roof_shape = world.Own(
      std::make_unique<btBoxShape>(btVector3(0.5 * g.net_depth_m, g.post_centre_y_m, 0.5 * t)));
  world.AddStatic(roof_shape,
                  btTransform(btQuaternion::getIdentity(), btVector3(x_mid, 0, h + 0.5 * t)),
                  BodyTag::kNet, net);
}

}  // namespace

PhysicsScene MakePhysicsScene(const FieldSpec& field, const PhysicsParams& params,
                              const Robot* robot, const std::vector<Obstacle>& obstacles,
                              const Vec2& p_F_ball, const SettledStances* settled) {
  PhysicsScene scene;
  scene.field = &field;
  scene.params = params;
  scene.lines = FieldLines::Of(field);
  scene.robot = robot;
  if (robot != nullptr) {
    scene.standing_q_rad = robot->StandingPositions();
    scene.settled_stances = settled != nullptr ? *settled : SettleStances(*robot, params);
  }
  const GoalSpec& g = field.goal;
  const double r = field.ball.radius_m;
  const double t = params.materials.net_thickness_m;
  for (double side : {1.0, -1.0}) {
    const double half_depth = 0.5 * g.net_depth_m + g.post_radius_m + t;
    scene.near_zones.push_back(
        {Vec2(side * (g.post_centre_x_m + 0.5 * g.net_depth_m), 0.0),
         std::hypot(half_depth, g.post_centre_y_m + g.post_radius_m + t) + r});
  }
  if (!obstacles.empty()) {
    assert(robot != nullptr);
    const double reach = ObstacleReach(scene);
    for (const Obstacle& o : obstacles) {
      const Vec2 to_ball = p_F_ball - o.p_F;
      const double heading =
          to_ball.squaredNorm() > 0.0 ? std::atan2(to_ball.y(), to_ball.x()) : 0.0;
      scene.obstacle_poses.push_back(Pose2{o.p_F, heading});
      scene.near_zones.push_back({o.p_F, reach + r});
    }
  }
  return scene;
}

void AddStatics(BulletWorld& world, const PhysicsScene& scene) {
  const MaterialParams& m = scene.params.materials;
  AddCarpetPlane(world, m);
  AddGoal(world, scene, 1.0);
  AddGoal(world, scene, -1.0);
  if (scene.obstacle_poses.empty()) return;
  const std::vector<Eigen::Isometry3d> poses = LinkPoses(scene.robot->model, scene.standing_q_rad);
  btCompoundShape* shape = MakeRobotShape(world, scene.robot->model, poses);
  const Material material{m.restitution.robot, m.friction.robot};
  for (const Pose2& pose : scene.obstacle_poses) {
    const Eigen::Isometry3d pose_F_root =
        PlanarPose(pose.p_F.x(), pose.p_F.y(), scene.robot->spec.base_height_m, pose.theta_rad);
    world.AddStatic(shape, ToBt(pose_F_root), BodyTag::kObstacle, material);
  }
}

bool WithinCarpet(const PhysicsScene& scene, const Vec2& p_F) {
  return std::abs(p_F.x()) <= 0.5 * scene.field->carpet_length_m &&
         std::abs(p_F.y()) <= 0.5 * scene.field->carpet_width_m;
}

double NearTimeStep(const StepParams& steps, double speed_mps) {
  // Contacts are solved once the ball overlaps (no speculative contacts), so a step may carry it
  // speed * dt into a post or a net before it bounces.
  return std::min(steps.near_time_step_s, steps.max_overlap_m / std::max(speed_mps, 1e-9));
}

double RollTimeStep(const PhysicsScene& scene, const Vec2& p_F, double speed_mps, bool on_carpet) {
  const StepParams& steps = scene.params.steps;
  const double near_step = NearTimeStep(steps, speed_mps);
  if (!on_carpet) return near_step;
  // Within one large step the ball moves speed * dt; keep a ball length of margin on top.
  const double reach = speed_mps * steps.free_time_step_s + 2.0 * scene.field->ball.radius_m;
  for (const NearZone& zone : scene.near_zones) {
    if ((p_F - zone.centre).norm() < zone.radius_m + reach) return near_step;
  }
  return speed_mps < steps.slow_speed_mps ? steps.slow_time_step_s : steps.free_time_step_s;
}

}  // namespace foresight
