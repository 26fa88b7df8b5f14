#include "models/situation.h"

#include <cmath>

#include "common/checks.h"
#include "common/error.h"
#include "common/json_reader.h"
#include "models/model_paths.h"
#include "models/physics_params.h"
#include "models/placement.h"

namespace foresight {

namespace {

StateEstimate ReadState(const JsonObject& root) {
  StateEstimate state;
  JsonObject robot = root.Object("robot");
  robot.RejectUnknownKeys({"x_m", "y_m", "theta_deg", "sigma_x_m", "sigma_y_m", "sigma_theta_deg"});
  state.robot.p_F = Vec2(robot.Number("x_m"), robot.Number("y_m"));
  state.robot.theta_rad = robot.Number("theta_deg") * kDegToRad;
  state.sigma_robot_x_m = robot.NumberOr("sigma_x_m", 0.0);
  state.sigma_robot_y_m = robot.NumberOr("sigma_y_m", 0.0);
  state.sigma_robot_theta_rad = robot.NumberOr("sigma_theta_deg", 0.0) * kDegToRad;

  JsonObject ball = root.Object("ball");
  ball.RejectUnknownKeys({"x_m", "y_m", "sigma_x_m", "sigma_y_m"});
  state.p_R_ball = Vec2(ball.Number("x_m"), ball.Number("y_m"));
  state.sigma_ball_x_m = ball.NumberOr("sigma_x_m", 0.0);
  state.sigma_ball_y_m = ball.NumberOr("sigma_y_m", 0.0);
  return state;
}

// Loads a file the situation names; a missing one is reported against the naming field.
template <typename Loader>
auto LoadReferenced(const JsonObject& root, std::string_view key, const std::filesystem::path& file,
                    Loader load) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    root.Fail(key, "refers to " + file.string() + ", which does not exist");
  }
  return load(file);
}

// The coarse rebounds' restitution from the physics file of the field (the one source of the
// figures: physics realises the same pairs).
void LoadReboundRestitution(const SituationOverrides& overrides,
                            const std::filesystem::path& models_dir, Situation& situation) {
  const std::filesystem::path file =
      overrides.physics_file.empty()
          ? DataFile(models_dir, DataFolder::kPhysics, situation.field.name)
          : overrides.physics_file;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError(situation.evaluation_file.string() +
                     ": rebounds.enabled: the coarse rebounds read their restitution from " +
                     file.string() + ", which does not exist");
  }
  const BallPairs e = LoadPhysicsParams(file).materials.restitution;
  CoarseRebounds& rebounds = situation.evaluation.rebounds;
  rebounds.post = e.post;
  rebounds.net = e.net;
  rebounds.robot = e.robot;
}

}  // namespace

void Situation::Validate() const {
  RequireInRange("robot.theta_deg", state.robot.theta_rad * kRadToDeg, -360.0, 360.0);
  RequireNonNegative("robot.sigma_x_m", state.sigma_robot_x_m);
  RequireNonNegative("robot.sigma_y_m", state.sigma_robot_y_m);
  RequireInRange("robot.sigma_theta_deg", state.sigma_robot_theta_rad * kRadToDeg, 0.0, 180.0);
  RequireNonNegative("ball.sigma_x_m", state.sigma_ball_x_m);
  RequireNonNegative("ball.sigma_y_m", state.sigma_ball_y_m);
  if (!OnCarpet(field, state.robot.p_F)) {
    throw InputError("robot: position " + PointText(state.robot.p_F) + " is outside the carpet (" +
                     CarpetText(field) + ")");
  }
  const Vec2 ball = state.MeanBallInField();
  if (!OnCarpet(field, ball)) {
    throw InputError("ball: position " + PointText(ball) +
                     " in the field frame is outside the carpet (" + CarpetText(field) + ")");
  }
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const std::string at = "obstacles[" + std::to_string(i) + "]";
    RequireInRange(at + ".radius_m", obstacles[i].radius_m, 0.01, 2.0);
    if (!OnCarpet(field, obstacles[i].p_F)) {
      throw InputError(at + ": position " + PointText(obstacles[i].p_F) +
                       " is outside the carpet (" + CarpetText(field) + ")");
    }
    const double gap_m = (obstacles[i].p_F - ball).norm() - obstacles[i].radius_m;
    if (gap_m < field.ball.radius_m) {
      throw InputError(at + ": overlaps the ball at " + PointText(ball));
    }
  }
}

void Situation::ValidatePlacement() const {
  RequireClearOfPosts(field, "robot", state.robot.p_F, field.default_obstacle_radius_m);
  const Vec2 ball = state.MeanBallInField();
  RequireClearOfPosts(field, "ball", ball, field.ball.radius_m);
  RequireBallOutOfGoals(field, ball);
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    RequireClearOfPosts(field, "obstacles[" + std::to_string(i) + "]", obstacles[i].p_F,
                        obstacles[i].radius_m);
  }
}

namespace {

Situation ReadSituation(const JsonDocument& doc, const std::string& origin,
                        const std::string& default_name, const std::filesystem::path& dir,
                        const std::filesystem::path& models_dir,
                        const SituationOverrides& overrides) {
  JsonObject root = doc.Root();
  root.RejectUnknownKeys({"name", "field", "kicks", "evaluation", "robot", "ball", "obstacles"});

  Situation situation;
  situation.name = root.StringOr("name", default_name);
  situation.field_file =
      ResolveModelFile(root.String("field"), DataFolder::kFields, dir, models_dir);
  situation.field = LoadReferenced(root, "field", situation.field_file, LoadFieldSpec);
  if (overrides.kicks) {
    situation.kicks_file = overrides.kicks_file;
    situation.kicks = *overrides.kicks;
  } else if (overrides.kicks_file.empty()) {
    situation.kicks_file =
        ResolveModelFile(root.String("kicks"), DataFolder::kKicks, dir, models_dir);
    situation.kicks = LoadReferenced(root, "kicks", situation.kicks_file, LoadKickModel);
  } else {
    situation.kicks_file = overrides.kicks_file;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(situation.kicks_file, ec)) {
      throw InputError("--kicks: " + situation.kicks_file.string() + " does not exist");
    }
    situation.kicks = LoadKickModel(situation.kicks_file);
  }
  // Without an "evaluation" key, the evaluation shipped for the field's name applies.
  situation.evaluation_file = ResolveModelFile(root.StringOr("evaluation", situation.field.name),
                                               DataFolder::kEvaluation, dir, models_dir);
  std::error_code ec;
  if (!root.Has("evaluation") && !std::filesystem::is_regular_file(situation.evaluation_file, ec)) {
    throw InputError(origin + ": no evaluation for field '" + situation.field.name + "' (" +
                     situation.evaluation_file.string() +
                     " does not exist); name one with \"evaluation\"");
  }
  situation.evaluation =
      LoadReferenced(root, "evaluation", situation.evaluation_file, LoadEvaluationParams);
  if (overrides.coarse_rebounds) situation.evaluation.rebounds.enabled = *overrides.coarse_rebounds;
  if (situation.evaluation.rebounds.enabled) {
    LoadReboundRestitution(overrides, models_dir, situation);
  }
  situation.state = ReadState(root);

  for (const JsonObject& item : root.ObjectArray("obstacles")) {
    item.RejectUnknownKeys({"x_m", "y_m", "radius_m"});
    situation.obstacles.push_back(
        {Vec2(item.Number("x_m"), item.Number("y_m")),
         item.NumberOr("radius_m", situation.field.default_obstacle_radius_m)});
  }
  WithFile(origin, [&] {
    situation.Validate();
    situation.ValidatePlacement();
  });
  return situation;
}

}  // namespace

Situation LoadSituation(const std::filesystem::path& file, const std::filesystem::path& models_dir,
                        const SituationOverrides& overrides) {
  return ReadSituation(JsonDocument::Load(file), file.string(), file.stem().string(),
                       file.parent_path(), models_dir, overrides);
}

Situation ParseSituation(std::string_view text, const std::string& origin,
                         const std::filesystem::path& dir, const std::filesystem::path& models_dir,
                         const SituationOverrides& overrides) {
  return ReadSituation(JsonDocument::Parse(text, origin), origin, origin, dir, models_dir,
                       overrides);
}

}  // namespace foresight
