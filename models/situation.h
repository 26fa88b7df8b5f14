// A decision situation (models/situations/*.json): the estimated state of the robot that has the
// ball and of the ball, with their uncertainties (Mellmann & Schlotter, sec. III-A), obstacle
// robots, and the field, kick model and evaluation that apply.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/geometry.h"
#include "models/evaluation_params.h"
#include "models/field_spec.h"
#include "models/kick_model.h"

namespace foresight {

// A robot that is not kicking: a static circle in the field frame.
struct Obstacle {
  Vec2 p_F{0.0, 0.0};
  double radius_m = 0.0;
};

// Mean and standard deviation of the state; each sample draws from independent normals.
struct StateEstimate {
  Pose2 robot;  // in F
  double sigma_robot_x_m = 0.0;
  double sigma_robot_y_m = 0.0;
  double sigma_robot_theta_rad = 0.0;
  Vec2 p_R_ball{0.0, 0.0};  // ball relative to the robot, in R
  double sigma_ball_x_m = 0.0;
  double sigma_ball_y_m = 0.0;

  Vec2 MeanBallInField() const { return robot.ToField(p_R_ball); }
};

struct Situation {
  std::string name;
  FieldSpec field;
  KickModel kicks;
  EvaluationParams evaluation;
  StateEstimate state;
  std::vector<Obstacle> obstacles;
  // The files that were read, for reports.
  std::filesystem::path field_file, kicks_file, evaluation_file;

  // Checks the situation against its field: sigmas, robot, ball and obstacles on the carpet, no
  // obstacle on the ball.
  void Validate() const;
  // What physics cannot start from: nothing standing in a goal post (the robot
  // counted as a disc of the field's default obstacle radius), the ball neither in a goal nor in
  // a net. Situation files must pass it; states made in code (tests, experiment grids, whose
  // points may fall in a post) need not.
  void ValidatePlacement() const;
};

struct SituationOverrides {
  std::filesystem::path kicks_file;  // replaces the situation's kick model when not empty
  // Replaces the evaluation file's rebounds.enabled when set (--coarse-rebounds).
  std::optional<bool> coarse_rebounds;
  // Where the coarse rebounds' restitution is read when not empty (the run's --physics file);
  // otherwise MODELS/physics/<field>.json, as physics reads it.
  std::filesystem::path physics_file;
  // An in-memory kick model replacing the situation's (the Python module's KickModel); it wins
  // over kicks_file, which then only names it in reports.
  std::optional<KickModel> kicks;
};

Situation LoadSituation(const std::filesystem::path& file, const std::filesystem::path& models_dir,
                        const SituationOverrides& overrides = {});
// The same from a situation file's text that came from elsewhere (the Python module's dicts):
// `origin` names it in messages and is the name unless "name" says otherwise; references ending
// in ".json" resolve against `dir`.
Situation ParseSituation(std::string_view text, const std::string& origin,
                         const std::filesystem::path& dir, const std::filesystem::path& models_dir,
                         const SituationOverrides& overrides = {});

}  // namespace foresight
