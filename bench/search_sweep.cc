// Not a benchmark: the rotation search's parameters against brute force. For random poses (the
// test scenes, no obstacle) and every kick, BestRotation with each parameter set below is
// compared with the best trimmed utility over the circle in 0.25 deg steps (30 samples); prints
// per kick the hypotheses, the samples simulated (what a search costs: a coarse look simulates
// fewer), and the worst and mean utility lost; for the shipped search its worst cases, its choice
// valued on held-out samples, and the noise floor (the exhaustive search's choice from 30 other
// samples, valued on these 30). The shipped choice (models/evaluation/spl.json)
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

// A case of the shipped search (its loss on the 30 samples it searched, and where).
struct Case {
  int pose = 0, kick = 0;
  double loss = 0.0, brute_deg = 0.0, found_deg = 0.0;
  double better_deg = 0.0;  // how much of the circle beats the found rotation on the 30 samples
  double brute_heldout = 0.0, found_heldout = 0.0;  // both rotations on held-out samples
  double best_heldout = -1.0;  // the best over the circle on the held-out samples (when looked at)
  // The noise floor: the exhaustive search run on 30 other samples (another seed), its choice
  // valued on these 30: what an exhaustive decision from another draw loses on them.
  double other_draw_loss = 0.0, other_draw_deg = 0.0;
};

// The seed of the 30 other samples of pose t (the sweep's own are 7 + t).
std::uint64_t OtherDrawSeed(int pose) {
  return 500009 + static_cast<std::uint64_t>(pose);
}

// The best trimmed utility over the circle in 0.5 deg steps on kHeldOutSamples held-out samples
// of pose `pose`: what the two rotations are both measured against.
double HeldOutBest(const Situation& s, int pose, int kick);

// Held-out samples: another seed, many samples, so that the utilities of two rotations are
// compared without the 30 samples the search and the brute force both looked at.
constexpr int kHeldOutSamples = 3000;

CoarseActionEvaluator HeldOutEvaluator(const CoarsePlanner& planner, int pose) {
  return planner.MakeEvaluator(kHeldOutSamples, 1000003 + static_cast<std::uint64_t>(pose));
}

double HeldOutBest(const Situation& s, int pose, int kick) {
  const CoarsePlanner planner(s);
  CoarseActionEvaluator heldout = HeldOutEvaluator(planner, pose);
  double best = 0.0;
  for (double d = -180.0; d < 180.0; d += 0.5) {
    best = std::max(best, heldout.Evaluate(kick, d * kDegToRad).trimmed_utility);
  }
  return best;
}

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
  // The shipped parameter set (models/evaluation/spl.json) among the variants.
  constexpr std::size_t kShipped = 3;  // Make(20, 5, 1, 0.25)
  std::vector<Case> shipped;
  RandomStream rng(StreamKey(seed, 0));
  int cases = 0;
  std::vector<Situation> situations;
  situations.reserve(static_cast<std::size_t>(poses));
  for (int t = 0; t < poses; ++t) {
    situations.push_back(testing::MakeSituation(testing::RandomPose(rng, 4.0, 2.8)));
    const Situation& s = situations.back();
    const CoarsePlanner planner(s);
    for (int kick = 0; kick < 3; ++kick) {
      CoarseActionEvaluator evaluator = planner.MakeEvaluator(30, 7 + t);
      double brute = 0.0, brute_deg = 0.0;
      std::vector<double> circle;
      for (double d = -180.0; d < 180.0; d += 0.25) {
        circle.push_back(evaluator.Evaluate(kick, d * kDegToRad).trimmed_utility);
        if (circle.back() > brute) brute = circle.back(), brute_deg = d;
      }
      for (std::size_t vi = 0; vi < variants.size(); ++vi) {
        Variant& v = variants[vi];
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
        if (vi == kShipped) {
          Case k{t, kick, loss, brute_deg, c.rotation_rad * kRadToDeg};
          for (double u : circle) k.better_deg += u > found ? 0.25 : 0.0;
          CoarseActionEvaluator other = planner.MakeEvaluator(30, OtherDrawSeed(t));
          double other_best = -1.0;
          for (double d = -180.0; d < 180.0; d += 0.25) {
            const double u = other.Evaluate(kick, d * kDegToRad).trimmed_utility;
            if (u > other_best) other_best = u, k.other_draw_deg = d;
          }
          k.other_draw_loss = std::max(
              0.0, brute - evaluator.Evaluate(kick, k.other_draw_deg * kDegToRad).trimmed_utility);
          CoarseActionEvaluator heldout = HeldOutEvaluator(planner, t);
          k.brute_heldout = heldout.Evaluate(kick, brute_deg * kDegToRad).trimmed_utility;
          k.found_heldout = heldout.Evaluate(kick, c.rotation_rad).trimmed_utility;
          shipped.push_back(k);
        }
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
  // The shipped search's worst cases, and its loss measured on held-out samples: the brute
  // force's best rotation on the 30 samples against the search's, each valued with
  // kHeldOutSamples other samples (a difference below zero: the search's rotation is better).
  std::vector<Case> worst = shipped;
  std::sort(worst.begin(), worst.end(), [](const Case& a, const Case& b) { return a.loss > b.loss; });
  std::printf("shipped search's worst cases (30-sample loss; both rotations on %d held-out samples):\n",
              kHeldOutSamples);
  for (std::size_t i = 0; i < std::min<std::size_t>(8, worst.size()); ++i) {
    Case& k = worst[i];
    k.best_heldout = HeldOutBest(situations[static_cast<std::size_t>(k.pose)], k.pose, k.kick);
    std::printf(
        "  pose %3d kick %d: loss %.4f, brute %7.2f deg, found %7.2f deg, %5.2f deg of the circle "
        "better; held out: brute %.4f found %.4f (brute - found %+.4f), best %.4f; exhaustive "
        "on another draw: %7.2f deg, loss %.4f\n",
        k.pose, k.kick, k.loss, k.brute_deg, k.found_deg, k.better_deg, k.brute_heldout,
        k.found_heldout, k.brute_heldout - k.found_heldout, k.best_heldout, k.other_draw_deg,
        k.other_draw_loss);
  }
  // The noise floor over all cases: the loss on the 30 samples of the exhaustive search's choice
  // made on 30 other samples, beside the shipped search's loss on the samples it searched.
  double other_total = 0.0, other_worst = 0.0, found_total = 0.0;
  int other_above = 0, found_above = 0;
  for (const Case& k : shipped) {
    other_total += k.other_draw_loss;
    other_worst = std::max(other_worst, k.other_draw_loss);
    other_above += k.other_draw_loss > 0.01;
    found_total += k.loss;
    found_above += k.loss > 0.01;
  }
  std::printf(
      "on the 30 samples: the shipped search loses mean %.2e, above 0.01 in %d cases; the "
      "exhaustive search's choice from 30 other samples loses mean %.2e, worst %.4f, above 0.01 "
      "in %d of %zu cases\n",
      found_total / shipped.size(), found_above, other_total / shipped.size(), other_worst,
      other_above, shipped.size());
  // Every 10th case against the held-out best: how far each choice of the 30 samples falls
  // short of the best rotation for the held-out samples (the sampling noise both searches share).
  double brute_regret = 0.0, found_regret = 0.0, brute_regret_worst = 0.0,
         found_regret_worst = 0.0;
  int looked = 0;
  for (std::size_t i = 0; i < shipped.size(); i += 10, ++looked) {
    const Case& k = shipped[i];
    const double best = HeldOutBest(situations[static_cast<std::size_t>(k.pose)], k.pose, k.kick);
    brute_regret += best - k.brute_heldout;
    found_regret += best - k.found_heldout;
    brute_regret_worst = std::max(brute_regret_worst, best - k.brute_heldout);
    found_regret_worst = std::max(found_regret_worst, best - k.found_heldout);
  }
  std::printf(
      "every 10th case (%d), short of the held-out best rotation: brute force's choice mean %.4f "
      "worst %.4f, the search's mean %.4f worst %.4f\n",
      looked, brute_regret / looked, brute_regret_worst, found_regret / looked,
      found_regret_worst);
  double heldout_worst = 0.0, heldout_total = 0.0, heldout_signed = 0.0;
  int above_001 = 0;
  for (const Case& k : shipped) {
    const double d = k.brute_heldout - k.found_heldout;
    heldout_worst = std::max(heldout_worst, d);
    heldout_total += std::max(0.0, d);
    heldout_signed += d;
    above_001 += d > 0.01;
  }
  std::printf(
      "held out (%d samples): brute force's rotation better than the search's by worst %.4f, mean "
      "%.2e (signed mean %+.2e), above 0.01 in %d of %zu cases\n",
      kHeldOutSamples, heldout_worst, heldout_total / shipped.size(),
      heldout_signed / shipped.size(), above_001, shipped.size());
  return 0;
}

}  // namespace
}  // namespace foresight

int main(int argc, char** argv) {
  const int poses = argc > 1 ? std::atoi(argv[1]) : 300;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 5;
  return foresight::Run(poses, seed);
}
