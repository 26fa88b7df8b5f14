#include "cbr/retrieval.h"

#include <algorithm>
#include <cmath>

#include "cbr/similarity.h"
#include "common/checks.h"
#include "common/enum_names.h"
#include "common/error.h"

namespace foresight {
namespace {

constexpr EnumNames<Verdict, 8> kVerdictNames{{{
    {Verdict::kCandidate, "candidate"},
    {Verdict::kOtherGoal, "other_goal"},
    {Verdict::kInvalidCase, "invalid_case"},
    {Verdict::kInvalidProblem, "invalid_problem"},
    {Verdict::kBallOutOfScope, "ball_out_of_scope"},
    {Verdict::kTooFewTeammates, "too_few_teammates"},
    {Verdict::kTooFar, "too_far"},
    {Verdict::kPathBlocked, "path_blocked"},
}}};

constexpr const char* kBandNames[] = {"H", "h", "l", "L"};

// Explanations give metres to the millimetre and memberships to 1e-3.
std::string Milli(double v) {
  return FormatNumber(std::round(v * 1000.0) / 1000.0);
}

std::string Point(const Vec2& p) {
  std::string s = "(";  // appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict) on that
  s += Milli(p.x());
  s += ", ";
  s += Milli(p.y());
  s += ")";
  return s;
}

}  // namespace

std::string_view VerdictName(Verdict verdict) {
  return kVerdictNames.Name(verdict);
}

int SimilarityBand(double similarity, const RetrievalParams& params) {
  for (int b = 0; b < 3; ++b) {
    if (similarity >= params.band_lower[b]) return b;
  }
  return 3;
}

namespace {

// Algorithm 1 into `out`, a default-constructed evaluation (retrieval builds it in place in the
// result's vector: no copy of the evaluation per case).
void Evaluate(const Problem& problem, const Case& c, int index, const RetrievalParams& params,
              CaseEvaluation* out) {
  CaseEvaluation& e = *out;
  e.case_index = index;
  e.teammates = static_cast<int>(c.teammates.size());
  if (c.defending != problem.defending) {
    e.verdict = Verdict::kOtherGoal;
    return;
  }
  if (c.teammates.empty() || c.teammates.size() > static_cast<std::size_t>(kMaxTeammates)) {
    e.verdict = Verdict::kInvalidCase;
    return;
  }
  if (problem.teammates.size() > static_cast<std::size_t>(kMaxTeammates)) {
    e.verdict = Verdict::kInvalidProblem;
    return;
  }
  e.ball_similarity = BallSimilarity(problem, c);
  e.band = SimilarityBand(e.ball_similarity, params);
  if (!(e.ball_similarity > params.thr_ball)) {
    e.verdict = Verdict::kBallOutOfScope;
    return;
  }
  if (c.teammates.size() > problem.teammates.size()) {
    e.verdict = Verdict::kTooFewTeammates;
    return;
  }
  e.correspondence = FindCorrespondence(problem, c, params.cost, params.thr_cost_m);
  if (!e.correspondence.feasible) {
    e.verdict = Verdict::kTooFar;
    return;
  }
  const CaseBallPath path =
      BuildBallPath(problem, c,
                    std::span<const Vec2>(e.correspondence.adapted_F.data(),
                                          static_cast<std::size_t>(e.correspondence.count)),
                    params);
  if (params.free_path) e.path = CheckFreePath(path, problem.opponents, params.thr_trajectory);
  if (!e.path.free) {
    e.verdict = Verdict::kPathBlocked;
    return;
  }
  e.conditions =
      params.opponent_similarity ? OpponentSimilarity(problem, c, params.thr_opponent) : 0;
  e.verdict = Verdict::kCandidate;
}

}  // namespace

CaseEvaluation EvaluateCase(const Problem& problem, const Case& c, int index,
                            const RetrievalParams& params) {
  CaseEvaluation e;
  Evaluate(problem, c, index, params, &e);
  return e;
}

bool RanksBefore(const CaseEvaluation& a, const CaseEvaluation& b, const RetrievalParams& params) {
  for (RankCriterion criterion : params.order) {
    switch (criterion) {
      case RankCriterion::kConditions:
        if (a.conditions != b.conditions) return a.conditions > b.conditions;
        break;
      case RankCriterion::kTeammates:
        if (a.teammates != b.teammates) return a.teammates > b.teammates;
        break;
      case RankCriterion::kBandThenCost:
        if (a.band != b.band) return a.band < b.band;
        if (a.correspondence.cost < b.correspondence.cost) return true;
        if (b.correspondence.cost < a.correspondence.cost) return false;
        break;
    }
  }
  return a.case_index < b.case_index;
}

namespace {

void Reset(RetrievalResult* out, bool all_cases) {
  out->retrieved.reset();
  out->evaluations.clear();
  out->all_cases = all_cases;
  out->ranking.clear();
  out->ball_path = CaseBallPath{};
}

// Algorithm 2 after the evaluations are in: sort the candidates (ranking holds their case
// indices, `slot` maps a case index to the position of its evaluation), store their ranks,
// build the retrieved case's ball path.
template <typename Slot>
void Rank(std::span<const Case> cases, const Problem& problem, const RetrievalParams& params,
          const Slot& slot, RetrievalResult* out) {
  auto& ev = out->evaluations;
  std::sort(out->ranking.begin(), out->ranking.end(),
            [&](int a, int b) { return RanksBefore(ev[slot(a)], ev[slot(b)], params); });
  for (std::size_t r = 0; r < out->ranking.size(); ++r) {
    ev[slot(out->ranking[r])].rank = static_cast<int>(r);
  }
  if (!out->ranking.empty()) {
    const int best = out->ranking.front();
    out->retrieved = best;
    const Correspondence& k = ev[slot(best)].correspondence;
    out->ball_path = BuildBallPath(
        problem, cases[static_cast<std::size_t>(best)],
        std::span<const Vec2>(k.adapted_F.data(), static_cast<std::size_t>(k.count)), params);
  }
}

}  // namespace

const CaseEvaluation* RetrievalResult::Find(int case_index) const {
  if (case_index < 0) return nullptr;
  if (all_cases) {
    return static_cast<std::size_t>(case_index) < evaluations.size()
               ? &evaluations[static_cast<std::size_t>(case_index)]
               : nullptr;
  }
  const auto it = std::lower_bound(evaluations.begin(), evaluations.end(), case_index,
                                   [](const CaseEvaluation& e, int i) { return e.case_index < i; });
  return it != evaluations.end() && it->case_index == case_index ? &*it : nullptr;
}

void Retrieve(std::span<const Case> cases, const Problem& problem, const RetrievalParams& params,
              RetrievalResult* out) {
  Reset(out, true);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    Evaluate(problem, cases[i], static_cast<int>(i), params, &out->evaluations.emplace_back());
    if (out->evaluations.back().verdict == Verdict::kCandidate) {
      out->ranking.push_back(static_cast<int>(i));
    }
  }
  Rank(
      cases, problem, params, [](int i) { return static_cast<std::size_t>(i); }, out);
}

void Retrieve(std::span<const Case> cases, const BallScopeIndex& index, const Problem& problem,
              const RetrievalParams& params, RetrievalResult* out) {
  if (index.size() != cases.size() || index.thr_ball() != params.thr_ball) {
    throw InputError(
        "Retrieve: the ball-scope index was built for " + std::to_string(index.size()) +
        " cases and thr_b " + FormatNumber(index.thr_ball()) + ", not for these " +
        std::to_string(cases.size()) + " cases and thr_b " + FormatNumber(params.thr_ball));
  }
  Reset(out, false);
  for (const std::uint32_t i : index.Query(problem.p_F_ball)) {
    Evaluate(problem, cases[i], static_cast<int>(i), params, &out->evaluations.emplace_back());
    if (out->evaluations.back().verdict == Verdict::kCandidate) {
      out->ranking.push_back(static_cast<int>(i));
    }
  }
  const auto& ev = out->evaluations;
  Rank(
      cases, problem, params,
      [&ev](int i) {
        return static_cast<std::size_t>(
            std::lower_bound(ev.begin(), ev.end(), i,
                             [](const CaseEvaluation& e, int k) { return e.case_index < k; }) -
            ev.begin());
      },
      out);
}

RetrievalResult Retrieve(std::span<const Case> cases, const BallScopeIndex& index,
                         const Problem& problem, const RetrievalParams& params) {
  RetrievalResult result;
  Retrieve(cases, index, problem, params, &result);
  return result;
}

CaseEvaluation EvaluationOf(const RetrievalResult& r, std::span<const Case> cases,
                            const Problem& problem, const RetrievalParams& params, int case_index) {
  if (const CaseEvaluation* e = r.Find(case_index)) return *e;
  if (case_index < 0 || static_cast<std::size_t>(case_index) >= cases.size()) {
    throw InputError("EvaluationOf: case index " + std::to_string(case_index) + " out of range");
  }
  return EvaluateCase(problem, cases[static_cast<std::size_t>(case_index)], case_index, params);
}

RetrievalResult Retrieve(std::span<const Case> cases, const Problem& problem,
                         const RetrievalParams& params) {
  RetrievalResult result;
  result.evaluations.reserve(cases.size());
  result.ranking.reserve(cases.size());
  Retrieve(cases, problem, params, &result);
  return result;
}

std::string Explain(const CaseEvaluation& e, const Case& c, const Problem& problem,
                    const RetrievalParams& params) {
  const std::string head = "case " + c.name + ": ";
  switch (e.verdict) {
    case Verdict::kCandidate: {
      std::string s = head + "candidate, rank " + std::to_string(e.rank) + ": conditions " +
                      std::to_string(e.conditions) + ", teammates " + std::to_string(e.teammates) +
                      ", similarity " + Milli(e.ball_similarity) + " (band " +
                      kBandNames[std::clamp(e.band, 0, 3)] + ")";
      s += ", cost " + Milli(e.correspondence.cost.primary) + " m (" +
           std::string(CostFunctionName(params.cost)) + ")";
      return s;
    }
    case Verdict::kOtherGoal:
      return head + "for the other defending goal (" + std::string(DefendingGoalName(c.defending)) +
             ")";
    case Verdict::kInvalidCase:
      return head + "invalid: " + std::to_string(e.teammates) + " teammates (1-" +
             std::to_string(kMaxTeammates) + " allowed)";
    case Verdict::kInvalidProblem:
      return head + "invalid problem: " + std::to_string(problem.teammates.size()) +
             " teammates (1-" + std::to_string(kMaxTeammates) + " allowed)";
    case Verdict::kBallOutOfScope:
      return head + "ball out of scope: similarity " + Milli(e.ball_similarity) + " <= thr_b " +
             Milli(params.thr_ball);
    case Verdict::kTooFewTeammates:
      return head + "too few teammates: the case needs " + std::to_string(e.teammates) +
             ", the problem has " + std::to_string(problem.teammates.size());
    case Verdict::kTooFar: {
      const Correspondence& k = e.correspondence;
      const int case_id = c.teammates[static_cast<std::size_t>(k.far_case_index)].id;
      const int problem_id = problem.teammates[static_cast<std::size_t>(k.far_problem_index)].id;
      return head + "too far: robot " + std::to_string(problem_id) + " would walk " +
             Milli(k.far_distance_m) + " m to case teammate " + std::to_string(case_id) +
             "'s adapted position " +
             Point(k.adapted_F[static_cast<std::size_t>(k.far_case_index)]) + " > thr_c " +
             Milli(params.thr_cost_m) + " m in the best matching";
    }
    case Verdict::kPathBlocked: {
      const CaseBallPath path =
          BuildBallPath(problem, c,
                        std::span<const Vec2>(e.correspondence.adapted_F.data(),
                                              static_cast<std::size_t>(e.correspondence.count)),
                        params);
      const FuzzyTrajectory& t = path.trajectories[static_cast<std::size_t>(e.path.trajectory)];
      std::string what = std::string(ActionTypeName(t.action)) + " by teammate " +
                         std::to_string(c.teammates[static_cast<std::size_t>(t.kicker)].id);
      if (t.receiver >= 0) {
        what +=
            " to teammate " + std::to_string(c.teammates[static_cast<std::size_t>(t.receiver)].id);
      }
      return head + "path blocked: opponent " + std::to_string(e.path.opponent) + " at " +
             Point(problem.opponents[static_cast<std::size_t>(e.path.opponent)]) +
             " on trajectory " + std::to_string(e.path.trajectory) + " (" + what + " from " +
             Point(t.start_F) + " to " + Point(t.end_F) + "), mu " + Milli(e.path.membership) +
             " > thr_t " + Milli(params.thr_trajectory);
    }
  }
  return head + "?";
}

}  // namespace foresight
