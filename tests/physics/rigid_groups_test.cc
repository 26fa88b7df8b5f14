#include "physics/rigid_groups.h"

#include <gtest/gtest.h>

#include "models/robot_spec.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

TEST(RigidGroupsTest, ForwardKickWeldsTheNaoIntoFourBodiesWithItsWholeMass) {
  const Robot robot = LoadRobot("nao", testing::ModelsDir());
  const KickMotion& motion = robot.motions[*robot.FindMotion("forward")];
  std::vector<bool> moving(robot.model.joints.size(), false);
  for (const std::string& name : motion.joints) moving[*robot.model.FindJoint(name)] = true;
  const std::vector<double> q = robot.StandingPositions();
  const std::vector<RigidGroup> groups = GroupRigidly(robot.model, q, moving);
  ASSERT_EQ(groups.size(), motion.joints.size() + 1);

  // Mass and centre of mass of the whole robot, computed link by link in the root frame.
  const std::vector<Eigen::Isometry3d> poses = LinkPoses(robot.model, q);
  const std::vector<Eigen::Isometry3d> group_poses = [&] {
    std::vector<Eigen::Isometry3d> out;
    for (const RigidGroup& g : groups) out.push_back(poses[g.link]);
    return out;
  }();
  double mass = 0.0, group_mass = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero(), group_moment = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < robot.model.links.size(); ++i) {
    const RobotLink& link = robot.model.links[i];
    mass += link.mass_kg;
    moment += link.mass_kg * (poses[i] * link.pose_L_C.translation());
  }
  std::size_t members = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    group_mass += groups[g].mass_kg;
    group_moment += groups[g].mass_kg * (group_poses[g] * groups[g].inertia.pose_L_C.translation());
    members += groups[g].members.size();
    EXPECT_GT(groups[g].inertia.diagonal_kgm2.minCoeff(), 0.0);
  }
  EXPECT_EQ(members, robot.model.links.size());
  EXPECT_NEAR(group_mass, mass, 1e-12);
  EXPECT_LT((group_moment - moment).norm(), 1e-12);
}

TEST(RigidGroupsTest, AllJointsMovingKeepsOneGroupPerLink) {
  const Robot robot = LoadRobot("aibo_ers7", testing::ModelsDir());
  const std::vector<bool> moving(robot.model.joints.size(), true);
  const std::vector<RigidGroup> groups =
      GroupRigidly(robot.model, robot.StandingPositions(), moving);
  ASSERT_EQ(groups.size(), robot.model.links.size());
  for (std::size_t g = 0; g < groups.size(); ++g) {
    EXPECT_EQ(groups[g].members.size(), 1u);
    EXPECT_DOUBLE_EQ(groups[g].mass_kg, robot.model.links[groups[g].link].mass_kg);
  }
}

}  // namespace
}  // namespace foresight
