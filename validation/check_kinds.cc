#include "validation/check_kinds.h"

#include <cmath>
#include <functional>
#include <string>
#include <variant>

#include "common/checks.h"
#include "common/enum_names.h"
#include "common/error.h"
#include "common/geometry.h"
#include "models/field_spec.h"
#include "models/kick_model.h"
#include "models/model_paths.h"
#include "physics/physics_scene.h"
#include "physics/robot_impact.h"
#include "physics/trial.h"
#include "report/report_format.h"
#include "stats/statistics.h"
#include "validation/calibration.h"
#include "validation/fidelity.h"
#include "validation/physics_calibration.h"

namespace foresight {

namespace {

CheckResult Result(bool passed, std::string detail) {
  CheckResult r;
  r.passed = passed;
  r.detail = std::move(detail);
  return r;
}

// The field and its physics with the carpet made uniform: checks of the engine, not the carpet.
struct UniformWorld {
  FieldSpec field;
  PhysicsParams params;
};

UniformWorld LoadUniformWorld(const std::string& field, const CheckSpec& spec,
                              const std::filesystem::path& models) {
  UniformWorld w;
  w.field = LoadFieldSpec(
      NamedFile("field", ResolveModelFile(field, DataFolder::kFields, spec.dir, models)));
  w.params = LoadPhysicsParams(DataFile(models, DataFolder::kPhysics, w.field.name));
  w.params.carpet.deceleration_sigma_rel = 0.0;
  w.params.carpet.patch_sigma_rel = 0.0;
  return w;
}

CheckResult Run(const FreeRollCheck& c, const CheckSpec& spec, const std::filesystem::path& models,
                int) {
  const UniformWorld w = LoadUniformWorld(c.field, spec, models);
  PhysicsScene scene = MakePhysicsScene(w.field, w.params, nullptr, {}, Vec2(0, 0));
  scene.carpet_has_edge = false;  // a check of the roll, not of the field: rolls run far
  const double v = c.speed_mps;
  const double a = w.params.carpet.rolling_deceleration_mps2;
  const double expected = v * v / (2.0 * a);
  const double heading = c.heading_deg * kDegToRad;
  const Vec2 dir = UnitVector(heading);
  const Vec2 start = -0.5 * expected * dir;
  const double r = w.field.ball.radius_m;
  const TrialResult trial = RunRollTrial(scene, RollingBall(start, r, v, heading), 1, true);
  const Vec2 travel = trial.outcome.p_F_rest - start;
  const double error_rel = std::abs(travel.norm() - expected) / expected;
  double lateral = 0.0;
  for (const TracePoint& p : trial.trace) {
    const Vec2 q = p.p_F.head<2>() - start;
    lateral = std::max(lateral, std::abs(dir.x() * q.y() - dir.y() * q.x()));
  }
  const bool ok = trial.settled && error_rel <= c.max_error_rel && lateral <= c.max_lateral_m;
  return Result(ok, "rolled " + Fixed(travel.norm(), 4) + " m, v^2/2a = " + Fixed(expected, 4) +
                        " m (error " + Fixed(error_rel * 100.0, 2) + " %, limit " +
                        Fixed(c.max_error_rel * 100.0, 2) + " %), off the line " +
                        Fixed(lateral * 1000.0, 1) + " mm (limit " +
                        Fixed(c.max_lateral_m * 1000.0, 1) + " mm)" +
                        (trial.settled ? "" : ", did not settle"));
}

CheckResult Run(const NoTunnellingCheck& c, const CheckSpec& spec,
                const std::filesystem::path& models, int) {
  const UniformWorld w = LoadUniformWorld(c.field, spec, models);
  const PhysicsScene scene = MakePhysicsScene(w.field, w.params, nullptr, {}, Vec2(0, 0));
  const double v = c.speed_mps;
  const double step_m = v * NearTimeStep(w.params.steps, v);
  double deepest = 0.0;
  int untouched = 0;
  for (int k = 0; k < c.phases; ++k) {
    const ImpactResult r = FireAt(scene, c.target, v, GapAtPhase(scene, v, double(k) / c.phases));
    deepest = std::max(deepest, r.penetration_m);
    untouched += r.touched ? 0 : 1;
  }
  const double limit = c.max_penetration_steps * step_m;
  const bool ok = untouched == 0 && deepest <= limit;
  return Result(ok, "ball at " + Fixed(v, 1) + " m/s into the " +
                        std::string(ImpactTargetName(c.target)) + " at " +
                        std::to_string(c.phases) + " phases: deepest " +
                        Fixed(deepest * 1000.0, 1) + " mm into it (limit " +
                        Fixed(limit * 1000.0, 1) + " mm, one step " + Fixed(step_m * 1000.0, 1) +
                        " mm)" + (untouched > 0 ? ", " + std::to_string(untouched) +
                                                      " shots never touched it"
                                                : ""));
}

CheckResult Run(const ReboundCheck& c, const CheckSpec& spec, const std::filesystem::path& models,
                int) {
  const UniformWorld w = LoadUniformWorld(c.field, spec, models);
  const PhysicsScene scene = MakePhysicsScene(w.field, w.params, nullptr, {}, Vec2(0, 0));
  const double e = TargetRestitution(scene, c.target);
  bool ok = true;
  std::string detail;
  for (double v : c.speeds_mps) {
    double worst_ratio = e, worst_error = 0.0;
    for (int k = 0; k < c.phases; ++k) {
      const ImpactResult r = FireAt(scene, c.target, v, GapAtPhase(scene, v, double(k) / c.phases));
      const double expected = e * r.approach_mps;
      const double error = std::abs(r.rebound_mps - expected);
      const double allowed = std::max(c.min_error_mps, c.max_error_rel * expected);
      if (!r.touched || error > allowed) ok = false;
      if (error >= worst_error) {
        worst_error = error;
        worst_ratio = r.approach_mps > 0.0 ? r.rebound_mps / r.approach_mps : 0.0;
      }
    }
    detail += (detail.empty() ? "" : "; ") + Fixed(v, 1) + " m/s: worst rebound/approach " +
              Fixed(worst_ratio, 3) + " (off by " + Fixed(worst_error * 1000.0, 1) + " mm/s)";
  }
  return Result(ok, std::string(ImpactTargetName(c.target)) + ", e = " + Fixed(e, 3) + ", " +
                        std::to_string(c.phases) + " phases per speed: " + detail);
}

CheckResult Run(const RobotReboundCheck& c, const CheckSpec& spec,
                const std::filesystem::path& models, int) {
  const UniformWorld w = LoadUniformWorld(c.field, spec, models);
  const Robot robot = LoadRobot(c.robot, models);
  const double e = w.params.materials.restitution.robot;
  const double mu = w.params.materials.friction.robot;
  const BallSpec& ball = w.field.ball;
  constexpr double kGapM = 0.01;  // the roll starts 1 cm before the first touch
  bool ok = true;
  std::string detail;
  for (double v : c.speeds_mps) {
    const RobotImpactResult r = RollIntoRobot(w.field, w.params, robot, c.link, v, kGapM);
    if (!r.touched) {
      ok = false;
      detail += (detail.empty() ? "" : "; ") + Fixed(v, 1) + " m/s: never touched";
      continue;
    }
    const double approach = -r.before.v_F.x();
    const RigidImpact theory =
        PredictRigidImpact(r.before, r.n_F, ball.radius_m, ball.inertia_factor, e, mu);
    const double back_error = std::abs(r.after.v_F.x() - theory.v_F.x()) / approach;
    const double up_error = std::abs(r.after.v_F.z() - theory.v_F.z()) / approach;
    const double e_error = std::abs(r.NormalRestitution() - e) / e;
    ok = ok && e_error <= c.max_error_rel && back_error <= c.max_error_rel &&
         up_error <= c.max_error_rel;
    detail += (detail.empty() ? "" : "; ") + Fixed(v, 1) + " m/s: normal " +
              Fixed(std::asin(std::clamp(r.n_F.z(), -1.0, 1.0)) * kRadToDeg, 1) +
              " deg up, e realised " + Fixed(r.NormalRestitution(), 3) + ", back " +
              Fixed(r.ReboundRatio(), 3) + " v (theory " + Fixed(theory.v_F.x() / approach, 3) +
              "), up " + Fixed(r.after.v_F.z() / approach, 3) + " v (theory " +
              Fixed(theory.v_F.z() / approach, 3) + "), hop " + Fixed(r.max_height_m * 1000.0, 1) +
              " mm";
  }
  return Result(ok, c.robot + " " + c.link + ", e = " + Fixed(e, 3) + ", mu = " + Fixed(mu, 2) +
                        ": " + detail);
}

// The calibration situation of the spec's robot with the spec's kick model, as `foresight
// calibrate --kicks` plays it.
PhysicsCalibrationSettings CalibrationSettingsOf(const std::string& robot, const std::string& kicks,
                                                 int trials, const CheckSpec& spec,
                                                 const std::filesystem::path& models, int threads) {
  PhysicsCalibrationSettings settings;
  settings.robot = robot;
  settings.kicks_file =
      NamedFile("kicks", ResolveModelFile(kicks, DataFolder::kKicks, spec.dir, models));
  settings.trials = trials;
  settings.threads = threads;
  settings.base = spec.base;
  return settings;
}

// The circular mean of the launch directions (stats/statistics.h).
double MeanDirection(const std::vector<KickObservation>& observations) {
  std::vector<double> directions;
  for (const KickObservation& o : observations) directions.push_back(o.launch_direction_rad);
  return SummarizeCircular(directions).mean_rad;
}

CheckResult Run(const KickDirectionCheck& c, const CheckSpec& spec,
                const std::filesystem::path& models, int threads) {
  PhysicsCalibrationSettings settings =
      CalibrationSettingsOf(c.robot, c.kicks, c.trials, spec, models, threads);
  settings.kick = c.kick;
  settings.kick_field = "kick";
  const PhysicsCalibration physics = RunPhysicsCalibration(settings, models);
  const PhysicsKickTrials& kick = physics.kicks.front();
  const int touched = static_cast<int>(kick.observations.size());
  const double mean = touched > 0 ? MeanDirection(kick.observations) : 0.0;
  const double expected = physics.model.kicks[kick.kick_index].direction_rad;
  const double error_deg = std::abs(WrapAngle(mean - expected)) * kRadToDeg;
  const bool ok =
      kick.missed == 0 && kick.fell == 0 && kick.blocked == 0 && error_deg <= c.max_error_deg;
  return Result(ok, std::to_string(touched) + " of " + std::to_string(settings.trials) +
                        " trials touched the ball standing, " + std::to_string(kick.fell) +
                        " fell, " + std::to_string(kick.blocked) + " blocked; mean direction " +
                        Fixed(mean * kRadToDeg, 1) + " deg, model " +
                        Fixed(expected * kRadToDeg, 1) + " deg (off by " + Fixed(error_deg, 1) +
                        ", limit " + Fixed(c.max_error_deg, 1) + ")");
}

CheckResult Run(const CalibrationBandCheck& c, const CheckSpec& spec,
                const std::filesystem::path& models, int threads) {
  PhysicsCalibrationSettings settings =
      CalibrationSettingsOf(c.robot, c.kicks, c.trials, spec, models, threads);
  settings.seed = c.seed;
  const PhysicsCalibration physics = RunPhysicsCalibration(settings, models);
  const double band = c.band_rel;
  bool ok = true;
  std::string detail;
  for (const PhysicsKickTrials& kick : physics.kicks) {
    const KickSpec& m = physics.model.kicks[kick.kick_index];
    const KickCalibration fit = CalibrateKick(m.name, kick.observations, CalibrationSettings{});
    const auto within = [&](double fitted, double committed) {
      return std::abs(fitted - committed) <= band * std::abs(committed);
    };
    const bool kick_ok =
        within(fit.speed.mean, m.speed_mps) && within(fit.speed.sd, m.sigma_speed_mps) &&
        within(fit.direction.sd_rad, m.sigma_direction_rad) &&
        std::abs(WrapAngle(fit.direction.mean_rad - m.direction_rad)) * kRadToDeg <= c.band_deg;
    ok = ok && kick_ok;
    // Both sides with the kick file's decimals: the committed figure as stored, the fit as a
    // calibration would store it.
    const auto pair = [](double fitted, double committed, int decimals) {
      return Fixed(fitted, decimals) + "/" + Fixed(committed, decimals);
    };
    detail += (detail.empty() ? "" : "; ") + m.name + (kick_ok ? " ok" : " OUT") + " (v0 " +
              pair(fit.speed.mean, m.speed_mps, kKickFileSpeedDecimals) + ", sigma_v " +
              pair(fit.speed.sd, m.sigma_speed_mps, kKickFileSpeedDecimals) + ", alpha " +
              pair(fit.direction.mean_rad * kRadToDeg, m.direction_rad * kRadToDeg,
                   kKickFileAngleDecimals) +
              ", sigma_alpha " +
              pair(fit.direction.sd_rad * kRadToDeg, m.sigma_direction_rad * kRadToDeg,
                   kKickFileAngleDecimals) +
              ")";
  }
  return Result(ok, "fitted/committed: " + detail);
}

// A situation set's name as it is, a file relative to the spec's folder (as every file a spec
// names).
std::string SituationsOf(const FidelityFloorCheck& c, const CheckSpec& spec,
                         const std::filesystem::path& models) {
  const std::filesystem::path named(c.situations);
  if (named.is_absolute() || !named.has_parent_path()) {
    return std::filesystem::exists(DataFile(models, DataFolder::kFidelity, c.situations))
               ? c.situations
               : (spec.dir / named).string();
  }
  return (spec.dir / named).string();
}

CheckResult Run(const FidelityFloorCheck& c, const CheckSpec& spec,
                const std::filesystem::path& models, int threads) {
  const std::filesystem::path kicks =
      ResolveModelFile(c.kicks, DataFolder::kKicks, spec.dir, models);
  SituationOverrides overrides;
  overrides.kicks_file = kicks;
  const FidelitySet set = LoadFidelitySet(SituationsOf(c, spec, models), models, overrides);
  FidelitySettings settings;
  settings.base = spec.base;
  settings.physics_trials = c.trials;
  settings.converged_samples = 500;
  settings.threads = threads;
  const FidelityResult r = RunFidelity(set, models, settings);
  const ClassSummary& all = r.classes.front();
  const bool ok = all.tau_coarse.mean >= c.min_tau_b && all.regret_coarse.mean <= c.max_regret;
  return Result(ok, std::to_string(all.situations) + " situations: mean tau-b " +
                        Fixed(all.tau_coarse.mean, 3) + " (floor " + Fixed(c.min_tau_b, 3) +
                        "), mean regret " + Fixed(all.regret_coarse.mean, 4) + " (ceiling " +
                        Fixed(c.max_regret, 4) + ")");
}

// Loading what a check reads, without running it: every check of a spec is prepared before the
// first runs, so a bad file or name fails at once, not after minutes of other checks.
void Prepare(const FreeRollCheck& c, const CheckSpec& spec, const std::filesystem::path& models) {
  LoadUniformWorld(c.field, spec, models);
}
void Prepare(const NoTunnellingCheck& c, const CheckSpec& spec,
             const std::filesystem::path& models) {
  LoadUniformWorld(c.field, spec, models);
}
void Prepare(const ReboundCheck& c, const CheckSpec& spec, const std::filesystem::path& models) {
  LoadUniformWorld(c.field, spec, models);
}
void Prepare(const RobotReboundCheck& c, const CheckSpec& spec,
             const std::filesystem::path& models) {
  LoadUniformWorld(c.field, spec, models);
  const Robot robot = LoadRobot(c.robot, models);
  if (!robot.model.FindLink(c.link)) {
    throw InputError("link: " + robot.spec.name + " has no link '" + c.link + "'");
  }
}
void Prepare(const KickDirectionCheck& c, const CheckSpec& spec,
             const std::filesystem::path& models) {
  PhysicsCalibrationSettings settings =
      CalibrationSettingsOf(c.robot, c.kicks, c.trials, spec, models, 1);
  settings.kick = c.kick;
  settings.kick_field = "kick";
  PlanPhysicsCalibration(settings, models);
}
void Prepare(const CalibrationBandCheck& c, const CheckSpec& spec,
             const std::filesystem::path& models) {
  PlanPhysicsCalibration(CalibrationSettingsOf(c.robot, c.kicks, c.trials, spec, models, 1),
                         models);
}
void Prepare(const FidelityFloorCheck& c, const CheckSpec& spec,
             const std::filesystem::path& models) {
  SituationOverrides overrides;
  overrides.kicks_file =
      NamedFile("kicks", ResolveModelFile(c.kicks, DataFolder::kKicks, spec.dir, models));
  LoadFidelitySet(SituationsOf(c, spec, models), models, overrides);
}

}  // namespace

void FreeRollCheck::Validate() const {
  RequireInRange("speed_mps", speed_mps, 0.05, kMaxCheckSpeedMps);
  RequireInRange("heading_deg", heading_deg, -360.0, 360.0);
  RequireInRange("max_error_rel", max_error_rel, 0.0, 1.0);
  RequireInRange("max_lateral_m", max_lateral_m, 0.0, kMaxCheckLateralM);
}

void NoTunnellingCheck::Validate() const {
  RequireInRange("speed_mps", speed_mps, 0.05, 20.0);
  RequireInRange("phases", phases, 1, kMaxCheckPhases);
  RequireInRange("max_penetration_steps", max_penetration_steps, 0.0, 10.0);
}

void ReboundCheck::Validate() const {
  if (speeds_mps.empty()) throw InputError("speeds_mps: must list at least one speed");
  for (double v : speeds_mps) RequireInRange("speeds_mps", v, 0.05, 20.0);
  RequireInRange("phases", phases, 1, kMaxCheckPhases);
  RequireInRange("max_error_rel", max_error_rel, 0.0, 1.0);
  RequireInRange("min_error_mps", min_error_mps, 0.0, 1.0);
}

void RobotReboundCheck::Validate() const {
  if (speeds_mps.empty()) throw InputError("speeds_mps: must list at least one speed");
  for (double v : speeds_mps) RequireInRange("speeds_mps", v, 0.05, 20.0);
  RequireInRange("max_error_rel", max_error_rel, 0.0, 1.0);
}

void KickDirectionCheck::Validate() const {
  RequireInRange("trials", trials, kMinCheckTrials, kMaxCheckTrials);
  RequireInRange("max_error_deg", max_error_deg, 0.0, 180.0);
}

void CalibrationBandCheck::Validate() const {
  RequireInRange("trials", trials, kMinCheckTrials, kMaxCheckTrials);
  RequireInRange("seed", static_cast<double>(seed), 0.0, kMaxCheckSeed);
  RequireInRange("band_rel", band_rel, 0.0, 1.0);
  RequireInRange("band_deg", band_deg, 0.0, 180.0);
}

void FidelityFloorCheck::Validate() const {
  RequireInRange("trials", trials, kMinCheckTrials, kMaxCheckTrials);
  RequireInRange("min_tau_b", min_tau_b, -1.0, 1.0);
  RequireInRange("max_regret", max_regret, 0.0, 1.0);
}

std::string_view KindName(const CheckKind& kind) {
  return std::visit([](const auto& check) { return check.kKind; }, kind);
}

void PrepareCheck(const CheckSpec& spec, const std::filesystem::path& models_dir) {
  std::visit([&](const auto& check) { Prepare(check, spec, models_dir); }, spec.kind);
}

CheckResult RunCheck(const CheckSpec& spec, const std::filesystem::path& models_dir, int threads) {
  return std::visit([&](const auto& check) { return Run(check, spec, models_dir, threads); },
                    spec.kind);
}

}  // namespace foresight
