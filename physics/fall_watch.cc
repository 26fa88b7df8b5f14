#include "physics/fall_watch.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "physics/bullet_world.h"
#include "physics/kicking_robot.h"
#include "physics/scene_recorder.h"

namespace foresight {

namespace {

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Andrew's monotone chain: the hull counter-clockwise, points on its edges left out.
std::vector<Eigen::Vector2d> ConvexHull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const std::size_t n = points.size();
  if (n < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * n);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {  // lower chain
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = n - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point is the first
  return hull;
}

Eigen::Vector2d Planar(const btVector3& v) {
  return {v.x(), v.y()};
}

// Mass-weighted over the base and every link; each collider sits at its group's centre of mass
// (kicking_robot.h).
Eigen::Vector2d CentreOfMassXY(const btMultiBody& body) {
  double mass_kg = body.getBaseMass();
  Eigen::Vector2d sum = mass_kg * Planar(body.getBaseCollider()->getWorldTransform().getOrigin());
  for (int i = 0; i < body.getNumLinks(); ++i) {
    const btMultibodyLink& link = body.getLink(i);
    sum += link.m_mass * Planar(link.m_collider->getWorldTransform().getOrigin());
    mass_kg += link.m_mass;
  }
  return sum / mass_kg;
}

// The points where the robot's links pressed on the carpet in the last step.
std::vector<Eigen::Vector2d> SupportPoints(btDispatcher& dispatcher) {
  std::vector<Eigen::Vector2d> points;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    const BodyTag a = TagOf(*manifold.getBody0()), b = TagOf(*manifold.getBody1());
    const bool carpet_a = a == BodyTag::kCarpet && b == BodyTag::kKicker;
    if (!carpet_a && !(b == BodyTag::kCarpet && a == BodyTag::kKicker)) continue;
    for (int k = 0; k < manifold.getNumContacts(); ++k) {
      const btManifoldPoint& point = manifold.getContactPoint(k);
      if (point.getAppliedImpulse() <= 0.0) continue;  // touching, carrying nothing
      points.push_back(
          Planar(carpet_a ? point.getPositionWorldOnA() : point.getPositionWorldOnB()));
    }
  }
  return points;
}

}  // namespace

double HullMarginM(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& p) {
  const std::vector<Eigen::Vector2d> hull = ConvexHull({points.begin(), points.end()});
  if (hull.size() < 3) return -std::numeric_limits<double>::infinity();
  double margin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    margin = std::min(margin, Cross(a, b, p) / (b - a).norm());  // > 0: left of a -> b, inside
  }
  return margin;
}

double SupportMarginM(const KickingRobot& robot, btDispatcher& dispatcher) {
  return HullMarginM(SupportPoints(dispatcher), CentreOfMassXY(robot.body()));
}

bool StandsStill(const KickingRobot& robot, btDispatcher& dispatcher, const WatchParams& watch) {
  const btMultiBody& body = robot.body();
  if (body.getBaseVel().length() > watch.still_base_speed_mps) return false;
  if (body.getBaseOmega().length() > watch.still_base_rate_radps) return false;
  for (int i = 0; i < body.getNumLinks(); ++i) {
    if (std::abs(body.getJointVel(i)) > watch.still_joint_speed_radps) return false;
  }
  if (robot.TiltRad() > watch.still_tilt_rad) return false;
  return SupportMarginM(robot, dispatcher) >= watch.still_support_margin_m;
}

WatchEnd WatchForFall(BulletWorld& world, KickingRobot& robot, const KickMotion& motion,
                      const WatchSpan& span, const PhysicsParams& params, double max_tilt_rad,
                      SceneRecorder* recorder) {
  const WatchParams& watch = params.watch;
  btDispatcher& dispatcher = *world.world().getDispatcher();
  // The kick's own step: coarser steps or fewer solver iterations changed how far the robot
  // swayed, and whether it fell (docs/PHYSICS.md, "The watch after the launch").
  const double dt = params.steps.kick_time_step_s;
  WatchEnd end;
  end.max_tilt_rad = max_tilt_rad;
  end.t_s = span.t_start_s;
  std::optional<double> still_since_s;  // since when the robot has stood still without a break
  for (double t = span.t_start_s; t < span.stand_end_s;) {
    robot.FollowMotion(motion, t, span.speed_factor);
    world.world().stepSimulation(dt, 0, dt);
    t += dt;
    end.t_s = t;
    if (recorder != nullptr) {
      recorder->ObserveKick(t, t * span.speed_factor, robot, nullptr, dispatcher);
    }
    end.max_tilt_rad = std::max(end.max_tilt_rad, robot.TiltRad());
    if (end.max_tilt_rad > params.robot.fall_tilt_rad) {
      end.fell = true;
      break;
    }
    // Before its motion's end the robot's targets still change: it is never still then.
    if (t < span.motion_end_s || !StandsStill(robot, dispatcher, watch)) {
      still_since_s.reset();
      continue;
    }
    if (!still_since_s) still_since_s = t;
    if (t - *still_since_s >= watch.still_time_s) {
      end.still = true;
      break;
    }
  }
  return end;
}

}  // namespace foresight
