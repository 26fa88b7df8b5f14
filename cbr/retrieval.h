// Case retrieval (Ros et al. 2009, sec. 3.4): Algorithm 1 filters, Algorithm 2 ranks.
//
// IsCandidate(p, c) (Algorithm 1), a case is rejected at the first failing test:
//   1. sim_B(B^p, B^c) > thr_b                                  (sec. 3.1)
//   2. the case has no more teammates than the problem          (sec. 3.2)
//   3. correspondence with every distance <= thr_c              (sec. 3.2, cbr/correspondence.h)
//   4. free_path(p, c) = 1                                       (sec. 3.3.1, cbr/free_path.h)
// Retrieve(p, CB) (Algorithm 2): the candidates sorted by the criteria of RetrievalParams::order
// (paper: conditions desc, teammates desc, similarity band H > h > l > L then cost asc); the first
// one is retrieved. Ties (all criteria equal) go to the lower case index. "No candidate" is a
// result (retrieved is empty), not an error.
//
// Decisions (the paper is silent): the defending goal is checked too (a case for the other goal
// is rejected, though the caller should pass only the cases of the problem's goal); a case with
// no teammates or more than kMaxTeammates is rejected as invalid, and so is every case for a
// problem with more than kMaxTeammates teammates (the problem loader allows 1-4). Conditions are
// computed for candidates only (they rank, never reject).
//
// Large case bases: Retrieve with a BallScopeIndex (cbr/ball_scope_index.h) evaluates only the
// cases whose ball scope may hold the problem ball and returns the same retrieved case, ranking
// and evaluations; the skipped cases' explanations come from EvaluationOf on request.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cbr/ball_scope_index.h"
#include "cbr/case.h"
#include "cbr/correspondence.h"
#include "cbr/free_path.h"
#include "cbr/problem.h"
#include "cbr/retrieval_params.h"

namespace foresight {

enum class Verdict {
  kCandidate,
  kOtherGoal,        // the case is for the other defending goal
  kInvalidCase,      // 0 or more than kMaxTeammates teammates
  kInvalidProblem,   // the problem has more than kMaxTeammates teammates
  kBallOutOfScope,   // sim_B <= thr_b
  kTooFewTeammates,  // the case needs more teammates than the problem has
  kTooFar,           // no matching keeps every distance <= thr_c
  kPathBlocked,      // an opponent is on a trajectory of the ball path
};
std::string_view VerdictName(Verdict verdict);

// Everything retrieval found out about one case.
struct CaseEvaluation {
  int case_index = -1;
  Verdict verdict = Verdict::kInvalidCase;
  double ball_similarity = 0.0;   // always computed (but for kOtherGoal / kInvalidCase)
  int teammates = 0;              // the case's teammates
  int conditions = 0;             // sim_opp; computed for candidates only
  int band = 3;                   // 0 = H, 1 = h, 2 = l, 3 = L
  Correspondence correspondence;  // from the cost test on (for kTooFar: the explanation)
  PathCheck path;                 // for kPathBlocked: the blocker
  int rank = -1;                  // 0 = retrieved; -1 when rejected
};

struct RetrievalResult {
  std::optional<int> retrieved;  // index into the cases passed in
  // all_cases: one per case, in the cases' order (evaluations[i].case_index == i). Retrieval
  // with a BallScopeIndex: only the cases the index returned, in ascending case_index; every
  // other case is not a candidate (kBallOutOfScope, or kOtherGoal / kInvalidCase /
  // kInvalidProblem as for every case) and EvaluationOf computes its explanation on request.
  std::vector<CaseEvaluation> evaluations;
  bool all_cases = true;
  std::vector<int> ranking;  // candidate case indices, best first
  CaseBallPath ball_path;    // of the retrieved case

  // The stored evaluation of case `case_index`, or nullptr if it was not evaluated.
  const CaseEvaluation* Find(int case_index) const;
  const CaseEvaluation* Best() const { return retrieved ? Find(*retrieved) : nullptr; }
};

// The similarity band of sec. 3.4: 0 (H) for sim >= band_lower[0], ..., 3 (L) below band_lower[2].
int SimilarityBand(double similarity, const RetrievalParams& params);

// Algorithm 1 with its explanation; `index` is stored as case_index.
CaseEvaluation EvaluateCase(const Problem& problem, const Case& c, int index,
                            const RetrievalParams& params);

// Whether candidate a ranks before candidate b (sec. 3.4, in the order of params.order).
bool RanksBefore(const CaseEvaluation& a, const CaseEvaluation& b, const RetrievalParams& params);

// Algorithm 2. `cases` should be the case base's cases for problem.defending. The overload with
// `out` reuses its vectors' capacity (no allocation once warm).
RetrievalResult Retrieve(std::span<const Case> cases, const Problem& problem,
                         const RetrievalParams& params);
void Retrieve(std::span<const Case> cases, const Problem& problem, const RetrievalParams& params,
              RetrievalResult* out);

// Algorithm 2 evaluating only the cases `index` returns for the problem ball (the others cannot
// pass the ball filter): the same retrieved case, ranking, ball path and, for every evaluated
// case, the same evaluation as Retrieve without the index; out->all_cases is false.
// Preconditions (InputError otherwise): `index` was built from `cases` with params.thr_ball.
void Retrieve(std::span<const Case> cases, const BallScopeIndex& index, const Problem& problem,
              const RetrievalParams& params, RetrievalResult* out);
RetrievalResult Retrieve(std::span<const Case> cases, const BallScopeIndex& index,
                         const Problem& problem, const RetrievalParams& params);

// The evaluation of case `case_index` for the result `r` of retrieving `problem` from `cases`:
// the stored one, or (a case the index skipped) EvaluateCase's, which is what retrieval without
// the index stores for it (rank -1).
CaseEvaluation EvaluationOf(const RetrievalResult& r, std::span<const Case> cases,
                            const Problem& problem, const RetrievalParams& params, int case_index);

// One line on why `e` was rejected or where it ranked, naming robots by id and opponents by
// their index in the problem ("path blocked: opponent 1 at (0.5, 0.02) on trajectory 0 (pass
// 2 -> 3), mu 0.99 > 0.368").
std::string Explain(const CaseEvaluation& e, const Case& c, const Problem& problem,
                    const RetrievalParams& params);

}  // namespace foresight
