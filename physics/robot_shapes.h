// Bullet collision shapes for a robot's links, made from the URDF's collision geometry:
// boxes, spheres and z-axis cylinders as Bullet primitives, meshes as convex hulls of their
// vertices (the project's meshes are convex: feet, paws, head).
#pragma once

#include <Eigen/Geometry>

#include "models/robot_model.h"
#include "physics/bullet_world.h"

class btCompoundShape;

namespace foresight {

// A compound of the link's collision shapes, placed relative to frame X (pose_X_L is the link
// frame in X), owned by `world`; nullptr if the link has no collision geometry.
btCompoundShape* MakeLinkShape(BulletWorld& world, const RobotLink& link,
                               const Eigen::Isometry3d& pose_X_L);

// Adds the link's collision shapes to `compound`, placed relative to its frame X.
void AddLinkShapes(BulletWorld& world, const RobotLink& link, const Eigen::Isometry3d& pose_X_L,
                   btCompoundShape& compound);

// Adds the shapes of every link of a robot standing with the given link poses (in the root
// frame) to one compound in frame X = root; used for static obstacle robots.
btCompoundShape* MakeRobotShape(BulletWorld& world, const RobotModel& model,
                                const std::vector<Eigen::Isometry3d>& pose_root_L);

}  // namespace foresight
