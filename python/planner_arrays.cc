// Planner.decide_many: one decision per row of NumPy arrays, without the GIL, as a long call
// (Ctrl-C, progress). Row i decides for robots[i] (x_m, y_m, theta_deg in F) and, if given,
// balls[i] (x_m, y_m in the robot frame), with seed `seed` (every row) or seeds[i]; the rest of
// the belief (sigmas) is the planner's situation's. Equal to decide() row by row.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <vector>

#include "common/error.h"
#include "common/geometry.h"
#include "common/long_call.h"
#include "python/long_call.h"
#include "python/planner_objects.h"

namespace py = pybind11;

namespace foresight::python {

namespace {

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

// NumPy's cast to double would drop a complex number's imaginary part and a masked array's
// mask without a word: both are refused.
void RequireRealUnmasked(const py::object& value, const char* what) {
  const py::module_ numpy = py::module_::import("numpy");
  py::object array;
  try {
    array = numpy.attr("asanyarray")(value);
  } catch (const py::error_already_set&) {
    return;  // no array at all (ragged rows): RowsOf says what it must be
  }
  if (py::isinstance(array, numpy.attr("ma").attr("MaskedArray"))) {
    throw InputError(std::string(what) +
                     ": a masked array (its mask would be ignored): pass the rows to use");
  }
  if (array.attr("dtype").attr("kind").cast<std::string>() == "c") {
    throw InputError(std::string(what) +
                     ": complex numbers (the imaginary part would be dropped): pass real ones");
  }
}

Rows RowsOf(const py::object& value, int columns, const char* what, const char* layout) {
  RequireRealUnmasked(value, what);
  Rows rows = Rows::ensure(value);
  if (!rows || rows.ndim() != 2 || rows.shape(1) != columns) {
    PyErr_Clear();
    throw InputError(std::string(what) + ": must be an array of shape (N, " +
                     std::to_string(columns) + "): " + layout);
  }
  return rows;
}

py::dict DecideMany(const std::shared_ptr<PlannerCore>& core, const py::object& robots,
                    const py::object& balls, const py::object& seed, const py::object& strategy,
                    const py::object& samples, const py::object& progress) {
  const Rows robot_rows = RowsOf(robots, 3, "robots", "x_m, y_m, theta_deg per row");
  const auto n = robot_rows.shape(0);
  std::vector<StateEstimate> states(static_cast<std::size_t>(n), core->situation.state);
  const auto r = robot_rows.unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    states[i].robot.p_F = Vec2(r(i, 0), r(i, 1));
    states[i].robot.theta_rad = r(i, 2) * kDegToRad;
  }
  if (!balls.is_none()) {
    const Rows ball_rows = RowsOf(balls, 2, "balls", "x_m, y_m per row, in the robot frame");
    if (ball_rows.shape(0) != n) {
      throw InputError("balls: has " + std::to_string(ball_rows.shape(0)) + " rows, robots " +
                       std::to_string(n));
    }
    const auto b = ball_rows.unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i) states[i].p_R_ball = Vec2(b(i, 0), b(i, 1));
  }
  std::vector<std::uint64_t> seeds;
  if (py::isinstance<py::array>(seed) || py::isinstance<py::list>(seed) ||
      py::isinstance<py::tuple>(seed)) {
    for (const py::handle s : seed) seeds.push_back(SeedFrom(s));
    if (static_cast<py::ssize_t>(seeds.size()) != n) {
      throw InputError("seed: has " + std::to_string(seeds.size()) + " seeds, robots " +
                       std::to_string(n) + " rows");
    }
  } else {
    seeds.assign(static_cast<std::size_t>(n), SeedFrom(seed));
  }
  const int sample_count = SamplesFrom(samples, core->samples);
  const Strategy chosen = StrategyFrom(strategy, core->strategy);

  py::array_t<std::int32_t> kick_index(n);
  py::array_t<double> rotation_deg(n), utility(n);
  py::array_t<std::int64_t> hypotheses(n);
  auto k = kick_index.mutable_unchecked<1>();
  auto rot = rotation_deg.mutable_unchecked<1>();
  auto u = utility.mutable_unchecked<1>();
  auto h = hypotheses.mutable_unchecked<1>();
  const PlannerLock lock(*core);
  RunLongCall(progress, [&] {
    const ProgressFunction report = LongCallProgress("decide", "poses", {});  // rate-limited
    for (py::ssize_t i = 0; i < n; ++i) {
      WithFile("robots[" + std::to_string(i) + "]",
               [&] { DecideLocked(*core, states[i], chosen, sample_count, seeds[i]); });
      const Decision& d = core->scratch;
      k(i) = d.kick_index;
      rot(i) = d.rotation_rad * kRadToDeg;
      u(i) = d.kick_index == kNoKick ? d.none.trimmed_utility
                                     : d.kicks[d.kick_index].choice.evaluation.trimmed_utility;
      h(i) = d.evaluations;
      if (report) report(static_cast<int>(i + 1), static_cast<int>(n));
      PollLongCall();
    }
    return 0;
  });
  py::dict out;
  out["kick_index"] = kick_index;
  out["rotation_deg"] = rotation_deg;
  out["trimmed_utility"] = utility;
  out["hypotheses"] = hypotheses;
  py::list names;
  for (const KickSpec& spec : core->situation.kicks.kicks) names.append(spec.name);
  out["kick_names"] = names;
  return out;
}

}  // namespace

void AddPlannerArrays(py::class_<PlannerCore, std::shared_ptr<PlannerCore>>& planner) {
  planner.def("decide_many", &DecideMany, py::arg("robots"), py::arg("balls") = py::none(),
              py::arg("seed") = 1, py::arg("strategy") = py::none(),
              py::arg("samples") = py::none(), py::arg("progress") = py::none(),
              "Decisions for many poses: robots (N, 3) [x_m, y_m, theta_deg] in F, balls None "
              "or (N, 2) [x_m, y_m] in the robot frame, seed an int (every row) or N ints. "
              "Returns NumPy arrays kick_index (int32, -1: none, into kick_names), "
              "rotation_deg, trimmed_utility (the chosen action's, eq. 6) and hypotheses "
              "(int64), row by row equal to decide(). Runs without the GIL; Ctrl-C stops it; "
              "progress(label, done, total) is called about 100 times.");
}

}  // namespace foresight::python
