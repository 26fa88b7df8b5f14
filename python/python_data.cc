#include "python/python_data.h"

#include "common/error.h"

namespace py = pybind11;

namespace foresight::python {

std::string TypeName(const py::handle& value) {
  return py::str(value.get_type().attr("__name__")).cast<std::string>();
}

std::optional<std::filesystem::path> AsPath(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return std::filesystem::path(value.cast<std::string>());
  if (py::hasattr(value, "__fspath__")) {
    const py::object text = py::module_::import("os").attr("fspath")(value);
    if (py::isinstance<py::str>(text)) return std::filesystem::path(text.cast<std::string>());
  }
  return std::nullopt;
}

nlohmann::json ToJson(const py::handle& value, const std::string& where) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (PyLong_Check(value.ptr())) return value.cast<long long>();
  if (PyFloat_Check(value.ptr())) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) {
        throw InputError(where + ": keys must be strings, got " +
                         py::repr(key).cast<std::string>());
      }
      const std::string name = key.cast<std::string>();
      object[name] = ToJson(item, where.empty() ? name : where + "." + name);
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    nlohmann::json array = nlohmann::json::array();
    int i = 0;
    for (const py::handle item : value) {
      array.push_back(ToJson(item, where + "[" + std::to_string(i++) + "]"));
    }
    return array;
  }
  if (py::hasattr(value, "to_dict")) return ToJson(value.attr("to_dict")(), where);
  if (auto path = AsPath(value)) return path->string();
  // NumPy scalars and arrays: integers by __index__, numbers by __float__, arrays by tolist().
  if (py::hasattr(value, "tolist") && py::hasattr(value, "shape")) {
    return ToJson(value.attr("tolist")(), where);
  }
  if (py::hasattr(value, "__index__")) return value.cast<long long>();
  if (py::hasattr(value, "__float__")) return value.cast<double>();
  throw InputError(where + ": a " + TypeName(value) +
                   " is not JSON data (dict, list, str, number, bool or None)");
}

std::string DictText(const py::handle& value, const std::string& what) {
  if (!py::isinstance<py::dict>(value)) {
    throw InputError(what + ": must be a path or a dict, got a " + TypeName(value));
  }
  return ToJson(value, "").dump();
}

}  // namespace foresight::python
