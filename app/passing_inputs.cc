#include "app/passing_inputs.h"

#include "app/base_flag.h"
#include "app/cli_values.h"
#include "app/passing_physics.h"
#include "app/shard_output.h"
#include "common/error.h"
#include "experiments/experiment_params.h"
#include "models/model_paths.h"

namespace foresight {

void AddPassingRunOptions(CLI::App& cmd, PassingOptions& o) {
  cmd.add_option("--config", o.config, "Opponents: dg, 2d or a configuration file")->required();
  cmd.add_option("--scenarios", o.scenarios, "Scenarios, e.g. 1-4 or 3,4 (default: all)");
  cmd.add_option("--trials", o.trials, "Trials per scenario (default: the configuration's)");
  cmd.add_flag("--mirror", o.mirror, "Attack the goal at -x instead (the mirrored game)");
  cmd.add_flag("--physics", o.physics, "Execute every kick in the Bullet scene");
  cmd.add_option("--physics-file", o.physics_file,
                 "Physics file (default: MODELS/physics/<field>.json)");
  AddBaseOption(cmd, o.base);
  cmd.add_option("--kicks", o.kicks_file, "AIBO kick model replacing the simulation file's");
  cmd.add_option("--goalie", o.goalie,
                 "Goalie model replacing the configuration's: ros2009 (the paper's) or "
                 "runswift2005 (rUNSWift's competition goalie)");
  cmd.add_option("--params", o.params, "Experiment file, or a name in MODELS/experiments/")
      ->capture_default_str();
  cmd.add_option("--seed", o.seed, "Random seed")->capture_default_str();
  cmd.add_option("--threads", o.threads, "Worker threads (0: all cores)")->capture_default_str();
  cmd.add_option("--out", o.out_dir, "Folder for the results")->required();
  AddShardOption(cmd, o.shard);
}

PassingInputs LoadPassingInputs(const PassingOptions& o, const std::string& team,
                                const std::filesystem::path& models) {
  PassingRequest request;
  request.params = o.params;
  request.config = o.config;
  request.team = team;
  if (!o.scenarios.empty()) request.scenarios = ParseSampleCounts("--scenarios", o.scenarios);
  if (!o.trials.empty()) request.trials = ParseCount("--trials", o.trials, 1, 10000000);
  request.mirrored = o.mirror;
  request.kicks_file = o.kicks_file;
  request.goalie = o.goalie;
  if (!o.physics && !o.physics_file.empty()) throw InputError("--physics-file needs --physics");
  if (!o.physics && !o.base.empty()) throw InputError("--base needs --physics");
  const std::optional<RobotBase> base = ParseBaseFlag(o.base);
  PassingInputs in{LoadPassingSetup(request, models), nullptr, "", ""};
  if (o.physics) {
    auto physics = std::make_unique<PhysicsKickExecutor>(in.setup.field, in.setup.kicks, models,
                                                         o.physics_file, base);
    in.physics_file = DisplayPath(physics->physics_file(), models);
    in.robot_base = RobotBaseName(physics->base());
    in.executor = std::move(physics);
  } else {
    in.executor = std::make_unique<CoarseKickExecutor>(in.setup.field,
                                                       in.setup.kicks.rolling_deceleration_mps2);
  }
  return in;
}

RunProvenance PassingProvenance(const PassingOptions& o, const PassingInputs& in,
                                const std::string& team, const std::string& team_file,
                                std::uint64_t seed, const std::filesystem::path& models) {
  const PassingSetup& setup = in.setup;
  RunProvenance p;
  p.version = FORESIGHT_VERSION;
  p.seed = seed;
  p.inputs = {{"file", DisplayPath(setup.params.file, models)},
              {"simulation", DisplayPath(setup.sim.file, models)},
              {"field", DisplayPath(setup.field_file, models)},
              {"kicks", DisplayPath(setup.kicks_file, models)},
              {"kicks_hash", ContentHash(setup.kicks_file)},
              {"config", DisplayPath(setup.config.file, models)},
              {"team", team},
              {"team_file", team_file},
              {"executor", o.physics ? "physics" : "coarse"},
              {"goalie", setup.config.HasGoalie()
                             ? std::string(GoalieModelName(setup.config.goalie.model))
                             : std::string("none")},
              {"mirrored", setup.mirrored ? "yes" : "no"}};
  if (o.physics) p.SetInput("physics", in.physics_file);
  if (o.physics) p.SetInput("robot_base", in.robot_base);
  return p;
}

nlohmann::ordered_json PassingSettings(const PassingOptions& o) {
  return {{"--config", o.config},   {"--scenarios", o.scenarios},
          {"--trials", o.trials},   {"--mirror", o.mirror},
          {"--physics", o.physics}, {"--physics-file", o.physics_file},
          {"--base", o.base},
          {"--kicks", o.kicks_file}, {"--goalie", o.goalie},
          {"--params", o.params},
          {"--seed", o.seed}};
}

PassingOptions PassingOptionsOf(const ShardPart& part, const std::string& out_dir) {
  PassingOptions o;
  o.config = SettingString(part, "--config");
  o.scenarios = SettingString(part, "--scenarios");
  o.trials = SettingString(part, "--trials");
  o.mirror = SettingFlag(part, "--mirror");
  o.physics = SettingFlag(part, "--physics");
  o.physics_file = SettingString(part, "--physics-file");
  o.base = SettingString(part, "--base");
  o.kicks_file = SettingString(part, "--kicks");
  o.goalie = SettingString(part, "--goalie");
  o.params = SettingString(part, "--params");
  o.seed = SettingString(part, "--seed");
  o.out_dir = out_dir;
  return o;
}

}  // namespace foresight
