// A kick motion mirrored through the robot's sagittal plane (x-z of the root link's frame): the
// kick with the other foot, paw or side of the head. A joint of one side becomes its partner on
// the other (robot.json's mirror_prefixes pair LHipRoll with RHipRoll); a joint of neither side
// (HeadYaw, neck_tilt) is its own partner. A joint angle keeps its sign where the partner's axis
// is the mirror image of the joint's (pitch joints) and flips it where the axis is mirrored onto
// its opposite (roll and yaw joints).
//
// Why the axes decide: a reflection S = diag(1, -1, 1) maps a rotation by q about axis a onto a
// rotation by -q about S a, that is by q about -S a (an axis is a pseudovector). So the mirror of
// joint J at q is the partner P at +q if a_P = -S a_J, and at -q if a_P = S a_J, with both axes
// in the root frame at the zero pose. The URDF decides, not a list of names; a partner whose axis
// is neither is not a mirror image, and mirroring refuses.
//
// The mirror keeps the keyframes' times, the weight shift's times and the ball's x; it mirrors
// the joints, the stance's pose, the shift's offsets and the ball's y. The shipped right kicks
// are the mirrors of the left ones (tests/tools/motion_mirror_test.cc).
#pragma once

#include <string>

#include "models/kick_motion.h"
#include "models/robot_spec.h"

namespace foresight {

// InputError "robot 'R': ..." when the robot names no mirror_prefixes, a joint has no partner,
// or a pair's axes are not mirror images.
KickMotion MirrorMotion(const Robot& robot, const KickMotion& motion, const std::string& name);

// +1 or -1: the sign joint_name's angle takes on its partner in the mirror (the rule above).
struct MirroredJoint {
  std::string name;
  double sign = 1.0;
};
MirroredJoint MirrorJoint(const Robot& robot, const std::string& joint_name);

}  // namespace foresight
