// Not a benchmark: how the rotation search's parameters were chosen, against brute force. For
// random poses (the test scenes, no obstacle) and every kick, BestRotation with each parameter set
// below is compared with the best trimmed utility over the circle in 0.25 deg steps; prints the
// hypotheses per kick and the worst and mean utility lost. The shipped choice
// (models/evaluation/spl.json) and the numbers are in docs/PERFORMANCE.md.
//   build/bench/search_sweep [poses=300] [seed=5]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "common/random.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace foresight {
namespace {

struct Variant {
  double grid_step_deg;
  int refine_levels;
  int refine_candidates;
  double worst = 0.0, total = 0.0;
  long long hypotheses = 0;
};

int Run(int poses, std::uint64_t seed) {
  std::vector<Variant> variants = {{10, 5, 3}, {10, 5, 2}, {15, 5, 2}, {20, 5, 3}, {20, 5, 2},
                                   {20, 5, 1}, {20, 4, 3}, {24, 5, 2}, {30, 5, 2}};
  RandomStream rng(StreamKey(seed, 0));
  int cases = 0;
  for (int t = 0; t < poses; ++t) {
    const Situation s = testing::MakeSituation(testing::RandomPose(rng, 4.0, 2.8));
    const CoarsePlanner planner(s);
    for (int kick = 0; kick < 3; ++kick) {
      CoarseActionEvaluator evaluator = planner.MakeEvaluator(30, 7 + t);
      double brute = 0.0;
      for (double d = -180.0; d < 180.0; d += 0.25) {
        brute = std::max(brute, evaluator.Evaluate(kick, d * kDegToRad).trimmed_utility);
      }
      for (Variant& v : variants) {
        const RotationSearchParams params{v.grid_step_deg * kDegToRad, v.refine_levels,
                                          v.refine_candidates};
        const long long before = evaluator.evaluations();
        const RotationChoice c = BestRotation(
            [&](double rho) { return evaluator.EvaluateForSearch(kick, rho); }, params);
        v.hypotheses += evaluator.evaluations() - before;
        const double found = evaluator.Evaluate(kick, c.rotation_rad).trimmed_utility;
        const double loss = std::max(0.0, brute - found);
        v.worst = std::max(v.worst, loss);
        v.total += loss;
      }
      ++cases;
    }
  }
  std::printf("%d kick cases (%d poses, seed %llu)\n", cases, poses,
              static_cast<unsigned long long>(seed));
  for (const Variant& v : variants) {
    std::printf(
        "grid %4.1f deg, %d levels, %d maxima: %5.1f hypotheses/kick, loss worst %.4f mean %.2e\n",
        v.grid_step_deg, v.refine_levels, v.refine_candidates,
        static_cast<double>(v.hypotheses) / cases, v.worst, v.total / cases);
  }
  return 0;
}

}  // namespace
}  // namespace foresight

int main(int argc, char** argv) {
  const int poses = argc > 1 ? std::atoi(argv[1]) : 300;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 5;
  return foresight::Run(poses, seed);
}
