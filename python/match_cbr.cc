// The match simulator and case retrieval from Python, for scripted experiments: passing() plays
// the passing experiment's trials (`foresight experiment passing`) and returns one NumPy entry
// per trial; CaseBase loads a case base once and retrieves for problem files or dicts
// (`foresight cbr retrieve`).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <vector>

#include "app/cbr_command.h"
#include "app/cli_values.h"
#include "app/passing_inputs.h"
#include "cbr/problem.h"
#include "common/error.h"
#include "python/json_to_python.h"
#include "python/long_call.h"
#include "python/module.h"
#include "python/python_data.h"

namespace py = pybind11;

namespace foresight::python {

namespace {

// One column over every (team, scenario, trial) in play order.
template <typename T, typename Field>
py::array_t<T> TrialColumn(const std::vector<PassingResult>& results, Field&& field) {
  std::vector<T> values;
  for (std::size_t t = 0; t < results.size(); ++t) {
    for (const ScenarioTrials& s : results[t].scenarios) {
      for (std::size_t i = 0; i < s.trials.size(); ++i) {
        values.push_back(static_cast<T>(field(static_cast<int>(t), s, static_cast<int>(i))));
      }
    }
  }
  py::array_t<T> column(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), column.mutable_data());
  return column;
}

int Sum(const std::vector<int>& counts) {
  int sum = 0;
  for (const int c : counts) sum += c;
  return sum;
}

py::dict Passing(const py::object& config, const py::object& team, const py::object& scenarios,
                 const py::object& trials, const py::object& seed, const py::object& threads,
                 bool mirror, bool physics, const py::object& kicks,
                 const std::optional<std::filesystem::path>& models, const py::object& progress,
                 const py::object& base) {
  PassingOptions o;
  o.config = FlagText(config, "config");
  if (!team.is_none()) o.team = FlagText(team, "team");
  if (!scenarios.is_none()) {
    std::string list;
    for (const py::handle s : scenarios) {
      const std::string name = FlagText(py::reinterpret_borrow<py::object>(s), "scenarios");
      list += (list.empty() ? "" : ",") + name;
    }
    o.scenarios = list;
  }
  if (!trials.is_none()) o.trials = FlagText(trials, "trials");
  if (!seed.is_none()) o.seed = FlagText(seed, "seed");
  if (!threads.is_none()) o.threads = FlagText(threads, "threads");
  o.mirror = mirror;
  o.physics = physics;
  if (!kicks.is_none()) o.kicks_file = FlagText(kicks, "kicks");
  if (!base.is_none()) o.base = FlagText(base, "base");
  const std::filesystem::path dir = ModelsDir(models);
  std::vector<std::string> teams;
  const std::vector<PassingResult> results = RunLongCall(progress, [&] {
    const std::uint64_t key = ParseSeed(o.seed);
    const int thread_count = ParseCount("--threads", o.threads, 0, 1024);
    const PassingInputs in = LoadPassingInputs(o, o.team, dir);
    std::vector<PassingResult> played;
    for (const std::string& name : in.setup.teams) {
      teams.push_back(name);
      played.push_back(RunPassing(in.setup, name, *in.executor, key, thread_count,
                                  CommandProgress("passing " + name, "trials")));
    }
    return played;
  });
  using S = const ScenarioTrials&;
  const auto at = [](S s, int i) -> const MatchTrialResult& { return s.trials[i]; };
  py::dict out;
  out["team"] = TrialColumn<std::int8_t>(results, [](int t, S, int) { return t; });
  out["scenario"] = TrialColumn<std::int32_t>(results, [](int, S s, int) { return s.scenario; });
  out["trial"] = TrialColumn<std::int32_t>(results, [](int, S, int i) { return i; });
  out["outcome"] = TrialColumn<std::int8_t>(
      results, [&](int, S s, int i) { return static_cast<int>(at(s, i).outcome); });
  out["to_goal"] =
      TrialColumn<bool>(results, [&](int, S s, int i) { return IsToGoal(at(s, i).outcome); });
  out["time_s"] =
      TrialColumn<double>(results, [&](int, S s, int i) { return at(s, i).counters.time_s; });
  out["attacker_kicks"] = TrialColumn<std::int32_t>(
      results, [&](int, S s, int i) { return Sum(at(s, i).counters.attacker_kicks); });
  out["opponent_touches"] = TrialColumn<std::int32_t>(
      results, [&](int, S s, int i) { return Sum(at(s, i).counters.opponent_touches); });
  // One counter of every trial (match/trial_result.h).
  const auto counter = [&](int TrialCounters::*field) {
    return TrialColumn<std::int32_t>(
        results, [&, field](int, S s, int i) { return at(s, i).counters.*field; });
  };
  out["shots_on_target"] = counter(&TrialCounters::shots_on_target);
  out["contests_resolved"] = counter(&TrialCounters::contests_resolved);
  out["stuck_penalties"] = counter(&TrialCounters::stuck_penalties);
  out["shots_saved"] = counter(&TrialCounters::shots_saved);
  out["grabs_failed"] = counter(&TrialCounters::grabs_failed);
  // Kicks whose physics trial did not end ok (physics=True only; models/outcome.h).
  out["kicks_missed"] = counter(&TrialCounters::kicks_missed);
  out["kicks_not_settled"] = counter(&TrialCounters::kicks_not_settled);
  out["kicks_fell"] = counter(&TrialCounters::kicks_fell);
  out["kicks_blocked"] = counter(&TrialCounters::kicks_blocked);
  std::vector<std::string> outcomes;
  for (int c = 0; c < kTrialOutcomeCount; ++c) {
    outcomes.emplace_back(TrialOutcomeName(static_cast<TrialOutcome>(c)));
  }
  out["team_names"] = teams;
  out["outcome_names"] = outcomes;
  return out;
}

struct CaseBaseObject {
  CbrRetriever retriever;
};

py::object Retrieve(const CaseBaseObject& base, const py::object& problem) {
  if (const auto path = AsPath(problem)) {
    const Problem p = LoadProblem(*path, base.retriever.models_dir);
    return ToPython(CbrRetrieveJson(RetrieveRun(base.retriever, p, *path)));
  }
  // A dict's field path ending in ".json" resolves against the working directory.
  const Problem p =
      ParseProblem(DictText(problem, "problem"), "problem (dict)", "", base.retriever.models_dir);
  return ToPython(CbrRetrieveJson(RetrieveRun(base.retriever, p, "")));
}

}  // namespace

void AddMatchAndCbr(py::module_& m) {
  m.def("passing", &Passing, py::arg("config"), py::arg("team") = py::none(),
        py::arg("scenarios") = py::none(), py::arg("trials") = py::none(),
        py::arg("seed") = py::none(), py::arg("threads") = py::none(), py::arg("mirror") = false,
        py::arg("physics") = false, py::arg("kicks") = py::none(), py::arg("models") = py::none(),
        // base last: older calls that pass arguments by position keep working
        py::arg("progress") = py::none(), py::arg("base") = py::none(),
        "The passing experiment's trials in the match simulator (`foresight experiment "
        "passing`): config 'dg' or '2d' (or a file), team 'reactive', 'cbr' or 'both', "
        "scenarios a list of 1-based numbers (None: all), trials per scenario. Returns NumPy "
        "arrays, one entry per trial in play order: team (code into team_names), scenario, "
        "trial, outcome (code into outcome_names), to_goal, time_s (simulated seconds), "
        "attacker_kicks, opponent_touches, shots_on_target, shots_saved, contests_resolved, "
        "stuck_penalties (the referee's local game stuck calls), grabs_failed, and the kicks whose physics trial missed, did not settle, fell or was "
        "blocked (kicks_missed, kicks_not_settled, kicks_fell, kicks_blocked; 0 without physics). base 'fixed' or "
        "'floating' (with physics=True) replaces the physics file's. The same seed gives the "
        "same trials as the command. Ctrl-C stops it; progress(label, done, total).");
  py::class_<CaseBaseObject>(m, "CaseBase",
                             "A case base (Ros et al. 2009) and the retrieval parameters, loaded "
                             "once (None: MODELS/cases and MODELS/cbr/retrieval.json).")
      .def(py::init([](const py::object& case_base, const py::object& params,
                       const std::optional<std::filesystem::path>& models) {
             CbrOptions options;
             if (!case_base.is_none()) options.case_base = FlagText(case_base, "case_base");
             if (!params.is_none()) options.params_file = FlagText(params, "params");
             return CaseBaseObject{LoadCbrRetriever(options, ModelsDir(models))};
           }),
           py::arg("case_base") = py::none(), py::arg("params") = py::none(),
           py::arg("models") = py::none())
      .def_property_readonly(
          "size", [](const CaseBaseObject& b) { return b.retriever.base.cases.size(); },
          "Stored cases, the symmetric copies included.")
      .def("retrieve", &Retrieve, py::arg("problem"),
           "Case retrieval for a problem (a path or a dict with the problem file's keys: field, "
           "defending, ball, teammates, opponents; metres and degrees in the field frame): what "
           "`foresight cbr retrieve --json` prints, as a dict.");
}

}  // namespace foresight::python
