// A random search with refinement over one kick motion's keyframes and its weight shift, in the
// project's physics: how the NAO's shipped forward_long and side kicks were fitted (their
// settings and start motions in models/motion_search/), so that a team can fit motions to its
// own robot. Settings (seed, rounds, refusal rules, objective) come from a file
// (tools/motion_search_settings.h).
//
// Round r draws its candidates around a centre: the settings' start motion (or the robot's
// shipped one) in the first round, the best candidate of the round before in the others.
// Candidate 0 of every round is the centre unchanged (the baseline in the first round, the
// incumbent after it), scored again on the round's own trials, and the candidates are ranked
// within their round only. Why: the best
// of many candidates scored on a few trials is the luckiest as often as the best (a candidate
// at 1.583 m/s over 8 trials launched 1.480 over 200); ranked across rounds, it stayed "best so
// far" and the later rounds, with more trials per candidate, centred on it. Scored again with
// the round's trials it keeps its place only by beating the round's other candidates on the
// same placements, playback speeds and carpets (common random numbers, so the difference between
// two candidates is measured with less noise than either score). A lower confidence bound on
// the score was the alternative; the score is not a mean (|mean - target| plus shares and an
// sd), so its bound would need an error model of its own, and it would still compare scores
// measured on different trials. A candidate moves every joint of every inner keyframe (the first and the last,
// the stance, stay) by a normal draw, clamped to the joint's limits; stretches every segment's
// duration by a normal factor; and adds one normal draw to the magnitude of every balance offset
// (equal and opposite offsets stay so). A segment in which a joint would pass max_speed_share of
// its URDF limit at the fastest playback a trial draws is slowed until it does not
// (FitToSpeedLimit). Each candidate is then
//   refused for speed     when a joint still passes it (models/robot_spec.h), or when the
//                         slowed motion lasts longer than max_duration_s;
//   refused for clearance when the links the motion moves come closer to the carpet than
//                         min_clearance_m over its targets (FindSwingClearance,
//                         physics/motion_clearance.h);
//   refused for speed     also when, played alone at the fastest playback, a joint turns
//                         faster than max_speed_share of its motor's no-load speed
//                         (FindPlayedSpeedShare, physics/played_speed.h): a joint carried on
//                         by the links around it can outrun what its target asks;
//   refused for balance   when the robot falls while shifting its weight, or falls in more
//                         than max_fall_share of its trials, or its torso tilts more than
//                         max_tilt_deg (the round's own, if it names one) in any of them
//                         (floating base);
// and otherwise scored by the objective over `trials` physics trials (lower is better).
//
// Determinism: candidate c >= 1 of round r draws from StreamKey(seed, r * 2^20 + c, domain); the
// trials of every candidate of round r use the physics streams of seed StreamKey(seed, r, ...)
// (common random numbers: the candidates of a round meet the same placements, playback speeds
// and carpets). Same settings, same results, whatever the thread count.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "models/kick_motion.h"
#include "physics/physics_runs.h"
#include "physics/physics_setup.h"
#include "tools/motion_search_settings.h"

namespace foresight {

enum class Refusal { kNone, kSpeed, kClearance, kBalance };
std::string_view RefusalName(Refusal refusal);

struct SearchCandidate {
  int round = 0;
  int index = 0;  // within its round
  KickMotion motion;
  Refusal refusal = Refusal::kNone;
  double score = 0.0;           // meaningful when not refused
  double speed_share = 0.0;     // peak joint speed / limit at the fastest playback
  double clearance_m = 0.0;
  TrialSummary summary;         // empty when refused before the trials
  double low_share = 0.0;       // of touched trials, launches below min_speed_mps
};

struct MotionSearchResult {
  std::vector<SearchCandidate> candidates;  // every candidate, in round and index order
  // Indices into candidates, best first: the scored ones of the last round that scored any (a
  // round whose candidates were all refused leaves the ranking of the round before).
  std::vector<int> best;
};

// The score of a summary under the objective (lower is better); low_share as in SearchCandidate.
double ScoreCandidate(const SearchObjective& objective, const TrialSummary& summary,
                      double low_share);

// Slows the segments of `motion` in which a joint would turn faster than max_share of its URDF
// limit (as written), one segment at a time, until none does or 20 passes are spent; the later
// keyframes move by what a segment gains. The shipped motions' searches timed the strike to a
// share of the limit likewise.
void FitToSpeedLimit(KickMotion& motion, const RobotModel& model, double max_share);

// Candidate `index` drawn around `centre` with the round's spreads (index 0 of the first round
// is the centre itself; the caller decides).
KickMotion DrawCandidate(const KickMotion& centre, const RobotModel& model,
                         const SearchRound& round, std::uint64_t stream);

struct MotionSearchRun {
  const MotionSearchSettings* settings = nullptr;
  const PhysicsSetup* setup = nullptr;  // loaded with settings' situation, kicks and base
  int threads = 0;                      // <= 0: all cores
  // Called after each round with the candidates so far (e.g. to print the round's best).
  std::function<void(int round, const MotionSearchResult&)> round_done;
};

MotionSearchResult RunMotionSearch(const MotionSearchRun& run);

// Loads the physics the settings name (throws InputError on bad files or an unknown kick).
std::unique_ptr<PhysicsSetup> LoadSearchSetup(const MotionSearchSettings& settings,
                                              const std::filesystem::path& models_dir);

}  // namespace foresight
