// Not a benchmark: the rotation search's parameters against brute force. For random poses (the
// test scenes, no obstacle) and every kick, BestRotation with each parameter set below is
// compared with the best trimmed utility over the circle in 0.25 deg steps (30 samples); prints
// per kick the hypotheses, the samples simulated (what a search costs: a coarse look simulates
// fewer), and the worst and mean utility lost. The shipped choice (models/evaluation/spl.json)
// and the numbers are in docs/PERFORMANCE.md.
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
  RotationSearchParams params;
  double worst = 0.0, total = 0.0;
  long long hypotheses = 0, samples = 0;
};

Variant Make(double grid_step_deg, int levels, int candidates, double coarse_share) {
  Variant v;
  v.params = {grid_step_deg * kDegToRad, levels, candidates, coarse_share};
  return v;
}

int Run(int poses, std::uint64_t seed) {
  std::vector<Variant> variants = {
      Make(20, 5, 2, 1.0),  Make(20, 5, 1, 1.0 / 3), Make(20, 5, 2, 1.0 / 3),
      Make(20, 5, 1, 0.25), Make(20, 5, 2, 0.25),    Make(20, 5, 3, 0.25),
      Make(20, 5, 2, 0.2),  Make(20, 4, 2, 0.25),    Make(24, 5, 2, 0.25)};
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
        const long long before = evaluator.evaluations();
        const long long samples_before = evaluator.samples_simulated();
        const RotationChoice c = BestRotation(
            [&](double rho, int samples) { return evaluator.EvaluateForSearch(kick, rho, samples); },
            evaluator.sample_count(), v.params);
        v.hypotheses += evaluator.evaluations() - before;
        v.samples += evaluator.samples_simulated() - samples_before;
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
    const RotationSearchParams& p = v.params;
    std::printf(
        "grid %4.1f deg on %2d of 30 samples, %d maxima, %d levels: %5.1f hypotheses/kick, "
        "%6.1f samples/kick, loss worst %.4f mean %.2e\n",
        p.grid_step_rad * kRadToDeg, p.CoarseSamples(30), p.refine_candidates, p.refine_levels,
        static_cast<double>(v.hypotheses) / cases,
        static_cast<double>(v.samples) / cases, v.worst, v.total / cases);
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
