// `foresight cbr`: case-based coordinated action selection (Ros et al. 2009) on the command line.
//   cbr retrieve: the case retrieved for a problem file, with the ranking and every rejection;
//   cbr check:    loads and validates a case base, prints its counts and overlap warnings, and
//                 fails on a case blocked by its own opponent or asking its kicks for more than
//                 they carry (cbr/case_reach.h);
//   cbr atlas:    an HTML page drawing every hand-written case.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cbr_retrieve_output.h"

namespace foresight {

struct CbrOptions {
  std::string problem_file;
  std::string case_base;    // folder or settings file; empty: MODELS/cases
  std::string params_file;  // empty: MODELS/cbr/retrieval.json
  std::string kicks_file;   // cbr check: the kick model to check reach against; empty: the base's
  bool json = false;
  bool verbose = false;
  std::string svg_file;
  std::string out_dir;
  CLI::App* retrieve = nullptr;
  CLI::App* check = nullptr;
  CLI::App* atlas = nullptr;
};

void AddCbrCommand(CLI::App& app, CbrOptions& options);

// What `cbr retrieve --json` prints for options.problem_file (with options.case_base and
// options.params_file), as JSON; bad input throws InputError (the Python module's cbr_retrieve).
nlohmann::ordered_json CbrRetrieveJsonFor(const CbrOptions& options,
                                          const std::filesystem::path& models);

// A case base and the retrieval parameters, loaded once for many retrievals (the Python
// module's CaseBase): options.case_base and options.params_file as `cbr retrieve` reads them.
struct CbrRetriever {
  std::filesystem::path case_base_path, params_file, models_dir;
  LoadedCaseBase base;
  RetrievalParams params;
};
CbrRetriever LoadCbrRetriever(const CbrOptions& options, const std::filesystem::path& models);
// One retrieval for `problem` (named `problem_file` in the output; "" for one not from a file).
// The run points into `retriever`.
CbrRetrieveRun RetrieveRun(const CbrRetriever& retriever, const Problem& problem,
                           const std::filesystem::path& problem_file);

// Runs the chosen subcommand; bad input throws InputError. Returns the exit code.
int RunCbrCommand(const CbrOptions& options, const std::string& models_dir);

}  // namespace foresight
