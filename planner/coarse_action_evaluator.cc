#include "planner/coarse_action_evaluator.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "planner/ball_roll.h"
#include "planner/roll_lanes.h"

namespace foresight {

CoarseActionEvaluator::CoarseActionEvaluator(const Situation& situation, const StateEstimate& state,
                                             const CoarseWorld& world, const PositionValue& value,
                                             int samples, std::uint64_t seed)
    : ActionEvaluator(situation, state), world_(world), value_(value) {
  Redraw(state, samples, seed);
}

void CoarseActionEvaluator::Redraw(const StateEstimate& state, int samples, std::uint64_t seed) {
  state_ = state;
  sample_count_ = samples;
  padded_count_ = static_cast<std::size_t>((samples + kLanes - 1) / kLanes * kLanes);
  // Padding lanes hold a ball at the centre spot without noise; their results are never summed.
  ball_x_.resize(padded_count_);
  ball_y_.resize(padded_count_);
  start_category_.resize(padded_count_);
  const std::size_t slots = static_cast<std::size_t>(kick_count()) * padded_count_;
  direction_x_.resize(slots);
  direction_y_.resize(slots);
  speed_mps_.resize(slots);
  stop_m_.resize(slots);
  moving_.resize(slots);
  const Lanes zero = Broadcast(0.0);
  LaneMask drawn = BroadcastMask(-1);
  SampleLanes groups_drawn[kDrawGroups];
  for (std::size_t first = 0; first < padded_count_; first += kLanes) {
    const std::size_t group = first / kLanes % kDrawGroups;
    if (group == 0) {
      const int groups = static_cast<int>(
          std::min<std::size_t>(kDrawGroups, (padded_count_ - first) / kLanes));
      DrawSampleGroups(state, seed, first, groups, groups_drawn);
    }
    const SampleLanes& s = groups_drawn[group];
    if (first + kLanes > static_cast<std::size_t>(samples)) {
      for (int l = 0; l < kLanes; ++l) drawn[l] = first + l < static_cast<std::size_t>(samples) ? -1 : 0;
    }
    const Lanes x = Select(drawn, s.ball_x, zero), y = Select(drawn, s.ball_y, zero);
    Store(x, &ball_x_[first]);
    Store(y, &ball_y_[first]);
    StoreMask(ClassifyPositionLanes(world_.lines, x, y), &start_category_[first]);
    const Lanes theta_rad = Select(drawn, s.robot_theta_rad, zero);
    const Lanes z_speed = Select(drawn, s.z_speed, zero);
    const Lanes z_direction = Select(drawn, s.z_direction, zero);
    // The launches as MakeAction draws them and CoarseSimulator turns them into F.
    for (int k = 0; k < kick_count(); ++k) {
      const KickSpec& kick = situation_.kicks.kicks[static_cast<std::size_t>(k)];
      const Lanes speed = LaunchSpeed(kick, z_speed);
      Lanes sin_heading, cos_heading;
      SinCosLanes(theta_rad + LaunchDirection(kick, z_direction), &sin_heading, &cos_heading);
      const LaneMask moving = speed > 0.0;
      const std::size_t slot = LaunchSlot(k, first);
      Store(cos_heading, &direction_x_[slot]);
      Store(sin_heading, &direction_y_[slot]);
      Store(speed, &speed_mps_[slot]);
      // StopDistance plus the launch offset, as RollBall adds them.
      Store(Select(moving, speed * speed / (2.0 * world_.deceleration_mps2) + kick.launch_offset_m,
                   zero),
            &stop_m_[slot]);
      StoreMask(moving, &moving_[slot]);
    }
  }
}

Outcome CoarseActionEvaluator::SimulateOne(int kick_index, std::size_t sample, double cos_rho,
                                           double sin_rho) const {
  const Vec2 p(ball_x_[sample], ball_y_[sample]);
  if (kick_index == kNoKick) return RollBall(world_, p, Vec2(1.0, 0.0), 0.0);
  const std::size_t slot = LaunchSlot(kick_index, sample);
  const double ux = direction_x_[slot], uy = direction_y_[slot];
  const Vec2 direction(cos_rho * ux - sin_rho * uy, sin_rho * ux + cos_rho * uy);
  return RollBall(world_, p, direction, speed_mps_[slot],
                  situation_.kicks.kicks[static_cast<std::size_t>(kick_index)].launch_offset_m);
}

ActionEvaluation CoarseActionEvaluator::EvaluateReference(int kick_index,
                                                          double rotation_rad) const {
  double sin_rho, cos_rho;
  SinCos(rotation_rad, &sin_rho, &cos_rho);
  HypothesisAccumulator hypothesis;
  for (int i = 0; i < sample_count_; ++i) {
    AddOutcome(hypothesis, SimulateOne(kick_index, static_cast<std::size_t>(i), cos_rho, sin_rho),
               value_);
  }
  return hypothesis.Finish(situation_.evaluation);
}

RollLanesInput CoarseActionEvaluator::Launch(int kick_index, std::size_t first, double cos_rho,
                                             double sin_rho) const {
  const std::size_t slot = LaunchSlot(kick_index, first);
  const Lanes ux = Load(&direction_x_[slot]), uy = Load(&direction_y_[slot]);
  RollLanesInput in;
  in.start_x = Load(&ball_x_[first]);
  in.start_y = Load(&ball_y_[first]);
  in.dir_x = cos_rho * ux - sin_rho * uy;
  in.dir_y = sin_rho * ux + cos_rho * uy;
  in.stop_m = Load(&stop_m_[slot]);
  in.moving = LoadMask(&moving_[slot]);
  in.start_category = LoadMask(&start_category_[first]);
  in.speed_mps = Load(&speed_mps_[slot]);
  in.offset_m =
      Broadcast(situation_.kicks.kicks[static_cast<std::size_t>(kick_index)].launch_offset_m);
  return in;
}

RestLanes CoarseActionEvaluator::RestingLanes(std::size_t first) const {
  return {Load(&ball_x_[first]), Load(&ball_y_[first]), LoadMask(&start_category_[first])};
}

ActionEvaluation CoarseActionEvaluator::Run(int kick_index, double rotation_rad, int samples,
                                            bool stop_when_trimmed) {
  ++evaluations_;
  const EvaluationParams& params = situation_.evaluation;
  // SinCos(+0.0) is (+0.0, 1.0) exactly; the paper's decision turns by no more.
  double sin_rho = 0.0, cos_rho = 1.0;
  if (rotation_rad != 0.0 || std::signbit(rotation_rad)) SinCos(rotation_rad, &sin_rho, &cos_rho);
  const int count = std::min(samples, sample_count_);
  // More outs than this, or one own goal, trims the N-sample action whatever the other
  // samples do.
  const int max_outs = MaxOuts(params, sample_count_);
  constexpr int kOut = static_cast<int>(Category::kOut);
  constexpr int kOwnGoal = static_cast<int>(Category::kOwnGoal);
  // HypothesisAccumulator's slot sums in lanes: sample i goes to slot i mod 8, which is lane
  // i mod kLanes of slot vector (i mod 8) / kLanes.
  constexpr int kSlotVectors = HypothesisAccumulator::kSumSlots / kLanes;
  static_assert(kSlotVectors * kLanes == HypothesisAccumulator::kSumSlots);
  const Lanes zero = Broadcast(0.0);
  Lanes value_sum[kSlotVectors], potential_sum[kSlotVectors], potential_all_sum[kSlotVectors];
  for (int v = 0; v < kSlotVectors; ++v) {
    value_sum[v] = potential_sum[v] = potential_all_sum[v] = zero;
  }
  int counts[kCategoryCount] = {};  // copied out at the end: kept in registers meanwhile
  HypothesisAccumulator by_sample;   // the 2-lane build's sums
  bool trimmed = false;
  // Chunks of kChunkGroups lane groups (32 samples, a multiple of the 8 slots): rolled, then
  // valued together (independent work side by side), then summed. A search stops at the sample
  // with which the candidate is certainly trimmed, with the sums up to that sample.
  constexpr int kChunkGroups = 32 / kLanes;
  for (std::size_t chunk = 0; chunk < static_cast<std::size_t>(count) && !trimmed;
       chunk += kChunkGroups * kLanes) {
    Lanes x[kChunkGroups], y[kChunkGroups], potential[kChunkGroups];
    LaneMask category[kChunkGroups];
    int groups = 0;
    for (std::size_t first = chunk; first < static_cast<std::size_t>(count) && groups < kChunkGroups;
         first += kLanes) {
      const RestLanes rest = kick_index == kNoKick
                                 ? RestingLanes(first)
                                 : RollLanes(world_, Launch(kick_index, first, cos_rho, sin_rho));
      x[groups] = rest.x;
      y[groups] = rest.y;
      category[groups] = rest.category;
      ++groups;
      // The samples rolled (not the lanes: the same count whatever the width).
      samples_simulated_ += static_cast<long long>(
          std::min<std::size_t>(kLanes, static_cast<std::size_t>(count) - first));
    }
    value_.PotentialLanes(x, y, potential, groups);
    for (int g = 0; g < groups && !trimmed; ++g) {
      const Lanes value = value_.ValueOfPotentialLanes(potential[g]);
      const std::size_t first = chunk + static_cast<std::size_t>(g) * kLanes;
      const int lanes = static_cast<int>(
          std::min<std::size_t>(kLanes, static_cast<std::size_t>(count) - first));
      if constexpr (kLanes == 2) {
        // With 2 lanes the accumulator's Add, sample by sample, is as fast (its 8 slots are
        // independent chains) and needs no lane masks (measured: the masks cost silvermont's
        // optimal_all 6 %).
        for (int l = 0; l < lanes && !trimmed; ++l) {
          by_sample.Add(static_cast<Category>(category[g][l]), value[l], potential[g][l]);
          trimmed = stop_when_trimmed && by_sample.CertainlyTrimmed(max_outs);
        }
      } else {
        // The lanes summed: all samples of the group, or up to the one that trims.
        unsigned taken = (1U << lanes) - 1U;
        int added[kCategoryCount];
        for (int c = 0; c < kCategoryCount; ++c) {
          added[c] = __builtin_popcount(MaskBits(category[g] == c) & taken);
        }
        if (stop_when_trimmed &&
            Trimmed(counts[kOut] + added[kOut], counts[kOwnGoal] + added[kOwnGoal], max_outs)) {
          int outs = counts[kOut], own_goals = counts[kOwnGoal], l = 0;
          for (;; ++l) {
            outs += category[g][l] == kOut;
            own_goals += category[g][l] == kOwnGoal;
            if (Trimmed(outs, own_goals, max_outs)) break;
          }
          taken = (2U << l) - 1U;
          for (int c = 0; c < kCategoryCount; ++c) {
            added[c] = __builtin_popcount(MaskBits(category[g] == c) & taken);
          }
          trimmed = true;
        }
        const LaneMask take = MaskOfBits(taken);
        const LaneMask infield =
            take & (category[g] == static_cast<std::int64_t>(Category::kInfield));
        const int v = g % kSlotVectors;
        value_sum[v] += Select(infield, value, zero);
        potential_sum[v] += Select(infield, potential[g], zero);
        potential_all_sum[v] += Select(take, potential[g], zero);
        for (int c = 0; c < kCategoryCount; ++c) counts[c] += added[c];
      }
    }
  }
  if constexpr (kLanes == 2) return by_sample.Finish(params, sample_count_);
  alignas(64) double slots[3][HypothesisAccumulator::kSumSlots];
  for (int v = 0; v < kSlotVectors; ++v) {
    Store(value_sum[v], &slots[0][v * kLanes]);
    Store(potential_sum[v], &slots[1][v * kLanes]);
    Store(potential_all_sum[v], &slots[2][v * kLanes]);
  }
  std::array<int, kCategoryCount> counted;
  for (int c = 0; c < kCategoryCount; ++c) counted[c] = counts[c];
  return HypothesisAccumulator::FromSlots(counted, slots[0], slots[1], slots[2])
      .Finish(params, sample_count_);
}

std::vector<Outcome> CoarseActionEvaluator::Outcomes(int kick_index, double rotation_rad) const {
  double sin_rho, cos_rho;
  SinCos(rotation_rad, &sin_rho, &cos_rho);
  std::vector<Outcome> outcomes;
  outcomes.reserve(static_cast<std::size_t>(sample_count_));
  for (int i = 0; i < sample_count_; ++i) {
    outcomes.push_back(SimulateOne(kick_index, static_cast<std::size_t>(i), cos_rho, sin_rho));
  }
  return outcomes;
}

}  // namespace foresight
