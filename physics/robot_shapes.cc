#include "physics/robot_shapes.h"

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include "physics/bullet_convert.h"

namespace foresight {

namespace {

std::unique_ptr<btCollisionShape> MakePrimitive(const RobotShape& shape) {
  switch (shape.kind) {
    case RobotShape::Kind::kBox:
      return std::make_unique<btBoxShape>(ToBt(Eigen::Vector3d(0.5 * shape.box_size_m)));
    case RobotShape::Kind::kSphere:
      return std::make_unique<btSphereShape>(shape.radius_m);
    case RobotShape::Kind::kCylinder:
      return std::make_unique<btCylinderShapeZ>(
          btVector3(shape.radius_m, shape.radius_m, 0.5 * shape.length_m));
    case RobotShape::Kind::kMesh: {
      auto hull = std::make_unique<btConvexHullShape>();
      for (const Eigen::Vector3d& v : shape.mesh_vertices_S_m) hull->addPoint(ToBt(v), false);
      hull->recalcLocalAabb();
      hull->setMargin(0.001);
      return hull;
    }
  }
  return nullptr;
}

}  // namespace

void AddLinkShapes(BulletWorld& world, const RobotLink& link, const Eigen::Isometry3d& pose_X_L,
                   btCompoundShape& compound) {
  for (const RobotShape& shape : link.collisions) {
    btCollisionShape* child = world.Own(MakePrimitive(shape));
    compound.addChildShape(ToBt(Eigen::Isometry3d(pose_X_L * shape.pose_L_S)), child);
  }
}

btCompoundShape* MakeLinkShape(BulletWorld& world, const RobotLink& link,
                               const Eigen::Isometry3d& pose_X_L) {
  if (link.collisions.empty()) return nullptr;
  btCompoundShape* compound = world.Own(std::make_unique<btCompoundShape>());
  AddLinkShapes(world, link, pose_X_L, *compound);
  return compound;
}

btCompoundShape* MakeRobotShape(BulletWorld& world, const RobotModel& model,
                                const std::vector<Eigen::Isometry3d>& pose_root_L) {
  btCompoundShape* compound = world.Own(std::make_unique<btCompoundShape>());
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    AddLinkShapes(world, model.links[i], pose_root_L[i], *compound);
  }
  return compound;
}

}  // namespace foresight
