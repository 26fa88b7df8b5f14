// The scene of the planner benchmarks: robot poses all over the field (so that rolls meet posts,
// nets, lines and open carpet) with the paper's uncertainty, on the shipped SPL field with the
// NAO kicks, and one obstacle robot. planner_bench decides on them in C++; planner_poses prints
// them for bench/python_decision_sweep.py, which decides on the same states from Python.
#pragma once

#include <vector>

#include "common/random.h"
#include "models/situation.h"
#include "tests/support/test_situations.h"

namespace foresight::bench {

inline std::vector<testing::StateSpec> BenchPoses(int count) {
  RandomStream rng(StreamKey(123, 0));
  std::vector<testing::StateSpec> poses;
  for (int i = 0; i < count; ++i) poses.push_back(testing::RandomPose(rng, 4.2, 2.8));
  return poses;
}

inline std::vector<Obstacle> BenchObstacles() {
  return {{Vec2(3.8, 0.4), 0.15}};
}

}  // namespace foresight::bench
