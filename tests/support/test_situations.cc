#include "tests/support/test_situations.h"

#include "models/model_paths.h"

namespace foresight::testing {

Situation MakeSituation(const StateSpec& spec, std::vector<Obstacle> obstacles,
                        const std::string& field, const std::string& kicks) {
  Situation s;
  s.name = "test";
  s.field_file = ModelsDir() / "fields" / (field + ".json");
  s.kicks_file = ModelsDir() / "kicks" / (kicks + ".json");
  s.evaluation_file = ModelsDir() / "evaluation" / (field + ".json");
  s.field = LoadFieldSpec(s.field_file);
  s.kicks = LoadKickModel(s.kicks_file);
  s.evaluation = LoadEvaluationParams(s.evaluation_file);
  s.state.robot = Pose2{Vec2(spec.x_m, spec.y_m), spec.theta_deg * kDegToRad};
  s.state.sigma_robot_x_m = s.state.sigma_robot_y_m = spec.sigma_xy_m;
  s.state.sigma_robot_theta_rad = spec.sigma_theta_deg * kDegToRad;
  s.state.p_R_ball = Vec2(spec.ball_x_m, spec.ball_y_m);
  s.state.sigma_ball_x_m = s.state.sigma_ball_y_m = spec.sigma_ball_m;
  s.obstacles = std::move(obstacles);
  s.Validate();
  return s;
}

Situation MakeNoiselessSituation(const StateSpec& state, std::vector<Obstacle> obstacles) {
  Situation s = MakeSituation(state, std::move(obstacles));
  for (KickSpec& kick : s.kicks.kicks) kick.sigma_speed_mps = kick.sigma_direction_rad = 0.0;
  return s;
}

StateSpec Uncertain(StateSpec state) {
  state.sigma_xy_m = 0.1;
  state.sigma_theta_deg = 5.0;
  state.sigma_ball_m = 0.05;
  return state;
}

StateSpec RandomPose(RandomStream& rng, double half_x_m, double half_y_m) {
  StateSpec spec;
  spec.x_m = half_x_m * (2.0 * rng.NextUniform() - 1.0);
  spec.y_m = half_y_m * (2.0 * rng.NextUniform() - 1.0);
  spec.theta_deg = 360.0 * rng.NextUniform() - 180.0;
  return Uncertain(spec);
}

}  // namespace foresight::testing
