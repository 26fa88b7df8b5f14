#include "python/planner_objects.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <stdexcept>

#include "app/decision_json.h"
#include "common/error.h"
#include "common/geometry.h"
#include "common/json_reader.h"
#include "common/long_call.h"
#include "models/evaluation_params.h"
#include "models/model_paths.h"
#include "planner/strategy_names.h"
#include "python/json_to_python.h"
#include "python/module.h"
#include "python/python_data.h"

namespace py = pybind11;

namespace foresight::python {

PlannerLock::PlannerLock(PlannerCore& core) : core_(core) {
  if (core.owner.load() == std::this_thread::get_id()) {
    throw std::runtime_error(
        "Planner: decide and decide_many cannot be called from within a decide_many of the same "
        "planner (its progress callback): the planner is busy with that call; use another "
        "Planner");
  }
  {
    const py::gil_scoped_release release;
    while (!core.mutex.try_lock_for(kPollInterval)) {
      const py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  }
  core.owner.store(std::this_thread::get_id());
}

PlannerLock::~PlannerLock() {
  core_.owner.store(std::thread::id{});
  core_.mutex.unlock();
}

std::uint64_t SeedFrom(const py::handle& value) {
  if (PyLong_Check(value.ptr()) ||
      (py::hasattr(value, "__index__") && !py::isinstance<py::bool_>(value))) {
    const py::object number = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
    if (number) {
      const unsigned long long seed = PyLong_AsUnsignedLongLong(number.ptr());
      if (!PyErr_Occurred()) return seed;
    }
    PyErr_Clear();
  }
  throw InputError("seed: must be an integer in [0, 18446744073709551615], got " +
                   py::repr(value).cast<std::string>());
}

Strategy StrategyFrom(const py::handle& value, Strategy fallback) {
  if (value.is_none()) return fallback;
  const std::string name = py::str(value).cast<std::string>();
  const std::optional<Strategy> strategy = ParseStrategy(name);
  if (!strategy) {
    throw InputError("strategy: unknown strategy '" + name + "' (one of: " + StrategyNames() + ")");
  }
  return *strategy;
}

int SamplesFrom(const py::handle& value, int fallback) {
  if (value.is_none()) return fallback;
  if (!PyLong_Check(value.ptr()) || py::isinstance<py::bool_>(value)) {
    throw InputError("samples: must be an integer in [1, " + std::to_string(kMaxSamples) +
                     "], got a " + TypeName(value));
  }
  const std::optional<long long> samples = AsInteger(value);
  if (!samples || *samples < 1 || *samples > kMaxSamples) {
    throw InputError("samples: must be an integer in [1, " + std::to_string(kMaxSamples) +
                     "], got " + py::repr(value).cast<std::string>());
  }
  return static_cast<int>(*samples);
}

// --- the planner ----------------------------------------------------------------------------

std::shared_ptr<PlannerCore> MakePlannerCore(const py::object& situation, const py::object& kicks,
                                             const py::object& strategy, const py::object& samples,
                                             const py::object& coarse_rebounds,
                                             const std::optional<std::filesystem::path>& models) {
  auto core = std::make_shared<PlannerCore>();
  core->models = ModelsDir(models);
  SituationOverrides overrides;
  if (!kicks.is_none()) {
    KickModelArg model = KickModelFrom(kicks);
    overrides.kicks_file = model.source;
    overrides.kicks = std::move(model.model);
  }
  if (!coarse_rebounds.is_none()) {
    // Only a bool: pybind11's cast would take any number's truth (nan, 1.5 and -1 as on).
    if (!py::isinstance<py::bool_>(coarse_rebounds)) {
      throw InputError("coarse_rebounds: must be True, False or None, got " +
                       py::repr(coarse_rebounds).cast<std::string>());
    }
    overrides.coarse_rebounds = coarse_rebounds.cast<bool>();
  }
  if (const auto path = AsPath(situation)) {
    core->situation = LoadSituation(*path, core->models, overrides);
    core->situation_file = path->string();
  } else {
    // References ending in ".json" resolve against the working directory.
    core->situation = ParseSituation(DictText(situation, "situation"), "situation (dict)", "",
                                     core->models, overrides);
  }
  core->check = core->situation;
  core->strategy = StrategyFrom(strategy, Strategy::kOptimalAll);
  core->samples = SamplesFrom(samples, core->situation.evaluation.samples);
  core->planner = std::make_unique<CoarsePlanner>(core->situation);
  core->evaluator.emplace(core->planner->MakeEvaluator(core->samples, 0));
  ReserveDecision(core->scratch, static_cast<int>(core->situation.kicks.kicks.size()));
  return core;
}

void DecideLocked(PlannerCore& core, const StateEstimate& state, Strategy strategy, int samples,
                  std::uint64_t seed) {
  core.check.state = state;
  core.check.Validate();
  core.planner->Decide(state, strategy, samples, seed, *core.evaluator, core.scratch);
}

namespace {

StateEstimate StateFrom(const PlannerCore& core, const py::handle& robot, const py::handle& ball) {
  StateEstimate state = core.situation.state;
  if (!robot.is_none()) ApplyPose(PoseFrom(robot, "robot"), state);
  if (!ball.is_none()) ApplyBall(BallFrom(ball, "ball"), state);
  return state;
}

}  // namespace

py::dict SituationDict(const Situation& s) {
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
      py::arg("robot") = py::dict(
          py::arg("x_m") = e.robot.p_F.x(), py::arg("y_m") = e.robot.p_F.y(),
          py::arg("theta_rad") = e.robot.theta_rad, py::arg("sigma_x_m") = e.sigma_robot_x_m,
          py::arg("sigma_y_m") = e.sigma_robot_y_m,
          py::arg("sigma_theta_rad") = e.sigma_robot_theta_rad),
      py::arg("ball") = py::dict(py::arg("x_m") = e.p_R_ball.x(), py::arg("y_m") = e.p_R_ball.y(),
                                 py::arg("sigma_x_m") = e.sigma_ball_x_m,
                                 py::arg("sigma_y_m") = e.sigma_ball_y_m),
      py::arg("obstacles") = obstacles);
}

py::object DecisionDict(const DecisionResult& r) {
  const DecisionRun run{
      r.core->situation_file, r.core->planner.get(), r.decision, r.samples, r.seed, r.core->models};
  return ToPython(DecisionJson(run));
}

void AddPlannerObjects(py::module_& m) {
  AddValueObjects(m);
  py::class_<DecisionResult>(m, "Decision", "One decision of a Planner.")
      .def_property_readonly(
          "kick",
          [](const DecisionResult& r) {
            return r.core->situation.kicks.NameOf(r.decision.kick_index);
          },
          "The chosen kick's name, or 'none' (leave the ball).")
      .def_property_readonly(
          "kick_index", [](const DecisionResult& r) { return r.decision.kick_index; },
          "Index into the planner's kick_names; -1 for none.")
      .def_property_readonly(
          "rotation_deg",
          [](const DecisionResult& r) { return r.decision.rotation_rad * kRadToDeg; },
          "The turn around the ball before the kick, degrees, counter-clockwise.")
      .def_property_readonly(
          "note", [](const DecisionResult& r) { return r.decision.note; },
          "Why a fallback was taken; empty normally.")
      .def_property_readonly(
          "strategy",
          [](const DecisionResult& r) { return std::string(StrategyName(r.decision.strategy)); })
      .def_property_readonly(
          "hypotheses", [](const DecisionResult& r) { return r.decision.evaluations; },
          "Hypotheses (kick, rotation) simulated, each over `samples` samples.")
      .def_readonly("samples", &DecisionResult::samples)
      .def_readonly("seed", &DecisionResult::seed)
      .def("to_dict", &DecisionDict,
           "What `foresight decide --json` prints for this decision: every kick's evaluation "
           "(probabilities, utilities), the chosen kick and rotation.")
      .def("__repr__", [](const DecisionResult& r) {
        return "Decision(kick='" + r.core->situation.kicks.NameOf(r.decision.kick_index) +
               "', rotation_deg=" +
               std::string(py::repr(py::float_(r.decision.rotation_rad * kRadToDeg))) + ")";
      });

  py::class_<PlannerCore, std::shared_ptr<PlannerCore>> planner(
      m, "Planner",
      "The coarse decision for one scene, built once and reused: field, obstacles, kick model "
      "and evaluation from a situation (a path or a dict with the situation file's keys), then "
      "decide() for any robot pose and ball and seed. Strategies: fast, optimal_value, "
      "optimal_all, optimal_one, naoth.");
  planner
      .def(py::init(&MakePlannerCore), py::arg("situation"), py::arg("kicks") = py::none(),
           py::arg("strategy") = py::none(), py::arg("samples") = py::none(),
           py::arg("coarse_rebounds") = py::none(), py::arg("models") = py::none())
      .def_property_readonly("situation",
                             [](const PlannerCore& c) { return SituationDict(c.situation); })
      .def_property_readonly("kick_names",
                             [](const PlannerCore& c) {
                               std::vector<std::string> names;
                               for (const KickSpec& s : c.situation.kicks.kicks)
                                 names.push_back(s.name);
                               return names;
                             })
      .def_property_readonly(
          "strategy", [](const PlannerCore& c) { return std::string(StrategyName(c.strategy)); })
      .def_readonly("samples", &PlannerCore::samples)
      .def(
          "decide",
          [](const std::shared_ptr<PlannerCore>& core, const py::object& robot,
             const py::object& ball, const py::object& seed, const py::object& strategy,
             const py::object& samples) {
            DecisionResult r;
            r.core = core;
            r.state = StateFrom(*core, robot, ball);
            r.seed = SeedFrom(seed);
            r.samples = SamplesFrom(samples, core->samples);
            const Strategy s = StrategyFrom(strategy, core->strategy);
            {
              const PlannerLock lock(*core);
              DecideLocked(*core, r.state, s, r.samples, r.seed);
              r.decision = core->scratch;
            }
            return r;
          },
          py::arg("robot") = py::none(), py::arg("ball") = py::none(), py::arg("seed") = 1,
          py::arg("strategy") = py::none(), py::arg("samples") = py::none(),
          "The decision for the robot pose `robot` (Pose, dict or (x_m, y_m, theta_deg) in F; "
          "None: the situation's) with the ball at `ball` (Ball, dict or (x_m, y_m) in the "
          "robot frame; None: the situation's), drawing its samples from `seed`.");
  AddPlannerArrays(planner);
}

}  // namespace foresight::python
