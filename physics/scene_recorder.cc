#include "physics/scene_recorder.h"

#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include <cmath>

#include "physics/bullet_convert.h"
#include "physics/bullet_world.h"
#include "physics/kicking_robot.h"
#include "physics/robot_kinematics.h"

namespace foresight {

namespace {

ScenePose PoseOf(const Eigen::Isometry3d& pose_F) {
  return {pose_F.translation(), Eigen::Quaterniond(pose_F.linear()).normalized()};
}

const char* StaticName(BodyTag tag) {
  switch (tag) {
    case BodyTag::kBall:
      return "ball";
    case BodyTag::kPost:
      return "post";
    case BodyTag::kNet:
      return "net";
    case BodyTag::kObstacle:
      return "obstacle";
    default:
      return "carpet";
  }
}

}  // namespace

SceneRecorder::SceneRecorder(const PhysicsScene& scene, const KickMotion& motion, double rate_hz)
    : motion_(motion) {
  trace_.rate_hz = rate_hz;
  const RobotModel& model = scene.robot->model;
  for (const RobotLink& link : model.links) trace_.links.push_back(link.name);
  const int keyframes = static_cast<int>(motion.keyframes.size());
  for (int k = 1; k < keyframes; ++k) {
    trace_.phases.push_back("kick " + motion.name + ": to keyframe " + std::to_string(k) + " of " +
                            std::to_string(keyframes - 1));
  }
  stand_phase_ = static_cast<int>(trace_.phases.size());
  trace_.phases.push_back("kick " + motion.name + ": motion over, robot standing");
  roll_phase_ = static_cast<int>(trace_.phases.size());
  trace_.phases.push_back("roll: ball alone, robot no longer simulated");
  if (!scene.obstacle_poses.empty()) {
    const std::vector<Eigen::Isometry3d> pose_root_L = LinkPoses(model, scene.standing_q_rad);
    for (const Pose2& pose : scene.obstacle_poses) {
      const Eigen::Isometry3d pose_F_root = PlanarPose(
          pose.p_F.x(), pose.p_F.y(), scene.robot->spec.base_height_m, pose.theta_rad);
      std::vector<ScenePose>& links = trace_.obstacles.emplace_back();
      for (const Eigen::Isometry3d& p : pose_root_L) links.push_back(PoseOf(pose_F_root * p));
    }
  }
}

int SceneRecorder::KickPhase(double motion_t_s) const {
  const int keyframes = static_cast<int>(motion_.keyframes.size());
  for (int k = 1; k < keyframes; ++k) {
    if (motion_t_s <= motion_.keyframes[k].time_s) return k - 1;
  }
  return stand_phase_;
}

bool SceneRecorder::FrameDue(double t_s) const { return t_s >= next_frame_s_; }

void SceneRecorder::TakeFrame(double t_s, int phase, const btRigidBody* ball,
                              const KickingRobot* robot) {
  SceneFrame& frame = last_;
  frame.t_s = t_s;
  frame.phase = phase;
  frame.ball = PoseOf(ToEigen(ball->getWorldTransform()));
  frame.w_F_ball = ToEigen(ball->getAngularVelocity());
  frame.links.clear();
  last_taken_ = false;
  if (!FrameDue(t_s)) return;  // kept as the last step only: no link poses needed
  if (robot != nullptr) AddLinks(*robot, frame.links);
  trace_.frames.push_back(frame);
  last_taken_ = true;
  FlushContacts(t_s);
  next_frame_s_ = NextFrameTime(t_s);
}

double SceneRecorder::NextFrameTime(double t_s) const {
  // The next multiple of the frame interval after t_s (a long roll step may skip several).
  const double interval_s = 1.0 / trace_.rate_hz;
  return (std::floor(t_s / interval_s + 1e-9) + 1.0) * interval_s;
}

void SceneRecorder::AddLinks(const KickingRobot& robot, std::vector<ScenePose>& links) {
  robot.LinkPoses(poses_scratch_);
  for (const Eigen::Isometry3d& p : poses_scratch_) links.push_back(PoseOf(p));
}

void SceneRecorder::AddContacts(btDispatcher& dispatcher, const KickingRobot* robot) {
  const int manifolds = dispatcher.getNumManifolds();
  for (int i = 0; i < manifolds; ++i) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
    const btCollisionObject* bodies[2] = {manifold->getBody0(), manifold->getBody1()};
    const BodyTag tags[2] = {TagOf(*bodies[0]), TagOf(*bodies[1])};
    if (tags[0] == BodyTag::kCarpet || tags[1] == BodyTag::kCarpet) continue;
    Sum sum;
    for (int k = 0; k < manifold->getNumContacts(); ++k) {
      const btManifoldPoint& point = manifold->getContactPoint(k);
      // Only points that pushed: a foot resting against the ball after the strike touches it
      // for many frames without any impulse.
      const double impulse = point.getAppliedImpulse();
      if (impulse <= 0.0) continue;
      sum.impulse_Ns += impulse;
      sum.weighted_p_F += impulse * ToEigen(point.getPositionWorldOnB());
      sum.weight += impulse;
    }
    if (sum.weight == 0.0) continue;
    std::string names[2];
    for (int s = 0; s < 2; ++s) {
      const auto* link = btMultiBodyLinkCollider::upcast(bodies[s]);
      names[s] = tags[s] == BodyTag::kKicker && link != nullptr && robot != nullptr
                     ? robot->ContactLinkName(link->m_link)
                     : StaticName(tags[s]);
    }
    // The ball first, so that a pair has one key whichever body Bullet lists first.
    if (names[1] == "ball" || (names[0] != "ball" && names[1] < names[0])) std::swap(names[0], names[1]);
    Sum& total = pending_[{names[0], names[1]}];
    total.impulse_Ns += sum.impulse_Ns;
    total.weighted_p_F += sum.weighted_p_F;
    total.weight += sum.weight;
  }
}

void SceneRecorder::FlushContacts(double t_s) {
  for (const auto& [pair, sum] : pending_) {
    trace_.contacts.push_back(
        {t_s, pair.first, pair.second, sum.weighted_p_F / sum.weight, sum.impulse_Ns});
  }
  pending_.clear();
}

void SceneRecorder::ObserveKick(double t_s, double motion_t_s, const KickingRobot& robot,
                                const btRigidBody* ball, btDispatcher& dispatcher) {
  AddContacts(dispatcher, &robot);
  if (ball != nullptr) {
    TakeFrame(t_s, KickPhase(motion_t_s), ball, &robot);
    return;
  }
  // The ball was launched and rolls in the roll phase's world, which replays from the launch;
  // a robot standing on after it is kept aside and joined to the roll's frames by time.
  if (t_s < next_standing_s_) return;
  SceneFrame& frame = standing_.emplace_back();
  frame.t_s = t_s;
  AddLinks(robot, frame.links);
  next_standing_s_ = NextFrameTime(t_s);
}

void SceneRecorder::ObserveRoll(double t_s, const btRigidBody& ball, btDispatcher& dispatcher) {
  AddContacts(dispatcher, nullptr);
  TakeFrame(t_s, roll_phase_, &ball, nullptr);
}

SceneTrace SceneRecorder::Finish() {
  if (!last_taken_) {
    trace_.frames.push_back(last_);
    FlushContacts(last_.t_s);
  }
  last_taken_ = true;
  // Each roll frame gets the robot as it stood at that time (the latest standing frame before).
  std::size_t s = 0;
  for (SceneFrame& frame : trace_.frames) {
    if (!frame.links.empty() || standing_.empty() || frame.t_s < standing_.front().t_s) continue;
    while (s + 1 < standing_.size() && standing_[s + 1].t_s <= frame.t_s) ++s;
    frame.links = standing_[s].links;
  }
  return std::move(trace_);
}

}  // namespace foresight
