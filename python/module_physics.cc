// foresight.simulate: physics trials of one kick as NumPy arrays, one entry per trial in trial
// order (trial i draws from its own stream, so the arrays do not depend on `threads`).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "app/simulate_command.h"
#include "common/geometry.h"
#include "python/long_call.h"
#include "python/module.h"

namespace py = pybind11;

namespace foresight::python {

namespace {

// One array of the trials' `field` (a double, or an enum or flag stored as int8).
template <typename T, typename Field>
py::array_t<T> Column(const std::vector<TrialResult>& trials, Field&& field) {
  py::array_t<T> column(static_cast<py::ssize_t>(trials.size()));
  auto out = column.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < trials.size(); ++i)
    out(static_cast<py::ssize_t>(i)) = static_cast<T>(field(trials[i]));
  return column;
}

py::dict Simulate(const std::filesystem::path& situation, const std::string& kick,
                  const py::object& trials,
                  const py::object& seed, const py::object& rotation_deg,
                  const py::object& threads, const py::object& kicks, const py::object& physics,
                  const std::optional<std::filesystem::path>& models, const py::object& base,
                  const py::object& progress) {
  SimulateOptions options;
  options.situation_file = situation.string();
  options.kick = kick;
  const auto set = [](std::string& flag, const py::object& value, const char* name) {
    if (!value.is_none()) flag = FlagText(value, name);
  };
  set(options.trials, trials, "trials");
  set(options.seed, seed, "seed");
  set(options.rotation_deg, rotation_deg, "rotation_deg");
  set(options.threads, threads, "threads");
  set(options.kicks_file, kicks, "kicks");
  set(options.physics_file, physics, "physics");
  set(options.base, base, "base");
  const std::filesystem::path dir = ModelsDir(models);
  const std::vector<TrialResult> r = RunLongCall(progress, [&] {
    const SimulationPlan plan = PlanSimulation(options, dir);
    return RunKickTrials(*plan.setup->simulator, plan.request);
  });
  using T = const TrialResult&;
  py::dict out;
  out["rest_x_m"] = Column<double>(r, [](T t) { return t.outcome.p_F_rest.x(); });
  out["rest_y_m"] = Column<double>(r, [](T t) { return t.outcome.p_F_rest.y(); });
  out["category"] = Column<std::int8_t>(r, [](T t) { return t.outcome.category; });
  out["first_contact"] = Column<std::int8_t>(r, [](T t) { return t.outcome.first_contact; });
  out["status"] = Column<std::int8_t>(r, [](T t) { return t.outcome.status; });
  out["time_s"] = Column<double>(r, [](T t) { return t.outcome.time_s; });
  out["touched"] = Column<bool>(r, [](T t) { return t.touched; });
  out["launched"] = Column<bool>(r, [](T t) { return t.launched; });
  out["settled"] = Column<bool>(r, [](T t) { return t.settled; });
  out["fell"] = Column<bool>(r, [](T t) { return t.fell; });
  out["blocked"] = Column<bool>(r, [](T t) { return t.blocked; });
  out["max_tilt_deg"] = Column<double>(r, [](T t) { return t.max_tilt_rad * kRadToDeg; });
  out["launch_speed_mps"] = Column<double>(r, [](T t) { return t.launch_speed_mps; });
  out["launch_direction_deg"] =
      Column<double>(r, [](T t) { return t.launch_direction_rad * kRadToDeg; });
  out["placement_dx_m"] = Column<double>(r, [](T t) { return t.draw.placement_dx_m; });
  out["placement_dy_m"] = Column<double>(r, [](T t) { return t.draw.placement_dy_m; });
  out["placement_dtheta_deg"] =
      Column<double>(r, [](T t) { return t.draw.placement_dtheta_rad * kRadToDeg; });
  out["speed_factor"] = Column<double>(r, [](T t) { return t.draw.speed_factor; });
  out["carpet_factor"] = Column<double>(r, [](T t) { return t.draw.carpet_factor; });
  out["placement_redraws"] = Column<std::int32_t>(r, [](T t) { return t.draw.placement_redraws; });
  // The names of the enum codes, index = code (models/outcome.h).
  std::vector<std::string> categories, contacts, statuses;
  for (int c = 0; c < kCategoryCount; ++c)
    categories.emplace_back(CategoryName(static_cast<Category>(c)));
  for (int c = 0; c <= static_cast<int>(Contact::kRobot); ++c)
    contacts.emplace_back(ContactName(static_cast<Contact>(c)));
  for (int s = 0; s < kOutcomeStatusCount; ++s)
    statuses.emplace_back(OutcomeStatusName(static_cast<OutcomeStatus>(s)));
  out["category_names"] = categories;
  out["contact_names"] = contacts;
  out["status_names"] = statuses;
  return out;
}

}  // namespace

void AddPhysicsFunctions(py::module_& m) {
  m.def("simulate", &Simulate, py::arg("situation"), py::arg("kick"),
        py::arg("trials") = py::none(), py::arg("seed") = py::none(),
        py::arg("rotation_deg") = py::none(), py::arg("threads") = py::none(),
        py::arg("kicks") = py::none(), py::arg("physics") = py::none(),
        // base and progress last: older calls that pass arguments by position keep working
        py::arg("models") = py::none(), py::arg("base") = py::none(),
        py::arg("progress") = py::none(),
        "Physics trials of one kick (`foresight simulate`): a dict of NumPy arrays, one entry "
        "per trial (rest_x_m, rest_y_m in F; category, first_contact, status as codes into "
        "category_names, contact_names, status_names; launch_speed_mps, launch_direction_deg in "
        "the intended robot frame; fell, blocked and max_tilt_deg on a floating base "
        "(base='floating'); "
        "the drawn perturbations). Ctrl-C stops it; progress(label, done, total) hears how far "
        "it is.");
}

}  // namespace foresight::python
