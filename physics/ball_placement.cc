#include "physics/ball_placement.h"

#include <algorithm>

#include "physics/bullet_convert.h"
#include "physics/bullet_world.h"
#include "physics/robot_kinematics.h"
#include "physics/robot_shapes.h"

namespace foresight {

namespace {

// The deepest overlap Bullet reports between the two objects (0 if none).
struct DeepestOverlap : btCollisionWorld::ContactResultCallback {
  double depth_m = 0.0;
  btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper*, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    depth_m = std::max(depth_m, -static_cast<double>(point.getDistance()));
    return 0;
  }
};

}  // namespace

StanceClearance::StanceClearance(const Robot& robot, const KickMotion& motion, double ball_radius_m)
    : StanceClearance(robot, robot.StandingPositions(motion), robot.BaseHeightM(motion),
                      ball_radius_m) {}

StanceClearance::StanceClearance(const Robot& robot, std::span<const double> q_rad,
                                 double base_height_m, double ball_radius_m)
    : world_(std::make_unique<BulletWorld>(BulletWorld::Kind::kRigid, SolverSettings{})),
      ball_radius_m_(ball_radius_m) {
  const std::vector<Eigen::Isometry3d> poses = LinkPoses(robot.model, q_rad);
  btCompoundShape* body = MakeRobotShape(*world_, robot.model, poses);
  body_ = world_->AddStatic(body, ToBt(PlanarPose(0.0, 0.0, base_height_m, 0.0)), BodyTag::kKicker,
                            Material{});
  auto* ball_shape = world_->Own(std::make_unique<btSphereShape>(ball_radius_m));
  ball_ = world_->AddStatic(ball_shape, btTransform::getIdentity(), BodyTag::kBall, Material{});
}

StanceClearance::~StanceClearance() = default;

double StanceClearance::DepthInsideM(const Vec2& p_R_ball) const {
  ball_->setWorldTransform(btTransform(btQuaternion::getIdentity(),
                                       btVector3(p_R_ball.x(), p_R_ball.y(), ball_radius_m_)));
  DeepestOverlap overlap;
  world_->world().contactPairTest(ball_, body_, overlap);
  return overlap.depth_m;
}

}  // namespace foresight
