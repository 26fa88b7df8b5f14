// Python data as the project's JSON: what the module's functions accept in place of a file.
// A dict is the file's content (the same keys and units); the module turns it into JSON text
// and reads it with the file's own reader, so a dict is checked exactly as a file is and a bad
// value raises InputError naming `origin`, the field and the value.
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace foresight::python {

// An int (or an object with __index__) that fits in 64 bits; nullopt otherwise (too large, not
// an integer).
std::optional<long long> AsInteger(const pybind11::handle& value);

// The name of a value's type, for messages ("dict", "str").
std::string TypeName(const pybind11::handle& value);

// str or os.PathLike as a path; nullopt for anything else.
std::optional<std::filesystem::path> AsPath(const pybind11::handle& value);

// A dict, list, str, number, bool or None (NumPy scalars, paths and objects with a to_dict()
// method included) as JSON; anything else is an InputError "WHERE: ...".
nlohmann::json ToJson(const pybind11::handle& value, const std::string& where);

// A dict as JSON text for the file readers; a non-dict is an InputError naming `what`.
std::string DictText(const pybind11::handle& value, const std::string& what);

}  // namespace foresight::python
