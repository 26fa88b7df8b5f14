// What `foresight cbr retrieve` prints: the retrieval of one problem over the case base, as text
// or as JSON (the contract: same input, same bytes).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "cbr/case.h"
#include "cbr/case_base.h"
#include "cbr/problem.h"
#include "cbr/retrieval.h"
#include "cbr/retrieval_params.h"

namespace foresight {

struct CbrRetrieveRun {
  std::filesystem::path problem_file;
  std::filesystem::path case_base_path;
  std::filesystem::path params_file;
  std::filesystem::path models_dir;
  Problem problem;
  const LoadedCaseBase* base = nullptr;
  std::span<const Case> cases;  // the case base's cases for problem.defending
  RetrievalParams params;
  RetrievalResult result;

  const Case* Retrieved() const {
    return result.retrieved ? &cases[static_cast<std::size_t>(*result.retrieved)] : nullptr;
  }
};

// A fulfilled condition of sec. 3.3.2: problem opponent `problem_opponent` is inside the scope of
// case opponent `case_opponent` (indices) moved to the problem's ball.
struct MetCondition {
  int case_opponent = -1;
  int problem_opponent = -1;
  double membership = 0.0;
};
std::vector<MetCondition> MetConditions(const Problem& problem, const Case& c, double thr_opp);

// The text report; `verbose` adds every rejected case's explanation.
std::string CbrRetrieveText(const CbrRetrieveRun& run, bool verbose);
nlohmann::ordered_json CbrRetrieveJson(const CbrRetrieveRun& run);

}  // namespace foresight
