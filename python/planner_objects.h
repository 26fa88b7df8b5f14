// The module's in-memory objects: a Planner built once (from a situation file or dict) and
// reused for any number of decisions, the small classes Pose, Ball, Obstacle and KickModel, and
// the Decision a planner returns. A decision from Python runs the C++ robot-cycle path
// (CoarsePlanner::Decide with a kept evaluator and Decision: no file, no allocation but the
// result's), so it costs about what the C++ decision costs (docs/PERFORMANCE.md).
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "models/situation.h"
#include "planner/coarse_planner.h"

namespace foresight::python {

// A robot pose in the field frame F (metres, degrees); unset sigmas keep the planner's.
struct PoseArg {
  double x_m = 0.0, y_m = 0.0, theta_deg = 0.0;
  std::optional<double> sigma_x_m, sigma_y_m, sigma_theta_deg;
};

// The ball relative to the robot, in its frame R (metres); unset sigmas keep the planner's.
struct BallArg {
  double x_m = 0.0, y_m = 0.0;
  std::optional<double> sigma_x_m, sigma_y_m;
};

// An obstacle robot in F (metres); unset radius: the field's default.
struct ObstacleArg {
  double x_m = 0.0, y_m = 0.0;
  std::optional<double> radius_m;
};

// A checked kick model, from a file or a dict, with the name it is reported by.
struct KickModelArg {
  KickModel model;
  std::string source;
};

// What a Planner holds: the situation, the planner over its scene, and the evaluator and
// Decision kept between decisions (guarded by `mutex`, taken through PlannerLock: one decision
// at a time per planner; `owner` is the thread that holds it).
struct PlannerCore {
  Situation situation;
  Situation check;  // the situation with each decision's state, for Situation::Validate
  std::unique_ptr<CoarsePlanner> planner;
  std::optional<CoarseActionEvaluator> evaluator;
  Decision scratch;
  std::filesystem::path models;
  std::string situation_file;  // "" for a dict
  Strategy strategy = Strategy::kOptimalAll;
  int samples = 0;
  std::timed_mutex mutex;
  std::atomic<std::thread::id> owner{};
};

// Holds core.mutex for one decision or one decide_many; made and destroyed with the GIL. It
// waits with the GIL released (a long call, decide_many, holds the mutex without the GIL and
// takes the GIL to poll for Ctrl-C), polling Python's signal handlers, so Ctrl-C ends the wait.
// A thread that already holds the planner (a decide_many progress callback calling decide or
// decide_many on the same planner) would wait for itself: that is refused with RuntimeError.
class PlannerLock {
 public:
  explicit PlannerLock(PlannerCore& core);
  ~PlannerLock();
  PlannerLock(const PlannerLock&) = delete;
  PlannerLock& operator=(const PlannerLock&) = delete;

 private:
  PlannerCore& core_;
};

// Builds the core from a situation (path or dict) with an optional kick model (path, dict or
// KickModel) replacing the situation's.
std::shared_ptr<PlannerCore> MakePlannerCore(const pybind11::object& situation,
                                             const pybind11::object& kicks,
                                             const pybind11::object& strategy,
                                             const pybind11::object& samples,
                                             const pybind11::object& coarse_rebounds,
                                             const std::optional<std::filesystem::path>& models);

// A robot pose, a ball and a kick model from the Python values a decision accepts: the class, a
// dict with the situation file's keys or a tuple (x_m, y_m[, theta_deg]); a kick model also from
// a path or a dict. Bad values are InputErrors naming `where` (value_objects.cc).
PoseArg PoseFrom(const pybind11::handle& value, const std::string& where);
BallArg BallFrom(const pybind11::handle& value, const std::string& where);
KickModelArg KickModelFrom(const pybind11::handle& value);
// The pose or ball set into `state`; unset sigmas stay.
void ApplyPose(const PoseArg& pose, StateEstimate& state);
void ApplyBall(const BallArg& ball, StateEstimate& state);

// The flags of a decision from Python values (None: `fallback`); bad values are InputErrors.
std::uint64_t SeedFrom(const pybind11::handle& value);
Strategy StrategyFrom(const pybind11::handle& value, Strategy fallback);
int SamplesFrom(const pybind11::handle& value, int fallback);

// One decision for `state` into core.scratch, the state checked as a situation file's would be
// (Situation::Validate). The caller holds core.mutex.
void DecideLocked(PlannerCore& core, const StateEstimate& state, Strategy strategy, int samples,
                  std::uint64_t seed);

// A decision and the planner it came from (for names and the full report).
struct DecisionResult {
  std::shared_ptr<PlannerCore> core;
  Decision decision;
  int samples = 0;
  std::uint64_t seed = 0;
  StateEstimate state;
};

// What `foresight decide --json` prints for this decision, as a Python dict.
pybind11::object DecisionDict(const DecisionResult& result);

// The situation as a dict: name, files, kick names, belief (robot in F, ball in R), obstacles.
pybind11::dict SituationDict(const Situation& situation);

// Registers Pose, Ball, Obstacle and KickModel (value_objects.cc).
void AddValueObjects(pybind11::module_& module);
// Registers those, Decision and Planner.
void AddPlannerObjects(pybind11::module_& module);
// Planner.decide_many: decisions for many poses, NumPy in and out (planner_arrays.cc).
void AddPlannerArrays(pybind11::class_<PlannerCore, std::shared_ptr<PlannerCore>>& planner);

}  // namespace foresight::python
