// libFuzzer targets for every reader of the project (issue 16): each binary feeds its input, as a
// file, to one loader. The promise under test is the project's error policy: bad input ends in an
// InputError (a one-line message, exit 2 in the command) and nothing else. Any other exception
// escapes and libFuzzer reports it (uncaught exception), as it reports crashes, hangs, leaks and
// AddressSanitizer/UBSan findings. One binary holds every reader; the environment variable
// FORESIGHT_FUZZ_TARGET chooses the one a run fuzzes (scripts/run_fuzzers.sh sets it).
//
// Readers and their seed corpora (fuzz/CMakeLists.txt): situation, field, kicks, evaluation,
// physics, robot (robot.json), motion (kick motion), urdf, mesh (OBJ referenced by a fixed URDF),
// fidelity_set, check_spec, stability, strategies, observed_kicks (CSV), case, problem,
// case_base (settings file), retrieval, match_robot, match_simulation, match_config,
// match_scenario (inside a fixed configuration), reactive, passing, cbr_team, cbr_variants;
// and the shard readers of `foresight merge`: shard_file (a shard.json's header and its set),
// shard_trial (a passing trial against the shape of a 2-vs-2 scenario), shard_calibration (a
// one-shard calibration of the NAO's forward kick, 8 trials, merged into its plan).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "cbr/case_base.h"
#include "cbr/case_file.h"
#include "cbr/problem.h"
#include "cbr/retrieval_params.h"
#include "cbr/team_params.h"
#include "common/error.h"
#include "common/json_reader.h"
#include "experiments/experiment_params.h"
#include "experiments/match_trial_shard.h"
#include "experiments/passing.h"
#include "experiments/passing_variants.h"
#include "match/match_config.h"
#include "match/match_params.h"
#include "match/reactive_team.h"
#include "models/evaluation_params.h"
#include "models/field_spec.h"
#include "models/kick_model.h"
#include "models/kick_motion.h"
#include "models/model_paths.h"
#include "models/physics_params.h"
#include "models/robot_model.h"
#include "models/robot_spec.h"
#include "models/situation.h"
#include "report/shard_file.h"
#include "validation/calibration_shard.h"
#include "validation/fidelity_set.h"
#include "validation/observed_kicks.h"
#include "validation/physics_checks.h"

namespace foresight {
namespace {

namespace fs = std::filesystem;

const fs::path& WorkDir() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("foresight_fuzz." + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

fs::path Write(const std::string& name, const uint8_t* data, std::size_t size) {
  const fs::path file = WorkDir() / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

// A URDF with one box link and one mesh link whose mesh is the fuzzed OBJ.
fs::path MeshUrdf() {
  const fs::path urdf = WorkDir() / "mesh_robot.urdf";
  std::ofstream(urdf) << R"(<?xml version="1.0"?>
<robot name="fuzz">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <link name="part"><inertial><mass value="0.1"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="input.obj"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="part"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>)";
  return urdf;
}

std::string ReadShipped(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A match configuration with the shipped field, simulation and robot.
void LoadMatchInputs(const fs::path& config) {
  static const fs::path models = DefaultModelsDir();
  static const SimulationParams sim = LoadSimulationParams("simulation", models);
  static const FieldSpec field = LoadFieldSpec(DataFile(models, DataFolder::kFields, sim.field));
  static const RobotParams robot = LoadRobotParams(sim.robot, models);
  LoadMatchConfig(config.string(), models, field, sim, robot);
}

// The fuzzed input as DIR/shard.json, read as `foresight merge` reads one shard folder.
std::vector<ShardPart> ReadShard(const uint8_t* data, std::size_t size) {
  fs::create_directories(WorkDir() / "shard");
  Write("shard/shard.json", data, size);
  return ReadShardParts({WorkDir() / "shard"}, FORESIGHT_VERSION);
}

using Reader = std::function<void(const uint8_t*, std::size_t)>;

const std::map<std::string, Reader>& Readers() {
  static const fs::path models = DefaultModelsDir();
  static const std::map<std::string, Reader> readers = {
      {"situation", [](auto d, auto n) { LoadSituation(Write("s.json", d, n), models); }},
      {"field", [](auto d, auto n) { LoadFieldSpec(Write("f.json", d, n)); }},
      {"kicks", [](auto d, auto n) { LoadKickModel(Write("k.json", d, n)); }},
      {"evaluation", [](auto d, auto n) { LoadEvaluationParams(Write("e.json", d, n)); }},
      {"physics", [](auto d, auto n) { LoadPhysicsParams(Write("p.json", d, n)); }},
      {"robot", [](auto d, auto n) { LoadRobotSpec(Write("robot.json", d, n)); }},
      {"motion", [](auto d, auto n) { LoadKickMotion(Write("m.json", d, n)); }},
      {"urdf", [](auto d, auto n) { LoadRobotModel(Write("r.urdf", d, n)); }},
      {"mesh",
       [](auto d, auto n) {
         Write("input.obj", d, n);
         LoadRobotModel(MeshUrdf());
       }},
      {"fidelity_set",
       [](auto d, auto n) { LoadFidelitySet(Write("set.json", d, n).string(), models); }},
      {"check_spec", [](auto d, auto n) { LoadCheckSuite(Write("c.json", d, n)); }},
      {"stability",
       [](auto d, auto n) { LoadStabilityParams(Write("st.json", d, n).string(), models); }},
      {"strategies",
       [](auto d, auto n) { LoadStrategiesParams(Write("sg.json", d, n).string(), models); }},
      {"observed_kicks",
       [](auto d, auto n) {
         // The reader, then its unit and consistency checks against the shipped NAO model.
         static const KickModel nao = LoadKickModel(DataFile(models, DataFolder::kKicks, "nao"));
         const std::filesystem::path file = Write("o.csv", d, n);
         CheckObservedKicks(ReadObservedKicks(file, 0.27), nao, file);
       }},
      {"case",
       [](auto d, auto n) {
         static const CaseRules rules = LoadCaseBase(DefaultCaseBasePath(models), models).rules;
         LoadCaseFile(Write("case.json", d, n), rules);
       }},
      {"problem", [](auto d, auto n) { LoadProblem(Write("problem.json", d, n), models); }},
      {"case_base", [](auto d, auto n) { LoadCaseBase(Write("case_base.json", d, n), models); }},
      {"retrieval",
       [](auto d, auto n) {
         static const FieldSpec field =
             LoadFieldSpec(DataFile(models, DataFolder::kFields, "four_legged"));
         LoadRetrievalParams(Write("retrieval.json", d, n), field);
       }},
      {"match_robot",
       [](auto d, auto n) { LoadRobotParams(Write("mr.json", d, n).string(), models); }},
      {"match_simulation",
       [](auto d, auto n) { LoadSimulationParams(Write("ms.json", d, n).string(), models); }},
      {"match_config", [](auto d, auto n) { LoadMatchInputs(Write("mc.json", d, n)); }},
      {"match_scenario",
       [](auto d, auto n) {
         Write("fz_scenario.json", d, n);
         const fs::path config = WorkDir() / "fz_config.json";
         std::string text = ReadShipped(models / "match" / "dg.json");
         text.replace(text.find("\"dg_1\""), 6, "\"fz_scenario.json\"");
         std::ofstream(config) << text;
         LoadMatchInputs(config);
       }},
      {"reactive",
       [](auto d, auto n) { LoadReactiveParams(Write("re.json", d, n).string(), models); }},
      {"passing",
       [](auto d, auto n) { LoadPassingParams(Write("pa.json", d, n).string(), models); }},
      {"cbr_team",
       [](auto d, auto n) { LoadCbrTeamParams(Write("ct.json", d, n).string(), models); }},
      {"cbr_variants",
       [](auto d, auto n) { LoadPassingVariants(Write("cv.json", d, n).string(), models); }},
      {"shard_file", [](auto d, auto n) { ReadShard(d, n); }},
      {"shard_trial",
       [](auto d, auto n) {
         const JsonDocument doc =
             JsonDocument::Parse(std::string(reinterpret_cast<const char*>(d), n), "t.json");
         ReadShardTrial(ShardValue(doc.Tree(), "t.json", "result"), {2, 2, 600.04, 4.0, 3.1});
       }},
      {"shard_calibration",
       [](auto d, auto n) {
         static const PhysicsCalibrationSettings settings = [] {
           PhysicsCalibrationSettings s;
           s.robot = "nao";
           s.kick = "forward";
           s.trials = 8;
           return s;
         }();
         static const PhysicsCalibration plan = PlanPhysicsCalibration(settings, models);
         const std::vector<ShardPart> parts = ReadShard(d, n);
         if (parts.front().header.items != settings.trials) return;  // another run's shard
         PhysicsCalibration merged = plan;
         MergeCalibrationShards(merged, settings.trials, parts);
       }},
  };
  return readers;
}

const Reader* chosen = nullptr;

}  // namespace
}  // namespace foresight

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* name = std::getenv("FORESIGHT_FUZZ_TARGET");
  const auto& readers = foresight::Readers();
  const auto it = readers.find(name == nullptr ? "" : name);
  if (it == readers.end()) {
    std::fprintf(stderr, "set FORESIGHT_FUZZ_TARGET to one of:");
    for (const auto& [reader, unused] : readers) std::fprintf(stderr, " %s", reader.c_str());
    std::fprintf(stderr, "\n");
    std::exit(2);
  }
  foresight::chosen = &it->second;
  // The reader's one-time set-up (a physics calibration's plan, loaded models) runs here, outside
  // the per-input timeout: under ASan on a loaded machine it took the first input past 10 s.
  static const uint8_t kEmpty[1] = {0};
  try {
    (*foresight::chosen)(kEmpty, 0);
  } catch (const foresight::InputError&) {
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  try {
    (*foresight::chosen)(data, size);
  } catch (const foresight::InputError&) {
    // the promised outcome of bad input
  }
  return 0;
}
