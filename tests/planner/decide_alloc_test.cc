// A robot's decision must not touch the heap: CoarsePlanner::Decide with a kept
// evaluator and Decision, for every strategy, many poses, seeds and sample counts, counted by a
// replacement of the global operator new. In a test binary of its own (planner_alloc_tests), so
// the replacement touches no other test.
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>
#include <string>

#include "common/random.h"
#include "planner/coarse_planner.h"
#include "tests/support/test_situations.h"

namespace {

// Counted only while a test asks, and only on its thread.
thread_local bool counting = false;
thread_local long long allocations = 0;

void* Allocate(std::size_t size) {
  if (counting) ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t size) {
  return Allocate(size);
}
void* operator new[](std::size_t size) {
  return Allocate(size);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace foresight {
namespace {

// Heap allocations made by `work` on this thread.
template <typename Work>
long long AllocationsIn(Work&& work) {
  allocations = 0;
  counting = true;
  work();
  counting = false;
  return allocations;
}

TEST(DecideAllocationTest, TheCounterSeesAnAllocation) {
  EXPECT_EQ(AllocationsIn([] {
              const std::string text(100, 'x');  // beyond the small-string buffer
              ASSERT_EQ(text.size(), 100u);
            }),
            1);
}

// The fresh form allocates (a new evaluator and Decision each time): the counter would catch a
// decision that allocates.
TEST(DecideAllocationTest, AFreshDecisionAllocates) {
  const Situation s = testing::MakeSituation(testing::Uncertain({.x_m = 1.0}));
  const CoarsePlanner planner(s);
  EXPECT_GT(AllocationsIn([&] { planner.Decide(Strategy::kOptimalAll, 30, 1); }), 0);
}

TEST(DecideAllocationTest, AKeptEvaluatorAndDecisionNeverAllocate) {
  const Situation base =
      testing::MakeSituation(testing::Uncertain({.x_m = 0.0}), {{Vec2(3.8, 0.4), 0.15}});
  const CoarsePlanner planner(base);
  CoarseActionEvaluator evaluator = planner.MakeEvaluator(30, 0);  // room for 30 samples
  Decision decision;
  ReserveDecision(decision, evaluator.kick_count());
  RandomStream rng(StreamKey(18, 1));
  int decisions = 0, fallbacks = 0, turned = 0, kicks = 0;
  for (int pose = 0; pose < 40; ++pose) {
    // Pose 0: the ball lies over the corner's lines, so no kick is acceptable and every
    // strategy but naoth falls back and writes its note.
    testing::StateSpec spec = testing::Uncertain({.x_m = 4.5, .y_m = 3.0, .theta_deg = 45});
    while (pose > 0) {
      spec = testing::RandomPose(rng, 4.4, 2.9);
      if ((Vec2(spec.x_m, spec.y_m) - Vec2(3.8, 0.4)).norm() >= 0.6)
        break;  // clear of the obstacle
    }
    const StateEstimate state = testing::MakeSituation(spec).state;
    for (Strategy strategy : AllStrategies()) {
      for (int samples : {30, 7, 1}) {
        const std::uint64_t seed = static_cast<std::uint64_t>(pose) * 7 + samples;
        EXPECT_EQ(AllocationsIn(
                      [&] { planner.Decide(state, strategy, samples, seed, evaluator, decision); }),
                  0)
            << StrategyName(strategy) << " pose " << pose << " samples " << samples;
        // What the fresh form decides, bit for bit.
        const Decision fresh = planner.Decide(state, strategy, samples, seed);
        EXPECT_EQ(decision.kick_index, fresh.kick_index);
        EXPECT_EQ(decision.rotation_rad, fresh.rotation_rad);
        EXPECT_EQ(decision.evaluations, fresh.evaluations);
        EXPECT_EQ(decision.note, fresh.note);
        ++decisions;
        fallbacks += !decision.note.empty();
        turned += decision.rotation_rad != 0.0;
        kicks += decision.kick_index != kNoKick;
      }
    }
  }
  EXPECT_EQ(decisions, 40 * 5 * 3);
  EXPECT_GT(fallbacks, 0);  // the poses include decisions that fall back and write a note
  EXPECT_GT(turned, 0);
  EXPECT_GT(kicks, decisions / 2);  // mostly the random poses, not the corner
}

}  // namespace
}  // namespace foresight
