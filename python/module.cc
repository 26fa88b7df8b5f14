#include "python/module.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "app/calibrate_command.h"
#include "app/cbr_command.h"
#include "app/decide_command.h"
#include "app/cli_values.h"
#include "app/fidelity_command.h"
#include "common/error.h"
#include "common/one_line.h"
#include "common/json_reader.h"
#include "models/model_paths.h"
#include "models/situation.h"
#include "python/json_to_python.h"
#include "python/long_call.h"
#include "python/planner_objects.h"
#include "python/python_data.h"

namespace py = pybind11;

namespace foresight::python {

std::filesystem::path ModelsDir(const std::optional<std::filesystem::path>& models) {
  // '' is refused as every other argument's (FlagText): an empty folder name read the data from
  // the working directory and failed later with a file that name does not explain.
  if (models && models->empty()) {
    throw InputError("models: empty value (pass None for the default)");
  }
  return models ? *models : DefaultModelsDir();
}

std::string FlagText(const py::object& value, const std::string& name) {
  if (value.is_none()) return "";
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  std::string text = py::str(value).cast<std::string>();
  if (text.empty()) throw InputError(name + ": empty value (pass None for the default)");
  return text;
}

namespace {

// Sets `flag` from a keyword argument unless it is None (the command's default stays).
void SetFlag(std::string& flag, const py::object& value, const char* name) {
  if (!value.is_none()) flag = FlagText(value, name);
}

// `work()`'s JSON, computed without the GIL (a short call: no Ctrl-C polling), as Python objects.
template <typename Work>
py::object JsonWithoutGil(Work&& work) {
  nlohmann::ordered_json json;
  {
    py::gil_scoped_release release;
    json = work();
  }
  return ToPython(json);
}

py::object LoadDataFile(const std::filesystem::path& file) {
  return ToPython(JsonDocument::Load(file).Tree());
}

py::dict LoadSituationDict(const std::filesystem::path& file, const py::object& kicks,
                           const std::optional<std::filesystem::path>& models) {
  SituationOverrides overrides;
  if (!kicks.is_none()) overrides.kicks_file = FlagText(kicks, "kicks");
  return SituationDict(LoadSituation(file, ModelsDir(models), overrides));
}

// A situation file with an optional kick-model file: the command's own code (its messages name
// the flags). A dict, or a kick model given as a dict or KickModel: a Planner's decision.
py::object Decide(const py::object& situation, const py::object& strategy,
                  const py::object& samples, const py::object& seed, const py::object& kicks,
                  const std::optional<std::filesystem::path>& models) {
  const auto situation_path = AsPath(situation);
  if (situation_path && (kicks.is_none() || AsPath(kicks))) {
    DecideOptions options;
    options.situation_file = situation_path->string();
    SetFlag(options.strategy, strategy, "strategy");
    SetFlag(options.samples, samples, "samples");
    SetFlag(options.seed, seed, "seed");
    SetFlag(options.kicks_file, kicks, "kicks");
    return JsonWithoutGil([&] { return DecideJson(options, ModelsDir(models)); });
  }
  DecisionResult r;
  r.core = MakePlannerCore(situation, kicks, strategy, samples, py::none(), models);
  r.state = r.core->situation.state;
  r.seed = seed.is_none() ? 1 : SeedFrom(seed);
  r.samples = r.core->samples;
  const PlannerLock lock(*r.core);
  DecideLocked(*r.core, r.state, r.core->strategy, r.samples, r.seed);
  r.decision = r.core->scratch;
  return DecisionDict(r);
}

py::object Calibrate(const std::string& robot, const py::object& kick, const py::object& trials,
                     const py::object& seed, const py::object& threads,
                     const py::object& situation, const py::object& kicks,
                     const py::object& physics, const py::object& from_csv,
                     const py::object& confidence, const py::object& resamples,
                     const std::optional<std::filesystem::path>& models, const py::object& base,
                     const py::object& progress) {
  CalibrateOptions options;
  options.robot = robot;
  SetFlag(options.kick, kick, "kick");
  options.all = kick.is_none();
  SetFlag(options.trials, trials, "trials");
  SetFlag(options.seed, seed, "seed");
  SetFlag(options.threads, threads, "threads");
  SetFlag(options.situation_file, situation, "situation");
  SetFlag(options.kicks_file, kicks, "kicks");
  SetFlag(options.physics_file, physics, "physics");
  SetFlag(options.from_csv, from_csv, "from_csv");
  SetFlag(options.confidence, confidence, "confidence");
  SetFlag(options.resamples, resamples, "resamples");
  SetFlag(options.base, base, "base");
  const std::filesystem::path dir = ModelsDir(models);
  return ToPython(RunLongCall(progress, [&] {
    return CalibrationJson(CalibrateInMemory(options, dir));
  }));
}

py::object Fidelity(const py::object& situations, const py::object& trials,
                    const py::object& samples, const py::object& converged, const py::object& seed,
                    const py::object& threads, const py::object& kicks, const py::object& physics,
                    const std::optional<std::filesystem::path>& models, const py::object& base,
                    const py::object& progress) {
  FidelityOptions options;
  SetFlag(options.situations, situations, "situations");
  SetFlag(options.trials, trials, "trials");
  SetFlag(options.samples, samples, "samples");
  SetFlag(options.converged, converged, "converged");
  SetFlag(options.seed, seed, "seed");
  SetFlag(options.threads, threads, "threads");
  SetFlag(options.kicks_file, kicks, "kicks");
  SetFlag(options.physics_file, physics, "physics");
  SetFlag(options.base, base, "base");
  const std::filesystem::path dir = ModelsDir(models);
  return ToPython(RunLongCall(progress, [&] {
    return FidelityJson(RunFidelityInMemory(options, dir));
  }));
}

py::object CbrRetrieve(const py::object& problem, const py::object& case_base,
                       const py::object& params,
                       const std::optional<std::filesystem::path>& models) {
  if (const auto path = AsPath(problem)) {
    CbrOptions options;
    options.problem_file = path->string();
    SetFlag(options.case_base, case_base, "case_base");
    SetFlag(options.params_file, params, "params");
    return JsonWithoutGil([&] { return CbrRetrieveJsonFor(options, ModelsDir(models)); });
  }
  return py::module_::import("foresight").attr("CaseBase")(case_base, params, models)
      .attr("retrieve")(problem);
}

}  // namespace

}  // namespace foresight::python

PYBIND11_MODULE(_foresight, m) {
  using namespace foresight::python;
  m.doc() = "foresight: robot-soccer kick selection by forward simulation, checked against "
            "Bullet physics, and case-based coordinated action selection. Each function returns what the command of the same name writes as "
            "JSON; bad input raises foresight.InputError with the command's one-line message.";
  m.attr("__version__") = FORESIGHT_VERSION;
  // The command line's one-line message, cut as the command line cuts it (common/one_line.h).
  static py::exception<foresight::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const foresight::InputError& e) {
      PyErr_SetString(input_error.ptr(), foresight::OneLine(e.what()).c_str());
    }
  });
  m.def("models_dir", [](const std::optional<std::filesystem::path>& models) {
    return ModelsDir(models).string();
  }, py::arg("models") = py::none(), "The data folder the functions read (models/).");
  m.def("load_situation", &LoadSituationDict, py::arg("situation"), py::arg("kicks") = py::none(),
        py::arg("models") = py::none(),
        "Loads and checks a situation file: its name, files, kick names, belief and obstacles.");
  m.def("load_kick_model", [](const std::filesystem::path& file) {
    foresight::LoadKickModel(file);  // checks it as every command does
    return LoadDataFile(file);
  }, py::arg("file"), "Loads and checks a kick-model file; returns its content.");
  m.def("load_field", [](const std::filesystem::path& file) {
    foresight::LoadFieldSpec(file);
    return LoadDataFile(file);
  }, py::arg("file"), "Loads and checks a field file; returns its content.");
  m.def("decide", &Decide, py::arg("situation"), py::arg("strategy") = py::none(),
        py::arg("samples") = py::none(), py::arg("seed") = py::none(),
        py::arg("kicks") = py::none(), py::arg("models") = py::none(),
        "The coarse decision: what `foresight decide --json` prints, as a dict.");
  m.def("calibrate", &Calibrate, py::arg("robot"), py::arg("kick") = py::none(),
        py::arg("trials") = py::none(), py::arg("seed") = py::none(),
        py::arg("threads") = py::none(), py::arg("situation") = py::none(),
        py::arg("kicks") = py::none(), py::arg("physics") = py::none(),
        py::arg("from_csv") = py::none(), py::arg("confidence") = py::none(),
        py::arg("resamples") = py::none(), py::arg("models") = py::none(),
        py::arg("base") = py::none(), py::arg("progress") = py::none(),
        "Calibrates a robot's kicks (all, or `kick`): the report's calibration.json as a dict; "
        "base 'fixed' or 'floating' replaces the physics file's (default: floating).");
  m.def("fidelity", &Fidelity, py::arg("situations") = py::none(), py::arg("trials") = py::none(),
        py::arg("samples") = py::none(), py::arg("converged") = py::none(),
        py::arg("seed") = py::none(), py::arg("threads") = py::none(),
        py::arg("kicks") = py::none(), py::arg("physics") = py::none(),
        py::arg("models") = py::none(), py::arg("base") = py::none(),
        py::arg("progress") = py::none(),
        "Coarse model against physics on a situation set: the report's fidelity.json as a dict; "
        "base 'fixed' or 'floating' replaces the physics files' (default: floating).");
  m.def("cbr_retrieve", &CbrRetrieve, py::arg("problem"), py::arg("case_base") = py::none(),
        py::arg("params") = py::none(), py::arg("models") = py::none(),
        "Case retrieval (Ros et al. 2009) for a problem file: what `foresight cbr retrieve "
        "--json` prints (the retrieved case, the ranking, every case's verdict), as a dict.");
  AddPhysicsFunctions(m);
  AddPlannerObjects(m);
  AddMatchAndCbr(m);
}
