#include "python/python_data.h"

#include <vector>

#include "common/error.h"
#include "common/strict_json.h"

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

std::optional<long long> AsInteger(const py::handle& value) {
  const py::object number = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!number) {
    PyErr_Clear();
    return std::nullopt;
  }
  int overflow = 0;
  const long long result = PyLong_AsLongLongAndOverflow(number.ptr(), &overflow);
  if (overflow != 0 || (result == -1 && PyErr_Occurred())) {
    PyErr_Clear();
    return std::nullopt;
  }
  return result;
}

namespace {

// One conversion: the containers open around the value being converted, checked before each
// step down, so a dict that holds itself or a structure deeper than the JSON reader's limit is
// one InputError instead of a C++ stack that overflows.
class Converter {
 public:
  explicit Converter(std::string argument) : argument_(std::move(argument)) {}

  nlohmann::json Convert(const py::handle& value, const std::string& where) {
    if (value.is_none()) return nullptr;
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
    if (PyLong_Check(value.ptr())) return Integer(value, where);
    if (PyFloat_Check(value.ptr())) return value.cast<double>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::dict>(value)) return Container(value, where, &Converter::Object);
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      return Container(value, where, &Converter::Array);
    }
    if (py::hasattr(value, "to_dict")) return Container(value, where, &Converter::ToDict);
    if (auto path = AsPath(value)) return path->string();
    // NumPy scalars and arrays: integers by __index__, numbers by __float__, arrays by tolist().
    if (py::hasattr(value, "tolist") && py::hasattr(value, "shape")) {
      return Container(value, where, &Converter::ToList);
    }
    if (py::hasattr(value, "__index__")) return Integer(value, where);
    if (py::hasattr(value, "__float__")) return value.cast<double>();
    Fail(where, "a " + TypeName(value) +
                    " is not JSON data (dict, list, str, number, bool or None)");
  }

 private:
  using Step = nlohmann::json (Converter::*)(const py::handle&, const std::string&);

  nlohmann::json Container(const py::handle& value, const std::string& where, Step step) {
    for (PyObject* open : open_) {
      if (open == value.ptr()) Fail(where, "holds itself (a dict or list inside itself)");
    }
    if (open_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
      Fail(where, "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    open_.push_back(value.ptr());
    nlohmann::json result = (this->*step)(value, where);
    open_.pop_back();
    return result;
  }

  nlohmann::json Object(const py::handle& value, const std::string& where) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, item] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(key)) {
        Fail(where, "keys must be strings, got " + py::repr(key).cast<std::string>());
      }
      const std::string name = key.cast<std::string>();
      object[name] = Convert(item, where.empty() ? name : where + "." + name);
    }
    return object;
  }

  // An object's to_dict() or an array's tolist() counts as a level: one that returns itself,
  // or a new object every time, ends as the containers do.
  nlohmann::json ToDict(const py::handle& value, const std::string& where) {
    return Convert(value.attr("to_dict")(), where);
  }
  nlohmann::json ToList(const py::handle& value, const std::string& where) {
    return Convert(value.attr("tolist")(), where);
  }

  nlohmann::json Array(const py::handle& value, const std::string& where) {
    nlohmann::json array = nlohmann::json::array();
    int i = 0;
    for (const py::handle item : value) {
      array.push_back(Convert(item, where + "[" + std::to_string(i++) + "]"));
    }
    return array;
  }

  long long Integer(const py::handle& value, const std::string& where) const {
    const std::optional<long long> n = AsInteger(value);
    if (!n) Fail(where, "an integer beyond 64 bits: " + py::repr(value).cast<std::string>());
    return *n;
  }

  [[noreturn]] void Fail(const std::string& where, const std::string& problem) const {
    std::string place = argument_;
    if (!where.empty()) place += (place.empty() ? "" : ": ") + where;
    throw InputError(place + ": " + problem);
  }

  std::string argument_;
  std::vector<PyObject*> open_;
};

}  // namespace

nlohmann::json ToJson(const py::handle& value, const std::string& where) {
  return Converter("").Convert(value, where);
}

std::string DictText(const py::handle& value, const std::string& what) {
  if (!py::isinstance<py::dict>(value)) {
    throw InputError(what + ": must be a path or a dict, got a " + TypeName(value));
  }
  return Converter(what).Convert(value, "").dump();
}

}  // namespace foresight::python
