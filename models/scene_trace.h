// A scene trace: what a 3D viewer needs to replay one trial (docs/VIEWER.md). Frames at a chosen
// rate hold the pose of every link of the kicking robot (position and orientation in F), the
// ball's pose and spin and the trial's phase; contacts hold where something touched what, with
// the impulse summed over the frame's interval. Plain data: physics/scene_recorder.h fills it
// from a Bullet trial, experiments/ fills it from a match (bodies instead of links), and
// report/viewer_page.h draws it. Times are seconds since the trial's start (for a kick, the
// motion's start: the ball trace's clock).
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "common/geometry.h"

namespace foresight {

struct ScenePose {
  Eigen::Vector3d p_F = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_F = Eigen::Quaterniond::Identity();
};

// A simple body drawn as an upright cylinder (a match robot): its name and team.
struct SceneBody {
  std::string name;
  int team = 0;  // 0: attackers / own side, 1: opponents
  double radius_m = 0.0;
  double height_m = 0.0;
};

struct SceneFrame {
  double t_s = 0.0;
  int phase = 0;  // into SceneTrace::phases
  ScenePose ball;
  Eigen::Vector3d w_F_ball = Eigen::Vector3d::Zero();  // spin, rad/s
  // One pose per SceneTrace::links while the robot is simulated; empty afterwards (the roll
  // phase has no robot: it stands as it was in the last frame that had one).
  std::vector<ScenePose> links;
  std::vector<Pose2> bodies;  // one per SceneTrace::bodies
};

// What touched what: the impulses of one pair of bodies summed over the steps of one frame's
// interval, at the impulse-weighted mean of their contact points.
struct SceneContact {
  double t_s = 0.0;
  std::string a;  // "ball", "post", "net", "obstacle" or a robot link's name
  std::string b;
  Eigen::Vector3d p_F = Eigen::Vector3d::Zero();
  double impulse_Ns = 0.0;
};

struct SceneTrace {
  double rate_hz = 0.0;
  std::vector<std::string> links;   // the kicking robot's model links, model order
  std::vector<std::string> phases;  // names of the frames' phases
  std::vector<SceneBody> bodies;
  std::vector<SceneFrame> frames;   // t_s increasing
  std::vector<SceneContact> contacts;
  // Robots standing still as obstacles: per robot, one pose per link (same links).
  std::vector<std::vector<ScenePose>> obstacles;
};

}  // namespace foresight
