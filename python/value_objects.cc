// The small classes of the module: Pose, Ball, Obstacle and KickModel, and the conversions of
// the Python values a decision accepts in their place (a dict with the file's keys, a tuple).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "common/error.h"
#include "common/geometry.h"
#include "common/json_reader.h"
#include "python/json_to_python.h"
#include "python/planner_objects.h"
#include "python/python_data.h"

namespace py = pybind11;

namespace foresight::python {

namespace {

double Number(const py::handle& value, const std::string& where) {
  if (py::isinstance<py::bool_>(value) ||
      !(PyFloat_Check(value.ptr()) || PyLong_Check(value.ptr()) ||
        py::hasattr(value, "__float__"))) {
    throw InputError(where + ": must be a number, got a " + TypeName(value));
  }
  return value.cast<double>();
}

std::optional<double> OptionalNumber(const py::dict& d, const char* key, const std::string& where) {
  if (!d.contains(key)) return std::nullopt;
  return Number(d[key], where + "." + key);
}

void RejectUnknown(const py::dict& d, std::initializer_list<const char*> known,
                   const std::string& where) {
  for (const auto& [key, value] : d) {
    const std::string name = py::str(key).cast<std::string>();
    bool found = false;
    for (const char* k : known) found = found || name == k;
    if (!found) throw InputError(where + ": unknown key '" + name + "'");
  }
}

py::dict Items(std::initializer_list<std::pair<const char*, std::optional<double>>> items) {
  py::dict d;
  for (const auto& [key, value] : items) {
    if (value) d[key] = *value;
  }
  return d;
}

}  // namespace

PoseArg PoseFrom(const py::handle& value, const std::string& where) {
  if (py::isinstance<PoseArg>(value)) return value.cast<PoseArg>();
  PoseArg p;
  if (py::isinstance<py::dict>(value)) {
    const py::dict d = value.cast<py::dict>();
    RejectUnknown(d, {"x_m", "y_m", "theta_deg", "sigma_x_m", "sigma_y_m", "sigma_theta_deg"},
                  where);
    for (const char* key : {"x_m", "y_m", "theta_deg"}) {
      if (!d.contains(key)) throw InputError(where + ": missing key '" + key + "'");
    }
    p.x_m = Number(d["x_m"], where + ".x_m");
    p.y_m = Number(d["y_m"], where + ".y_m");
    p.theta_deg = Number(d["theta_deg"], where + ".theta_deg");
    p.sigma_x_m = OptionalNumber(d, "sigma_x_m", where);
    p.sigma_y_m = OptionalNumber(d, "sigma_y_m", where);
    p.sigma_theta_deg = OptionalNumber(d, "sigma_theta_deg", where);
    return p;
  }
  if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
    const py::sequence s = value.cast<py::sequence>();
    if (s.size() != 3) {
      throw InputError(where + ": must be (x_m, y_m, theta_deg), got " + std::to_string(s.size()) +
                       " values");
    }
    p.x_m = Number(s[0], where + "[0]");
    p.y_m = Number(s[1], where + "[1]");
    p.theta_deg = Number(s[2], where + "[2]");
    return p;
  }
  throw InputError(where + ": must be a Pose, a dict or (x_m, y_m, theta_deg), got a " +
                   TypeName(value));
}

BallArg BallFrom(const py::handle& value, const std::string& where) {
  if (py::isinstance<BallArg>(value)) return value.cast<BallArg>();
  BallArg b;
  if (py::isinstance<py::dict>(value)) {
    const py::dict d = value.cast<py::dict>();
    RejectUnknown(d, {"x_m", "y_m", "sigma_x_m", "sigma_y_m"}, where);
    for (const char* key : {"x_m", "y_m"}) {
      if (!d.contains(key)) throw InputError(where + ": missing key '" + key + "'");
    }
    b.x_m = Number(d["x_m"], where + ".x_m");
    b.y_m = Number(d["y_m"], where + ".y_m");
    b.sigma_x_m = OptionalNumber(d, "sigma_x_m", where);
    b.sigma_y_m = OptionalNumber(d, "sigma_y_m", where);
    return b;
  }
  if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
    const py::sequence s = value.cast<py::sequence>();
    if (s.size() != 2) {
      throw InputError(where + ": must be (x_m, y_m), got " + std::to_string(s.size()) + " values");
    }
    b.x_m = Number(s[0], where + "[0]");
    b.y_m = Number(s[1], where + "[1]");
    return b;
  }
  throw InputError(where + ": must be a Ball, a dict or (x_m, y_m), got a " + TypeName(value));
}

void ApplyPose(const PoseArg& p, StateEstimate& state) {
  state.robot.p_F = Vec2(p.x_m, p.y_m);
  state.robot.theta_rad = p.theta_deg * kDegToRad;
  if (p.sigma_x_m) state.sigma_robot_x_m = *p.sigma_x_m;
  if (p.sigma_y_m) state.sigma_robot_y_m = *p.sigma_y_m;
  if (p.sigma_theta_deg) state.sigma_robot_theta_rad = *p.sigma_theta_deg * kDegToRad;
}

void ApplyBall(const BallArg& b, StateEstimate& state) {
  state.p_R_ball = Vec2(b.x_m, b.y_m);
  if (b.sigma_x_m) state.sigma_ball_x_m = *b.sigma_x_m;
  if (b.sigma_y_m) state.sigma_ball_y_m = *b.sigma_y_m;
}

KickModelArg KickModelFrom(const py::handle& value) {
  if (py::isinstance<KickModelArg>(value)) return value.cast<KickModelArg>();
  if (const auto path = AsPath(value)) return {LoadKickModel(*path), path->string()};
  return {ParseKickModel(DictText(value, "kicks"), "kicks (dict)"), "kicks (dict)"};
}

void AddValueObjects(py::module_& m) {
  py::class_<PoseArg>(m, "Pose",
                      "A robot pose in the field frame F: x_m, y_m (metres), theta_deg "
                      "(degrees, 0 = towards the opponent goal); sigmas of the belief "
                      "(None: the situation's).")
      .def(py::init<double, double, double, std::optional<double>, std::optional<double>,
                    std::optional<double>>(),
           py::arg("x_m"), py::arg("y_m"), py::arg("theta_deg"), py::arg("sigma_x_m") = py::none(),
           py::arg("sigma_y_m") = py::none(), py::arg("sigma_theta_deg") = py::none())
      .def_readwrite("x_m", &PoseArg::x_m)
      .def_readwrite("y_m", &PoseArg::y_m)
      .def_readwrite("theta_deg", &PoseArg::theta_deg)
      .def_readwrite("sigma_x_m", &PoseArg::sigma_x_m)
      .def_readwrite("sigma_y_m", &PoseArg::sigma_y_m)
      .def_readwrite("sigma_theta_deg", &PoseArg::sigma_theta_deg)
      .def(
          "to_dict",
          [](const PoseArg& p) {
            py::dict d = Items({{"x_m", p.x_m},
                                {"y_m", p.y_m},
                                {"theta_deg", p.theta_deg},
                                {"sigma_x_m", p.sigma_x_m},
                                {"sigma_y_m", p.sigma_y_m},
                                {"sigma_theta_deg", p.sigma_theta_deg}});
            return d;
          },
          "The situation file's `robot` object (unset sigmas left out).")
      .def("__repr__", [](const PoseArg& p) {
        return "Pose(x_m=" + std::string(py::repr(py::float_(p.x_m))) +
               ", y_m=" + std::string(py::repr(py::float_(p.y_m))) +
               ", theta_deg=" + std::string(py::repr(py::float_(p.theta_deg))) + ")";
      });
  py::class_<BallArg>(m, "Ball",
                      "The ball relative to the robot, in the robot frame R: x_m "
                      "ahead, y_m to the left (metres); sigmas of the belief (None: "
                      "the situation's).")
      .def(py::init<double, double, std::optional<double>, std::optional<double>>(), py::arg("x_m"),
           py::arg("y_m"), py::arg("sigma_x_m") = py::none(), py::arg("sigma_y_m") = py::none())
      .def_readwrite("x_m", &BallArg::x_m)
      .def_readwrite("y_m", &BallArg::y_m)
      .def_readwrite("sigma_x_m", &BallArg::sigma_x_m)
      .def_readwrite("sigma_y_m", &BallArg::sigma_y_m)
      .def(
          "to_dict",
          [](const BallArg& b) {
            return Items({{"x_m", b.x_m},
                          {"y_m", b.y_m},
                          {"sigma_x_m", b.sigma_x_m},
                          {"sigma_y_m", b.sigma_y_m}});
          },
          "The situation file's `ball` object (unset sigmas left out).")
      .def("__repr__", [](const BallArg& b) {
        return "Ball(x_m=" + std::string(py::repr(py::float_(b.x_m))) +
               ", y_m=" + std::string(py::repr(py::float_(b.y_m))) + ")";
      });
  py::class_<ObstacleArg>(m, "Obstacle",
                          "An obstacle robot in the field frame F: a disc at x_m, "
                          "y_m of radius_m (None: the field's default), metres.")
      .def(py::init<double, double, std::optional<double>>(), py::arg("x_m"), py::arg("y_m"),
           py::arg("radius_m") = py::none())
      .def_readwrite("x_m", &ObstacleArg::x_m)
      .def_readwrite("y_m", &ObstacleArg::y_m)
      .def_readwrite("radius_m", &ObstacleArg::radius_m)
      .def(
          "to_dict",
          [](const ObstacleArg& o) {
            return Items({{"x_m", o.x_m}, {"y_m", o.y_m}, {"radius_m", o.radius_m}});
          },
          "The situation file's obstacle object.")
      .def("__repr__", [](const ObstacleArg& o) {
        return "Obstacle(x_m=" + std::string(py::repr(py::float_(o.x_m))) +
               ", y_m=" + std::string(py::repr(py::float_(o.y_m))) + ")";
      });

  py::class_<KickModelArg>(m, "KickModel",
                           "A checked kick model (models/kicks/*.json): from a path or a dict "
                           "with the file's keys (robot, rolling_deceleration_mps2, kicks: name, "
                           "speed_mps, sigma_speed_mps, direction_deg, sigma_direction_deg, "
                           "launch_offset_m).")
      .def(py::init([](const py::object& source) { return KickModelFrom(source); }),
           py::arg("source"))
      .def_property_readonly("robot", [](const KickModelArg& k) { return k.model.robot; })
      .def_property_readonly("source", [](const KickModelArg& k) { return k.source; })
      .def_property_readonly(
          "rolling_deceleration_mps2",
          [](const KickModelArg& k) { return k.model.rolling_deceleration_mps2; })
      .def_property_readonly(
          "names",
          [](const KickModelArg& k) {
            std::vector<std::string> names;
            for (const KickSpec& s : k.model.kicks) names.push_back(s.name);
            return names;
          },
          "The kicks' names in the model's order (the kick_index of a decision).")
      .def(
          "to_dict",
          [](const KickModelArg& k) {
            return ToPython(JsonDocument::Parse(KickModelJson(k.model, ""), k.source).Tree());
          },
          "The model as its file's content (degrees, m/s, m/s^2).")
      .def("__repr__", [](const KickModelArg& k) {
        return "KickModel(robot='" + k.model.robot + "', kicks=[" + k.model.Names() + "])";
      });
}

}  // namespace foresight::python
