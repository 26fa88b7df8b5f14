// A case played in the situation it was written for: its own problem (ball, goal, teammates
// facing the attacked goal, opponents where the case puts them) and the free-path test there
// (Ros et al. 2009, sec. 3.3.1). A case whose own opponent stands on its ball path is never
// retrieved by a problem that looks exactly like it (`foresight cbr check` fails on such cases,
// `cbr atlas` marks them).
#pragma once

#include "cbr/case.h"
#include "cbr/free_path.h"
#include "cbr/problem.h"
#include "cbr/retrieval_params.h"

namespace foresight {

Problem CaseOwnProblem(const Case& c);

// The ball path of `c` played from its own problem, its teammates at their own positions.
CaseBallPath OwnBallPath(const Case& c, const RetrievalParams& params);

PathCheck OwnPathCheck(const Case& c, const RetrievalParams& params);

}  // namespace foresight
