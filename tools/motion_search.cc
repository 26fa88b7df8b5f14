#include "tools/motion_search.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/error.h"
#include "common/geometry.h"
#include "common/random.h"
#include "models/situation.h"
#include "physics/motion_clearance.h"
#include "physics/played_speed.h"
#include "physics/settled_stance.h"

namespace foresight {

namespace {

constexpr std::uint64_t kCandidateDomain = 0x6d6f74696f6e7331ULL;  // "motions1"
constexpr std::uint64_t kTrialSeedDomain = 0x6d6f74696f6e7332ULL;
constexpr std::uint64_t kRoundStride = 1ULL << 20;  // candidates per round stay below it
// Stretching the segment that holds a joint's peak speed settles within a few passes; a motion
// still too fast after these is refused for speed.
constexpr int kMaxRetimePasses = 20;

const RobotJoint& JointNamed(const RobotModel& model, const std::string& name) {
  return model.joints[static_cast<std::size_t>(*model.FindJoint(name))];
}

// The candidate's physics: a robot whose motion m is the candidate, its settled stance (on a
// floating base with a balance), the scene and the simulator, and the trials.
struct Played {
  bool shift_fell = false;
  std::vector<TrialResult> results;
};

Played Play(const MotionSearchRun& run, Robot& robot, int motion_index, int kick_index,
            int trials, std::uint64_t trial_seed) {
  const PhysicsSetup& setup = *run.setup;
  const KickMotion& motion = robot.motions[static_cast<std::size_t>(motion_index)];
  Played played;
  // Only this motion is played, so only its stance is settled.
  SettledStances settled(robot.motions.size());
  if (setup.params.robot.base == RobotBase::kFloating && motion.balance.Has()) {
    settled[static_cast<std::size_t>(motion_index)] = SettleBalance(robot, motion, setup.params);
    if (settled[static_cast<std::size_t>(motion_index)]->fell) {
      played.shift_fell = true;
      return played;
    }
  }
  const Situation& s = setup.situation;
  const PhysicsSimulator simulator(
      MakePhysicsScene(s.field, setup.params, &robot, s.obstacles, setup.state.p_F_ball, &settled),
      s.kicks);
  KickTrialsRequest request;
  request.state = setup.state;
  request.kick_index = kick_index;
  request.trials = trials;
  request.seed = trial_seed;
  request.threads = run.threads;
  played.results = RunKickTrials(simulator, request);
  return played;
}

void Evaluate(const MotionSearchRun& run, Robot& robot, int motion_index, int kick_index,
              const SearchRound& round, std::uint64_t trial_seed, SearchCandidate& c) {
  const MotionSearchSettings& settings = *run.settings;
  const double max_factor = robot.spec.variation.MaxSpeedFactor();
  FitToSpeedLimit(c.motion, robot.model, settings.constraints.max_speed_share / max_factor);
  c.speed_share = FindPeakJointSpeed(c.motion, robot.model).share * max_factor;
  if (c.speed_share > settings.constraints.max_speed_share ||
      c.motion.DurationS() > settings.constraints.max_duration_s) {
    c.refusal = Refusal::kSpeed;
    return;
  }
  robot.motions[static_cast<std::size_t>(motion_index)] = c.motion;
  c.clearance_m = FindSwingClearance(robot, c.motion).lowest_m;
  if (c.clearance_m < settings.constraints.min_clearance_m) {
    c.refusal = Refusal::kClearance;
    return;
  }
  // The targets' speed is not the joints': a joint carried on by the links swinging around it
  // may outrun its motor where its own target does not ask it to.
  if (FindPlayedSpeedShare(robot, c.motion, run.setup->params, max_factor) >
      settings.constraints.max_speed_share) {
    c.refusal = Refusal::kSpeed;
    return;
  }
  Played played = Play(run, robot, motion_index, kick_index, round.trials, trial_seed);
  if (played.shift_fell) {
    c.refusal = Refusal::kBalance;
    return;
  }
  c.summary = Summarize(played.results);
  int low = 0;
  for (const TrialResult& r : played.results) {
    low += r.touched && r.launch_speed_mps < settings.objective.min_speed_mps;
  }
  c.low_share = c.summary.touched > 0 ? static_cast<double>(low) / c.summary.touched : 0.0;
  if (static_cast<double>(c.summary.fell) > settings.constraints.max_fall_share * c.summary.trials ||
      c.summary.max_tilt_rad > round.max_tilt_rad.value_or(settings.constraints.max_tilt_rad)) {
    c.refusal = Refusal::kBalance;
    return;
  }
  c.score = ScoreCandidate(settings.objective, c.summary, c.low_share);
}

// The scored candidates of `round`, best first (ties by index, so the order is total).
std::vector<int> Rank(const std::vector<SearchCandidate>& candidates, int round) {
  std::vector<int> order;
  for (int i = 0; i < static_cast<int>(candidates.size()); ++i) {
    const SearchCandidate& c = candidates[static_cast<std::size_t>(i)];
    if (c.round == round && c.refusal == Refusal::kNone) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return candidates[static_cast<std::size_t>(a)].score <
           candidates[static_cast<std::size_t>(b)].score;
  });
  return order;
}

}  // namespace

void FitToSpeedLimit(KickMotion& motion, const RobotModel& model, double max_share) {
  for (int pass = 0; pass < kMaxRetimePasses; ++pass) {
    const PeakJointSpeed peak = FindPeakJointSpeed(motion, model);
    if (peak.joint < 0 || peak.share <= max_share) return;
    // The segment holding the peak, stretched by the excess (and a hair more, so that the
    // tangents of the neighbouring keyframes, which depend on it too, settle in a few passes).
    std::size_t k = 1;
    while (k + 1 < motion.keyframes.size() && motion.keyframes[k].time_s < peak.t_s) ++k;
    const double stretch_s = (motion.keyframes[k].time_s - motion.keyframes[k - 1].time_s) *
                             (peak.share / max_share * 1.001 - 1.0);
    for (std::size_t i = k; i < motion.keyframes.size(); ++i) motion.keyframes[i].time_s += stretch_s;
  }
}

std::string_view RefusalName(Refusal refusal) {
  switch (refusal) {
    case Refusal::kNone: return "none";
    case Refusal::kSpeed: return "speed";
    case Refusal::kClearance: return "clearance";
    case Refusal::kBalance: return "balance";
  }
  return "none";
}

double ScoreCandidate(const SearchObjective& o, const TrialSummary& s, double low_share) {
  const double trials = std::max(1, s.trials);
  const double miss_share = 1.0 - s.launched / trials;
  const double fall_share = s.fell / trials;
  double score = std::abs(s.launch_speed_mean_mps - o.target_speed_mps);
  score += o.sd_weight * std::max(0.0, s.launch_speed_sd_mps - o.speed_sd_max_mps);
  score += o.low_weight * low_share;
  if (s.touched > 0) {
    const double direction_error =
        std::abs(WrapAngle(s.launch_direction_mean_rad - o.target_direction_rad));
    score += o.direction_weight * std::max(0.0, direction_error - o.direction_max_rad);
  }
  score += o.miss_weight * miss_share;
  score += o.fall_weight * fall_share;
  return score;
}

KickMotion DrawCandidate(const KickMotion& centre, const RobotModel& model,
                         const SearchRound& round, std::uint64_t stream) {
  RandomStream random(stream);
  KickMotion motion = centre;
  const std::size_t last = motion.keyframes.size() - 1;
  for (std::size_t k = 1; k < last; ++k) {
    for (std::size_t j = 0; j < motion.joints.size(); ++j) {
      const RobotJoint& joint = JointNamed(model, motion.joints[j]);
      double& q = motion.keyframes[k].positions_rad[j];
      q = std::clamp(q + round.keyframe_sigma_rad * random.NextNormal(), joint.lower_rad,
                     joint.upper_rad);
    }
  }
  // Segment durations stretch by exp(sigma N): always positive, as likely shorter as longer.
  double t_s = 0.0;
  for (std::size_t k = 1; k <= last; ++k) {
    const double duration_s = centre.keyframes[k].time_s - centre.keyframes[k - 1].time_s;
    t_s += duration_s * std::exp(round.time_sigma_rel * random.NextNormal());
    motion.keyframes[k].time_s = t_s;
  }
  const double shift_rad = round.balance_sigma_rad * random.NextNormal();
  for (auto& [name, offset_rad] : motion.balance.offsets_rad) {
    const double magnitude = std::max(0.0, std::abs(offset_rad) + shift_rad);
    offset_rad = std::copysign(magnitude, offset_rad);
  }
  return motion;
}

std::unique_ptr<PhysicsSetup> LoadSearchSetup(const MotionSearchSettings& settings,
                                              const std::filesystem::path& models_dir) {
  SituationOverrides overrides;
  overrides.kicks_file = settings.kicks_file;
  Situation situation = LoadSituation(settings.situation_file, models_dir, overrides);
  if (!situation.kicks.Find(settings.kick)) {
    throw InputError(settings.file.string() + ": kick: no kick '" + settings.kick + "' in " +
                     situation.kicks_file.string() + " (one of: " + situation.kicks.Names() + ")");
  }
  auto setup = LoadPhysicsSetup(std::move(situation), models_dir, {}, settings.base);
  const std::optional<int> motion_index = setup->robot.FindMotion(settings.kick);
  if (!motion_index) {
    throw InputError(settings.file.string() + ": kick: robot '" + setup->robot.spec.name +
                     "' has no motion for kick '" + settings.kick + "'");
  }
  if (!settings.start_file.empty()) {
    setup->robot.motions[static_cast<std::size_t>(*motion_index)] =
        LoadRobotKickMotion(setup->robot, settings.kick, settings.start_file);
  }
  return setup;
}

MotionSearchResult RunMotionSearch(const MotionSearchRun& run) {
  const MotionSearchSettings& settings = *run.settings;
  const PhysicsSetup& setup = *run.setup;
  Robot robot = setup.robot;  // its motion is replaced by each candidate in turn
  const int motion_index = *robot.FindMotion(settings.kick);
  const int kick_index = *setup.situation.kicks.Find(settings.kick);
  const KickMotion start = robot.motions[static_cast<std::size_t>(motion_index)];
  MotionSearchResult result;
  for (int r = 0; r < static_cast<int>(settings.rounds.size()); ++r) {
    const SearchRound& round = settings.rounds[static_cast<std::size_t>(r)];
    // A copy: the candidates vector grows below.
    const KickMotion centre =
        result.best.empty() ? start
                            : result.candidates[static_cast<std::size_t>(result.best[0])].motion;
    const std::uint64_t trial_seed =
        StreamKey(settings.seed, static_cast<std::uint64_t>(r), kTrialSeedDomain);
    for (int c = 0; c < round.candidates; ++c) {
      SearchCandidate candidate;
      candidate.round = r;
      candidate.index = c;
      const std::uint64_t index = static_cast<std::uint64_t>(r) * kRoundStride +
                                  static_cast<std::uint64_t>(c);
      // Candidate 0 is the centre itself: in the first round the start motion (the baseline),
      // in the others the incumbent, scored again on this round's trials.
      candidate.motion = c == 0 ? centre
                                : DrawCandidate(centre, robot.model, round,
                                                StreamKey(settings.seed, index, kCandidateDomain));
      Evaluate(run, robot, motion_index, kick_index, round, trial_seed, candidate);
      result.candidates.push_back(std::move(candidate));
    }
    // Ranked within the round only: its candidates met the same trials (common random numbers),
    // the earlier rounds' scores came from fewer trials and other draws. A round whose
    // candidates were all refused keeps the ranking before it.
    std::vector<int> ranked = Rank(result.candidates, r);
    if (!ranked.empty()) result.best = std::move(ranked);
    if (run.round_done) run.round_done(r, result);
  }
  return result;
}

}  // namespace foresight
