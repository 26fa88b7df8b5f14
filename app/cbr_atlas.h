// The case atlas of `foresight cbr atlas`: one self-contained HTML page that draws every
// hand-written case of a case base (app/cbr_drawing.h) in a grid, with its name, notes and the
// names of its stored symmetric copies.
#pragma once

#include <filesystem>
#include <string>

#include "cbr/case_base.h"
#include "cbr/retrieval_params.h"

namespace foresight {

struct CbrAtlasInput {
  std::filesystem::path case_base_path;
  std::filesystem::path params_file;
  std::filesystem::path models_dir;
  const LoadedCaseBase* base = nullptr;
  RetrievalParams params;
};

std::string CbrAtlasHtml(const CbrAtlasInput& input);

}  // namespace foresight
