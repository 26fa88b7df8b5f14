// A JSON value (the reports' contract) as the Python objects json.loads would make of it: dict
// (keys in order), list, str, int, float, bool, None. The numbers keep their bits.
#pragma once

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace foresight::python {

pybind11::object ToPython(const nlohmann::json& value);
pybind11::object ToPython(const nlohmann::ordered_json& value);

}  // namespace foresight::python
