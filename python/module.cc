#include "python/module.h"

#include <pybind11/stl.h>
#include <signal.h>

#include <atomic>

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

namespace py = pybind11;

namespace foresight::python {

std::filesystem::path ModelsDir(const std::optional<std::string>& models) {
  return models ? std::filesystem::path(*models) : DefaultModelsDir();
}

std::string FlagText(const py::object& value) {
  if (value.is_none()) return "";
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  return py::str(value).cast<std::string>();
}

namespace {

// Sets `flag` from a keyword argument unless it is None (the command's default stays).
void SetFlag(std::string& flag, const py::object& value) {
  if (!value.is_none()) flag = FlagText(value);
}

py::object LoadDataFile(const std::string& file) {
  return ToPython(JsonDocument::Load(file).Tree());
}

py::dict LoadSituationDict(const std::string& file, const std::optional<std::string>& kicks,
                           const std::optional<std::string>& models) {
  SituationOverrides overrides;
  if (kicks) overrides.kicks_file = *kicks;
  const Situation s = LoadSituation(file, ModelsDir(models), overrides);
  py::list kick_names, obstacles;
  for (const KickSpec& k : s.kicks.kicks) kick_names.append(k.name);
  for (const Obstacle& o : s.obstacles) {
    obstacles.append(py::dict(py::arg("x_m") = o.p_F.x(), py::arg("y_m") = o.p_F.y(),
                              py::arg("radius_m") = o.radius_m));
  }
  const StateEstimate& e = s.state;
  return py::dict(
      py::arg("name") = s.name, py::arg("field_file") = s.field_file.string(),
      py::arg("kicks_file") = s.kicks_file.string(),
      py::arg("evaluation_file") = s.evaluation_file.string(), py::arg("kicks") = kick_names,
      py::arg("samples") = s.evaluation.samples,
      py::arg("robot") = py::dict(py::arg("x_m") = e.robot.p_F.x(), py::arg("y_m") = e.robot.p_F.y(),
                                  py::arg("theta_rad") = e.robot.theta_rad,
                                  py::arg("sigma_x_m") = e.sigma_robot_x_m,
                                  py::arg("sigma_y_m") = e.sigma_robot_y_m,
                                  py::arg("sigma_theta_rad") = e.sigma_robot_theta_rad),
      py::arg("ball") = py::dict(py::arg("x_m") = e.p_R_ball.x(), py::arg("y_m") = e.p_R_ball.y(),
                                 py::arg("sigma_x_m") = e.sigma_ball_x_m,
                                 py::arg("sigma_y_m") = e.sigma_ball_y_m),
      py::arg("obstacles") = obstacles);
}

py::object Decide(const std::string& situation, const py::object& strategy,
                  const py::object& samples, const py::object& seed, const py::object& kicks,
                  const std::optional<std::string>& models) {
  DecideOptions options;
  options.situation_file = situation;
  SetFlag(options.strategy, strategy);
  SetFlag(options.samples, samples);
  SetFlag(options.seed, seed);
  SetFlag(options.kicks_file, kicks);
  nlohmann::ordered_json json;
  {
    const ReleasedCall call;
    json = DecideJson(options, ModelsDir(models));
  }
  return ToPython(json);
}

py::object Calibrate(const std::string& robot, const py::object& kick, const py::object& trials,
                     const py::object& seed, const py::object& threads,
                     const py::object& situation, const py::object& kicks,
                     const py::object& physics, const py::object& from_csv,
                     const py::object& confidence, const py::object& resamples,
                     const std::optional<std::string>& models) {
  CalibrateOptions options;
  options.robot = robot;
  SetFlag(options.kick, kick);
  options.all = kick.is_none();
  SetFlag(options.trials, trials);
  SetFlag(options.seed, seed);
  SetFlag(options.threads, threads);
  SetFlag(options.situation_file, situation);
  SetFlag(options.kicks_file, kicks);
  SetFlag(options.physics_file, physics);
  SetFlag(options.from_csv, from_csv);
  SetFlag(options.confidence, confidence);
  SetFlag(options.resamples, resamples);
  nlohmann::ordered_json json;
  {
    const ReleasedCall call;
    json = CalibrationJson(CalibrateInMemory(options, ModelsDir(models)));
  }
  return ToPython(json);
}

py::object Fidelity(const py::object& situations, const py::object& trials,
                    const py::object& samples, const py::object& converged, const py::object& seed,
                    const py::object& threads, const py::object& kicks, const py::object& physics,
                    const std::optional<std::string>& models) {
  FidelityOptions options;
  SetFlag(options.situations, situations);
  SetFlag(options.trials, trials);
  SetFlag(options.samples, samples);
  SetFlag(options.converged, converged);
  SetFlag(options.seed, seed);
  SetFlag(options.threads, threads);
  SetFlag(options.kicks_file, kicks);
  SetFlag(options.physics_file, physics);
  nlohmann::ordered_json json;
  {
    const ReleasedCall call;
    json = FidelityJson(RunFidelityInMemory(options, ModelsDir(models)));
  }
  return ToPython(json);
}

py::object CbrRetrieve(const std::string& problem, const py::object& case_base,
                       const py::object& params, const std::optional<std::string>& models) {
  CbrOptions options;
  options.problem_file = problem;
  SetFlag(options.case_base, case_base);
  SetFlag(options.params_file, params);
  nlohmann::ordered_json json;
  {
    const ReleasedCall call;
    json = CbrRetrieveJsonFor(options, ModelsDir(models));
  }
  return ToPython(json);
}

// Ctrl-C during a call. The work runs with the GIL released, where Python's own SIGINT handler
// only notes the signal for the interpreter to act on when the call returns. A handler chained in
// front of Python's notes it here too; the commands' progress check (app/cli_values.h), which the
// long loops run at least every 1 % of their items from any thread, then ends the call, and the
// exception becomes Python's KeyboardInterrupt (or whatever the script's handler raises).
struct Interrupted {};
std::atomic<bool> interrupt_pending{false};
std::atomic<int> calls_running{0};  // a Ctrl-C between calls is Python's alone
struct sigaction python_sigint {};

void NoteInterrupt(int signal, siginfo_t* info, void* context) {
  if (calls_running.load() > 0) interrupt_pending.store(true);
  if (python_sigint.sa_flags & SA_SIGINFO) {
    python_sigint.sa_sigaction(signal, info, context);
  } else if (python_sigint.sa_handler != SIG_DFL && python_sigint.sa_handler != SIG_IGN) {
    python_sigint.sa_handler(signal);
  }
}

void WatchInterrupts() {
  struct sigaction current {};
  if (::sigaction(SIGINT, nullptr, &current) != 0) return;
  const bool python_handles = (current.sa_flags & SA_SIGINFO) ||
                              (current.sa_handler != SIG_DFL && current.sa_handler != SIG_IGN);
  if (!python_handles) return;  // an embedding without Python's handler: leave SIGINT alone
  python_sigint = current;
  struct sigaction chained = current;
  chained.sa_flags |= SA_SIGINFO;
  chained.sa_sigaction = NoteInterrupt;
  ::sigaction(SIGINT, &chained, nullptr);
  interrupt_pending.store(false);
  SetProgressCheck([] {
    if (interrupt_pending.exchange(false)) throw Interrupted{};
  });
}

}  // namespace

ReleasedCall::ReleasedCall() {
  if (calls_running.fetch_add(1) == 0) interrupt_pending.store(false);
}

ReleasedCall::~ReleasedCall() {
  calls_running.fetch_sub(1);
}

}  // namespace foresight::python

PYBIND11_MODULE(foresight, m) {
  using namespace foresight::python;
  m.doc() = "foresight: robot-soccer kick selection by forward simulation, checked against "
            "Bullet physics, and case-based coordinated action selection. Each function returns what the command of the same name writes as "
            "JSON; bad input raises foresight.InputError with the command's one-line message.";
  m.attr("__version__") = FORESIGHT_VERSION;
  // The command line's one-line message, cut as the command line cuts it (common/error.h).
  static py::exception<foresight::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const foresight::InputError& e) {
      PyErr_SetString(input_error.ptr(), foresight::OneLine(e.what()).c_str());
    } catch (const Interrupted&) {
      if (PyErr_CheckSignals() == 0) PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
  WatchInterrupts();
  m.def("models_dir", [](const std::optional<std::string>& models) {
    return ModelsDir(models).string();
  }, py::arg("models") = py::none(), "The data folder the functions read (models/).");
  m.def("load_situation", &LoadSituationDict, py::arg("situation"), py::arg("kicks") = py::none(),
        py::arg("models") = py::none(),
        "Loads and checks a situation file: its name, files, kick names, belief and obstacles.");
  m.def("load_kick_model", [](const std::string& file) {
    foresight::LoadKickModel(file);  // checks it as every command does
    return LoadDataFile(file);
  }, py::arg("file"), "Loads and checks a kick-model file; returns its content.");
  m.def("load_field", [](const std::string& file) {
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
        "Calibrates a robot's kicks (all, or `kick`): the report's calibration.json as a dict.");
  m.def("fidelity", &Fidelity, py::arg("situations") = py::none(), py::arg("trials") = py::none(),
        py::arg("samples") = py::none(), py::arg("converged") = py::none(),
        py::arg("seed") = py::none(), py::arg("threads") = py::none(),
        py::arg("kicks") = py::none(), py::arg("physics") = py::none(),
        py::arg("models") = py::none(),
        "Coarse model against physics on a situation set: the report's fidelity.json as a dict.");
  m.def("cbr_retrieve", &CbrRetrieve, py::arg("problem"), py::arg("case_base") = py::none(),
        py::arg("params") = py::none(), py::arg("models") = py::none(),
        "Case retrieval (Ros et al. 2009) for a problem file: what `foresight cbr retrieve "
        "--json` prints (the retrieved case, the ranking, every case's verdict), as a dict.");
  AddPhysicsFunctions(m);
}
