// The Python module `foresight`: the commands' work as functions that return what the
// commands print or write as JSON, as Python objects. Every function takes the command's flags as
// keyword arguments (None: the command's default) and checks them with the command's own code, so
// bad input raises foresight.InputError (a ValueError) with the command's one-line message. Long
// work runs without the GIL.
#pragma once

#include <filesystem>
#include <optional>
#include <pybind11/pybind11.h>
#include <string>

namespace foresight::python {

// The data folder: `models`, or the one the command would use (models/model_paths.h).
std::filesystem::path ModelsDir(const std::optional<std::filesystem::path>& models);

// A keyword argument as the flag's text: "" for None, str(value) otherwise (so 0.1 stays 0.1).
// An empty text is an InputError naming the argument `name`: '' is never "not given", as the
// command line refuses `--flag ''`.
std::string FlagText(const pybind11::object& value, const std::string& name);

// `simulate`: physics trials as NumPy arrays (module_physics.cc).
void AddPhysicsFunctions(pybind11::module_& module);

// `passing` and `CaseBase`: the match simulator and case retrieval (match_cbr.cc).
void AddMatchAndCbr(pybind11::module_& module);

}  // namespace foresight::python
