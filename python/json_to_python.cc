#include "python/json_to_python.h"

#include <cmath>
#include <cstdint>

namespace foresight::python {

namespace {

template <typename Json>
pybind11::object Convert(const Json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::object: {
      pybind11::dict dict;
      for (auto it = value.begin(); it != value.end(); ++it) dict[pybind11::str(it.key())] = Convert(*it);
      return dict;  // moved implicitly (C++20)
    }
    case nlohmann::json::value_t::array: {
      pybind11::list list;
      for (const auto& item : value) list.append(Convert(item));
      return list;  // moved implicitly (C++20)
    }
    case nlohmann::json::value_t::string:
      return pybind11::str(value.template get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean:
      return pybind11::bool_(value.template get<bool>());
    case nlohmann::json::value_t::number_integer:
      return pybind11::int_(value.template get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return pybind11::int_(value.template get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: {
      // The CLI writes NaN and the infinities as null (JSON has no such numbers); so does this.
      const double x = value.template get<double>();
      if (!std::isfinite(x)) return pybind11::none();
      return pybind11::float_(x);
    }
    default:
      return pybind11::none();
  }
}

}  // namespace

pybind11::object ToPython(const nlohmann::json& value) { return Convert(value); }
pybind11::object ToPython(const nlohmann::ordered_json& value) { return Convert(value); }

}  // namespace foresight::python
