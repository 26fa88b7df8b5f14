// Scenes shared by tests and benchmarks (written inline, as MuJoCo's tests write their models):
// the shipped SPL field, NAO kicks and evaluation, with a state set in code.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/random.h"
#include "models/situation.h"
#include "tests/support/temp_files.h"

namespace foresight::testing {

struct StateSpec {
  double x_m = 0.0, y_m = 0.0, theta_deg = 0.0;
  double ball_x_m = 0.15, ball_y_m = 0.0;  // relative to the robot
  double sigma_xy_m = 0.0, sigma_theta_deg = 0.0, sigma_ball_m = 0.0;
};

// A situation on the shipped `field` with the shipped kick model and evaluation.
Situation MakeSituation(const StateSpec& state, std::vector<Obstacle> obstacles = {},
                        const std::string& field = "spl", const std::string& kicks = "nao");

// The same kick model without any kick noise (exact analytic answers).
Situation MakeNoiselessSituation(const StateSpec& state, std::vector<Obstacle> obstacles = {});

// The paper's typical uncertainty: 0.1 m / 5 deg on the robot, 0.05 m on the ball.
StateSpec Uncertain(StateSpec state);

// A random robot pose, uniform over [-half_x, half_x] x [-half_y, half_y] and all headings,
// with the paper's uncertainty (Uncertain()).
StateSpec RandomPose(RandomStream& rng, double half_x_m, double half_y_m);

}  // namespace foresight::testing
