// How close the kick motions take the robots to the carpet (physics/motion_clearance.h): the
// lowest point of each shape kind against its closed form, and every shipped motion's clearance.
#include "physics/motion_clearance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/geometry.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

RobotLink LinkWith(const RobotShape& shape) {
  RobotLink link;
  link.collisions.push_back(shape);
  return link;
}

Eigen::Isometry3d At(double z_m, double pitch_rad) {
  Eigen::Isometry3d pose(Eigen::Translation3d(0.3, -0.2, z_m));
  pose.rotate(Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()));
  return pose;
}

TEST(LowestPointTest, ShapesMatchTheirClosedForms) {
  const double pitch = 30.0 * kDegToRad;
  RobotShape sphere;
  sphere.kind = RobotShape::Kind::kSphere;
  sphere.radius_m = 0.05;
  EXPECT_NEAR(LowestPointZ(LinkWith(sphere), At(0.2, pitch)), 0.15, 1e-12);

  // A 0.2 x 0.1 x 0.4 box pitched 30 deg: its corners reach 0.1 sin 30 + 0.2 cos 30 down.
  RobotShape box;
  box.kind = RobotShape::Kind::kBox;
  box.box_size_m = Eigen::Vector3d(0.2, 0.1, 0.4);
  EXPECT_NEAR(LowestPointZ(LinkWith(box), At(0.5, pitch)),
              0.5 - 0.1 * std::sin(pitch) - 0.2 * std::cos(pitch), 1e-12);

  // A cylinder (radius 0.05, length 0.4) pitched 30 deg: cap L/2 cos 30 plus rim r sin 30.
  RobotShape cylinder;
  cylinder.kind = RobotShape::Kind::kCylinder;
  cylinder.radius_m = 0.05;
  cylinder.length_m = 0.4;
  EXPECT_NEAR(LowestPointZ(LinkWith(cylinder), At(0.5, pitch)),
              0.5 - 0.2 * std::cos(pitch) - 0.05 * std::sin(pitch), 1e-12);

  // The shape's own origin in the link counts: a sphere 0.1 below the link frame.
  sphere.pose_L_S = Eigen::Translation3d(0.0, 0.0, -0.1);
  EXPECT_NEAR(LowestPointZ(LinkWith(sphere), At(0.2, 0.0)), 0.05, 1e-12);
}

// A motion that straightens the AIBO's right front knee from the stance (122 deg) to 0: with
// the rotator at 50 deg the lower leg points straight down when the knee passes 50 deg, and the
// paw then reaches 4 cm below the carpet. The targets follow 122 - 122 (3 s^2 - 2 s^3) (zero
// speed at both ends, models/kick_motion.h), so the knee passes 50 deg at t = 0.561 s; the paw's
// centre lies 4.41 deg off the lower leg's line, so its lowest point comes between the knee at
// 54.4 and 45.6 deg, 0.536 and 0.585 s.
TEST(MotionClearanceTest, FindsAPawDrivenIntoTheCarpet) {
  const Robot robot = LoadRobot("aibo_ers7", testing::ModelsDir());
  KickMotion motion;
  motion.joints = {"rf_j3"};
  motion.keyframes = {{0.0, {122.0 * kDegToRad}}, {1.0, {0.0}}};
  const MotionClearance clearance = FindMotionClearance(robot, motion);
  EXPECT_EQ(robot.model.links[clearance.link].name, "rf_lower");
  EXPECT_GT(clearance.t_s, 0.536);
  EXPECT_LT(clearance.t_s, 0.585);
  EXPECT_LT(clearance.lowest_m, -0.03);
  // Standing still: the paws rest on the carpet (robot.json's base height).
  motion.keyframes = {{0.0, {122.0 * kDegToRad}}, {1.0, {122.0 * kDegToRad}}};
  EXPECT_NEAR(FindMotionClearance(robot, motion).lowest_m, 0.0, 5e-4);
}

// Every shipped motion keeps the body above the carpet (within 1 mm, the meshes' facets). Three
// once did not (found in issue 12's fifth pass: the NAO's `forward` 34 mm and `forward_long` 19 mm
// below it, the AIBO's `forward` 58 mm), which the fixed-base scene let them do, so their
// launches were not ones a real robot could make; all three were redone standing up
// (docs/PHYSICS.md, "Kicks through the carpet" and "The NAO's kicks above the
// carpet").
TEST(MotionClearanceTest, ShippedMotionsStayAboveTheCarpet) {
  for (const char* robot_name : {"nao", "aibo_ers7"}) {
    const Robot robot = LoadRobot(robot_name, testing::ModelsDir());
    for (const KickMotion& motion : robot.motions) {
      const MotionClearance clearance = FindMotionClearance(robot, motion);
      EXPECT_GT(clearance.lowest_m, -0.001)
          << robot_name << " " << motion.name << " at " << clearance.t_s << " s, "
          << clearance.link_name;
    }
  }
}

// The swing's clearance leaves out what the motion does not move: the NAO's forward kick stands
// on its left sole (the body's lowest point is on the carpet) while the right foot swings at
// least 5 mm above it (the motion's notes).
TEST(MotionClearanceTest, SwingClearanceCountsOnlyTheLinksTheMotionMoves) {
  const Robot robot = LoadRobot("nao", testing::ModelsDir());
  const KickMotion& forward = robot.motions[*robot.FindMotion("forward")];
  EXPECT_NEAR(FindMotionClearance(robot, forward).lowest_m, 0.0, 1e-3);
  const MotionClearance swing = FindSwingClearance(robot, forward);
  EXPECT_GT(swing.lowest_m, 0.0045);
  EXPECT_LT(swing.lowest_m, 0.05);
  EXPECT_EQ(swing.link_name.front(), 'r') << swing.link_name;
}

}  // namespace
}  // namespace foresight
