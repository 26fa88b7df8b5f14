// The mirror of a kick motion: the signs come from the URDF's axes and agree with the robots'
// symmetric standing poses (an independent source: robot.json's published stance), the shipped
// right kicks are the mirrors of the left ones, mirroring twice gives the motion back, and the
// command writes the mirror and refuses bad input in one line.
#include "tools/motion_mirror.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "common/error.h"
#include "tests/support/model_test_util.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using testing::ModelsDir;

const KickMotion& Motion(const Robot& robot, const std::string& kick) {
  return robot.motions[static_cast<std::size_t>(*robot.FindMotion(kick))];
}

std::map<std::string, double> AsMap(const std::vector<std::pair<std::string, double>>& values) {
  return {values.begin(), values.end()};
}

void ExpectSameMotion(const KickMotion& a, const KickMotion& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.p_R_ball, b.p_R_ball);
  EXPECT_EQ(a.joints, b.joints);
  ASSERT_EQ(a.keyframes.size(), b.keyframes.size());
  for (std::size_t k = 0; k < a.keyframes.size(); ++k) {
    EXPECT_EQ(a.keyframes[k].time_s, b.keyframes[k].time_s) << "keyframe " << k;
    EXPECT_EQ(a.keyframes[k].positions_rad, b.keyframes[k].positions_rad) << "keyframe " << k;
  }
  EXPECT_EQ(a.stance.base_height_m, b.stance.base_height_m);
  EXPECT_EQ(AsMap(a.stance.pose_rad), AsMap(b.stance.pose_rad));
  EXPECT_EQ(a.balance.shift_s, b.balance.shift_s);
  EXPECT_EQ(a.balance.settle_s, b.balance.settle_s);
  EXPECT_EQ(AsMap(a.balance.offsets_rad), AsMap(b.balance.offsets_rad));
}

TEST(MotionMirrorTest, SignsFromTheAxesAgreeWithTheSymmetricStandingPoses) {
  for (const std::string name : {"nao", "aibo_ers7"}) {
    const Robot robot = LoadRobot(name, ModelsDir());
    const std::map<std::string, double> pose = AsMap(robot.spec.standing_pose_rad);
    int checked = 0, flipped = 0;
    for (const RobotJoint& joint : robot.model.joints) {
      if (joint.kind != RobotJoint::Kind::kRevolute) continue;
      const MirroredJoint m = MirrorJoint(robot, joint.name);
      const auto at = [&](const std::string& j) { return pose.count(j) ? pose.at(j) : 0.0; };
      EXPECT_EQ(at(m.name), m.sign * at(joint.name)) << name << " " << joint.name;
      checked += 1;
      flipped += m.sign < 0.0;
    }
    EXPECT_GE(checked, 12) << name;
    EXPECT_GT(flipped, 0) << name;  // some joints do flip: the test can tell the signs apart
  }
  const Robot nao = LoadRobot("nao", ModelsDir());
  EXPECT_EQ(MirrorJoint(nao, "LHipPitch").name, "RHipPitch");
  EXPECT_EQ(MirrorJoint(nao, "LHipPitch").sign, 1.0);
  EXPECT_EQ(MirrorJoint(nao, "RHipRoll").name, "LHipRoll");
  EXPECT_EQ(MirrorJoint(nao, "RHipRoll").sign, -1.0);
  EXPECT_EQ(MirrorJoint(nao, "HeadYaw").name, "HeadYaw");
  EXPECT_EQ(MirrorJoint(nao, "HeadYaw").sign, -1.0);
  EXPECT_EQ(MirrorJoint(nao, "HeadPitch").sign, 1.0);
}

TEST(MotionMirrorTest, ShippedRightKicksAreTheMirrorsOfTheLeftOnes) {
  const Robot nao = LoadRobot("nao", ModelsDir());
  ExpectSameMotion(MirrorMotion(nao, Motion(nao, "side_kick_left"), "side_kick_right"),
                   Motion(nao, "side_kick_right"));
  const Robot aibo = LoadRobot("aibo_ers7", ModelsDir());
  ExpectSameMotion(MirrorMotion(aibo, Motion(aibo, "head_kick_left"), "head_kick_right"),
                   Motion(aibo, "head_kick_right"));
}

TEST(MotionMirrorTest, TwiceIsTheMotionAgainAndARobotWithoutPrefixesRefuses) {
  const Robot nao = LoadRobot("nao", ModelsDir());
  const KickMotion& forward = Motion(nao, "forward");
  ExpectSameMotion(MirrorMotion(nao, MirrorMotion(nao, forward, "x"), "forward"), forward);
  Robot plain = nao;
  plain.spec.left_prefix.clear();
  plain.spec.right_prefix.clear();
  try {
    MirrorMotion(plain, forward, "x");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "robot 'nao': mirror_prefixes: not given, so its motions cannot be mirrored");
  }
}

std::pair<int, std::string> RunCommand(const std::string& arguments,
                                       const std::filesystem::path& dir) {
  const std::string command = std::string(FORESIGHT_MIRROR_MOTION) + " " + arguments +
                              " --models " + ModelsDir().string() + " >" +
                              (dir / "log.txt").string() + " 2>" + (dir / "err.txt").string();
  const int status = std::system(command.c_str());
  std::ifstream err(dir / "err.txt");
  std::string all((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, all};
}

TEST(MirrorMotionCommandTest, WritesTheShippedRightKickAndRefusesBadInputInOneLine) {
  const std::filesystem::path dir = testing::FreshTempDir("mirror_cmd");
  const std::filesystem::path motions = ModelsDir() / "robots" / "nao" / "motions";
  const std::filesystem::path right = dir / "side_kick_right.json";
  std::filesystem::copy_file(motions / "side_kick_right.json", right);
  // In place: the right kick's file is its own template.
  const auto [status, err] =
      RunCommand("--robot nao --in " + (motions / "side_kick_left.json").string() +
                     " --name side_kick_right --like " + right.string() + " --out " + right.string(),
                 dir);
  ASSERT_EQ(status, 0) << err;
  const Robot nao = LoadRobot("nao", ModelsDir());
  const KickMotion written = LoadRobotKickMotion(nao, "side_kick_right", right);
  ExpectSameMotion(written, Motion(nao, "side_kick_right"));
  std::ifstream text(right);
  const std::string content((std::istreambuf_iterator<char>(text)), std::istreambuf_iterator<char>());
  EXPECT_NE(content.find("onto the left (support) leg"), std::string::npos);  // its own notes

  const auto [bad_status, bad_err] =
      RunCommand("--robot nao --in " + (dir / "nothing.json").string() +
                     " --name x --out " + (dir / "x.json").string(),
                 dir);
  EXPECT_EQ(bad_status, 2);
  EXPECT_EQ(std::count(bad_err.begin(), bad_err.end(), '\n'), 1) << bad_err;
  EXPECT_NE(bad_err.find("nothing.json"), std::string::npos) << bad_err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.json"));
  const auto [missing_status, missing_err] = RunCommand("--robot nao --in x.json --name x", dir);
  EXPECT_EQ(missing_status, 2);
  EXPECT_NE(missing_err.find("--out: required"), std::string::npos) << missing_err;
}

}  // namespace
}  // namespace foresight
