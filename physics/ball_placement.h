// Whether the ball, where a trial puts it, lies clear of the kicking robot's body.
//
// A trial stands the robot so that the ball lies at the motion's nominal spot p_R_ball plus a drawn
// placement error (trial.h). The nominal spots lie just clear of the striking foot (the NAO's
// forward kick: 1.9 mm ahead of the toe's collision surface), so a normal error of 1 cm put the
// ball inside the foot in 42 % of the trials (up to 26 mm deep at the 3-sigma clip); two AIBO spots
// even lie inside the paw (forward 6.1 mm, pass 16.9 mm: 71 and 95 % of their draws overlap,
// docs/PHYSICS.md). Bullet pushed such a ball out before the kick. A robot that walks
// up to a ball cannot stand inside it: it touches the ball first. The placement error is therefore
// drawn conditional on the ball lying outside the body: a draw that puts the ball inside a link of
// the robot (standing in the kick's stance) is rejected and drawn again (trial.cc, DrawTrial), and
// the trial counts how many draws it rejected. Rejection keeps the error's shape outside the body
// instead of piling the rejected share up against the toe (as moving each such ball out to the
// surface would: a ball touching the foot at the start in 40 % of the trials is no robot's
// approach).
//
// The test asks Bullet: the ball's sphere against the robot's links, each placed by the
// project's forward kinematics (robot_kinematics.h) in the motion's stance, with Bullet's contact
// query (btCollisionWorld::contactPairTest; convex hulls keep their 1 mm collision margin, as in
// the trial). The ball's placement relative to the robot does not depend on the heading error
// (trial.cc turns the robot about the ball), so x and y in R decide.
#pragma once

#include <memory>
#include <span>

#include "common/geometry.h"
#include "models/robot_spec.h"

class btCollisionObject;

namespace foresight {

class BulletWorld;

class StanceClearance {
 public:
  // The robot in `motion`'s stance, its root frame R at the carpet's origin; the ball's radius.
  StanceClearance(const Robot& robot, const KickMotion& motion, double ball_radius_m);
  // The robot with joints at q_rad (model.joints order), R base_height_m above the carpet.
  StanceClearance(const Robot& robot, std::span<const double> q_rad, double base_height_m,
                  double ball_radius_m);
  ~StanceClearance();
  StanceClearance(const StanceClearance&) = delete;
  StanceClearance& operator=(const StanceClearance&) = delete;

  // How deep a ball lying on the carpet at p_R_ball (its centre's x, y in R) is inside the
  // robot's nearest link: 0 when it is clear (touching counts as clear).
  double DepthInsideM(const Vec2& p_R_ball) const;

 private:
  std::unique_ptr<BulletWorld> world_;
  double ball_radius_m_;
  btCollisionObject* body_ = nullptr;  // owned by world_
  btCollisionObject* ball_ = nullptr;
};

}  // namespace foresight
