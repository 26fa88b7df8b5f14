// A lab's program that links the ground truth from an installed foresight (Bullet, urdfdom and
// assimp private to the archives): a few physics trials of the situation's first kick, printed
// as the launch speeds, so the test sees the robot, its meshes and motions load from the
// installed data.
//
// Usage: physics_trials SITUATION_FILE TRIALS
#include <iostream>
#include <string>

#include "common/error.h"
#include "physics/physics_runs.h"
#include "physics/physics_setup.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: physics_trials SITUATION_FILE TRIALS\n";
    return 2;
  }
  try {
    const auto setup =
        foresight::LoadPhysicsSetup(foresight::LoadSituation(argv[1], MODELS_DIR), MODELS_DIR);
    foresight::KickTrialsRequest request;
    request.state = setup->state;
    request.trials = std::stoi(argv[2]);
    request.seed = 1;
    const auto results = foresight::RunKickTrials(*setup->simulator, request);
    const foresight::TrialSummary summary = foresight::Summarize(results);
    std::cout << "trials " << summary.trials << " touched " << summary.touched
              << " launch_speed_mean_mps " << summary.launch_speed_mean_mps << "\n";
    return summary.touched > 0 ? 0 : 1;
  } catch (const foresight::InputError& e) {
    std::cerr << "physics_trials: error: " << e.what() << "\n";
    return 2;
  }
}
