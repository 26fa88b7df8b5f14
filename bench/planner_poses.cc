// Not a benchmark: prints the planner benchmarks' scene (bench/bench_scenes.h) as a situation
// dict with the poses, for bench/python_decision_sweep.py, which times the same decisions from
// Python. Numbers are printed with 17 significant digits, so Python reads the same doubles.
#include <cstdio>
#include <cstdlib>

#include "bench/bench_scenes.h"

int main(int argc, char** argv) {
  using namespace foresight;
  const int count = argc > 1 ? std::atoi(argv[1]) : 16;
  std::printf("{\"field\": \"spl\", \"kicks\": \"nao\", \"obstacles\": [");
  const std::vector<Obstacle> obstacles = bench::BenchObstacles();
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    std::printf("%s{\"x_m\": %.17g, \"y_m\": %.17g, \"radius_m\": %.17g}", i ? ", " : "",
                obstacles[i].p_F.x(), obstacles[i].p_F.y(), obstacles[i].radius_m);
  }
  std::printf("],\n \"poses\": [");
  const std::vector<testing::StateSpec> poses = bench::BenchPoses(count);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const testing::StateSpec& p = poses[i];
    std::printf(
        "%s\n  {\"robot\": {\"x_m\": %.17g, \"y_m\": %.17g, \"theta_deg\": %.17g, \"sigma_x_m\": "
        "%.17g, \"sigma_y_m\": %.17g, \"sigma_theta_deg\": %.17g}, \"ball\": {\"x_m\": %.17g, "
        "\"y_m\": %.17g, \"sigma_x_m\": %.17g, \"sigma_y_m\": %.17g}}",
        i ? "," : "", p.x_m, p.y_m, p.theta_deg, p.sigma_xy_m, p.sigma_xy_m, p.sigma_theta_deg,
        p.ball_x_m, p.ball_y_m, p.sigma_ball_m, p.sigma_ball_m);
  }
  std::printf("]}\n");
  return 0;
}
