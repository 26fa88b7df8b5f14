#include "app/cbr_retrieve_output.h"

#include <array>
#include <cmath>
#include <string>

#include "cbr/similarity.h"
#include "common/one_line.h"
#include "models/model_paths.h"
#include "report/report_format.h"

namespace foresight {

namespace {

constexpr std::array<const char*, 4> kBands{"H", "h", "l", "L"};
constexpr std::array<Verdict, 7> kRejections{
    Verdict::kOtherGoal,       Verdict::kInvalidCase, Verdict::kInvalidProblem,
    Verdict::kBallOutOfScope,  Verdict::kTooFewTeammates, Verdict::kTooFar,
    Verdict::kPathBlocked};

const char* BandName(int band) {
  return kBands[static_cast<std::size_t>(std::clamp(band, 0, 3))];
}

// Numbers in the JSON: rounded to 0.1 mm (or 1e-6 for similarities) so the bytes do not depend
// on the last bit of a sum; dividing by the power of ten gives the shortest form ("1.45").
double Round(double value, double per_unit) {
  return std::round(value * per_unit) / per_unit;
}
double Metres(double value) {
  return Round(value, 1e4);
}
double Unit(double value) {
  return Round(value, 1e6);
}

nlohmann::ordered_json Point(const Vec2& p) {
  return {{"x_m", Metres(p.x())}, {"y_m", Metres(p.y())}};
}

std::string Xy(const Vec2& p) {
  return Format("(%.2f, %.2f)", p.x(), p.y());
}

// The problem robot (id) that plays case teammate `case_index` of the retrieved case.
int RobotId(const CbrRetrieveRun& run, int case_index) {
  if (case_index < 0) return 0;
  const CaseEvaluation& e = *run.result.Best();
  const int p = e.correspondence.problem_index[static_cast<std::size_t>(case_index)];
  return run.problem.teammates[static_cast<std::size_t>(p)].id;
}

std::string TrajectoryText(const CbrRetrieveRun& run, const FuzzyTrajectory& t) {
  std::string who = t.action == ActionType::kPass
                        ? Format("pass robot %d -> robot %d", RobotId(run, t.kicker),
                                 RobotId(run, t.receiver))
                        : Format("kick by robot %d", RobotId(run, t.kicker));
  std::string text = who + " from " + Xy(t.start_F) + " to " + Xy(t.end_F) +
                     Format(", %.2f m, exp(-1) half-widths %.2f -> %.2f m", t.length_m,
                            t.r_start_m, t.r_end_m);
  if (t.knee_m > 0.0) text += Format(" at its target %.2f m out", t.knee_m);
  return text;
}

int Rejected(const CbrRetrieveRun& run, Verdict verdict) {
  int n = 0;
  for (const CaseEvaluation& e : run.result.evaluations) n += e.verdict == verdict;
  return n;
}

}  // namespace

std::vector<MetCondition> MetConditions(const Problem& problem, const Case& c, double thr_opp) {
  std::vector<MetCondition> met;
  for (std::size_t k = 0; k < c.opponents.size(); ++k) {
    for (std::size_t j = 0; j < problem.opponents.size(); ++j) {
      const double omega = OpponentScopeMembership(problem, c, c.opponents[k], problem.opponents[j]);
      if (omega > thr_opp) {
        met.push_back({static_cast<int>(k), static_cast<int>(j), omega});
        break;
      }
    }
  }
  return met;
}

std::string CbrRetrieveText(const CbrRetrieveRun& run, bool verbose) {
  const Problem& p = run.problem;
  std::string s;
  s += "problem: " + run.problem_file.string() + " (defending " +
       std::string(DefendingGoalName(p.defending)) + ", ball " + Xy(p.p_F_ball) +
       Format(", teammates %zu, opponents %zu)\n", p.teammates.size(), p.opponents.size());
  s += "case base: " + DisplayPath(run.case_base_path, run.models_dir) +
       Format(" (%zu cases for %s)\n", run.cases.size(),
              std::string(DefendingGoalName(p.defending)).c_str());
  const Case* c = run.Retrieved();
  if (c == nullptr) {
    s += "retrieved: none (no case fits the problem)\n";
  } else {
    const CaseEvaluation& e = *run.result.Best();
    s += "retrieved: " + OneLine(c->name) + " (" +
         std::string(CaseTransformName(c->transform)) + " of " + OneLine(c->source) + ")\n";
    s += "  notes: " + OneLine(c->notes) + "\n";
    s += Format("  cost %.3f m (%s), ball similarity %.3f (band %s), conditions %d of %zu, "
                "teammates %d\n",
                e.correspondence.cost.primary, std::string(CostFunctionName(run.params.cost)).c_str(),
                e.ball_similarity, BandName(e.band), e.conditions, c->opponents.size(),
                e.teammates);
    s += "  correspondence (problem robot -> case teammate: adapted position, walk):\n";
    for (int i = 0; i < e.correspondence.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const ProblemTeammate& robot = p.teammates[static_cast<std::size_t>(
          e.correspondence.problem_index[k])];
      s += Format("    robot %d -> teammate %d: ", robot.id, c->teammates[k].id) + Xy(robot.pose.p_F) +
           " to " + Xy(e.correspondence.adapted_F[k]) +
           Format(", walks %.2f m\n", e.correspondence.distance_m[k]);
    }
    const std::vector<MetCondition> met = MetConditions(p, *c, run.params.thr_opponent);
    s += "  conditions met:";
    if (met.empty()) s += " none";
    s += "\n";
    for (const MetCondition& m : met) {
      s += Format("    case opponent %d scope holds problem opponent %d at ",
                  c->opponents[static_cast<std::size_t>(m.case_opponent)].id, m.problem_opponent) +
           Xy(p.opponents[static_cast<std::size_t>(m.problem_opponent)]) +
           Format(" (Omega %.3f)\n", m.membership);
    }
    s += "  ball path:";
    if (run.result.ball_path.count == 0) s += " none (the ball does not move)";
    s += "\n";
    for (int t = 0; t < run.result.ball_path.count; ++t) {
      s += Format("    %d: ", t) +
           TrajectoryText(run, run.result.ball_path.trajectories[static_cast<std::size_t>(t)]) +
           "\n";
    }
  }
  s += Format("candidates: %zu\n", run.result.ranking.size());
  if (!run.result.ranking.empty()) {
    s += Format("  %4s  %-28s %4s %5s %5s %8s %6s\n", "rank", "case", "band", "cond", "team",
                "cost_m", "sim");
  }
  for (std::size_t r = 0; r < run.result.ranking.size(); ++r) {
    const CaseEvaluation& e = run.result.evaluations[static_cast<std::size_t>(run.result.ranking[r])];
    const Case& cc = run.cases[static_cast<std::size_t>(e.case_index)];
    s += Format("  %4zu  %-28s %4s %5d %5d %8.3f %6.3f\n", r + 1, OneLine(cc.name).c_str(), BandName(e.band),
                e.conditions, e.teammates, e.correspondence.cost.primary, e.ball_similarity);
  }
  s += "rejected:";
  int total = 0;
  for (const Verdict v : kRejections) {
    const int n = Rejected(run, v);
    total += n;
    if (n > 0) s += Format(" %s %d", std::string(VerdictName(v)).c_str(), n);
  }
  if (total == 0) s += " none";
  s += "\n";
  if (verbose) {
    for (const CaseEvaluation& e : run.result.evaluations) {
      if (e.verdict == Verdict::kCandidate) continue;
      s += "  " +
           Explain(e, run.cases[static_cast<std::size_t>(e.case_index)], p, run.params) + "\n";
    }
  } else if (total > 0) {
    s += "  (--verbose or --json: why each case was rejected)\n";
  }
  return s;
}

nlohmann::ordered_json CbrRetrieveJson(const CbrRetrieveRun& run) {
  const Problem& p = run.problem;
  nlohmann::ordered_json j;
  j["foresight_version"] = FORESIGHT_VERSION;
  j["command"] = "cbr retrieve";
  nlohmann::ordered_json problem;
  problem["file"] = run.problem_file.string();
  problem["defending"] = DefendingGoalName(p.defending);
  problem["ball"] = Point(p.p_F_ball);
  problem["teammates"] = nlohmann::ordered_json::array();
  for (const ProblemTeammate& t : p.teammates) {
    problem["teammates"].push_back({{"id", t.id},
                                    {"x_m", Metres(t.pose.p_F.x())},
                                    {"y_m", Metres(t.pose.p_F.y())},
                                    {"theta_deg", Round(t.pose.theta_rad * kRadToDeg, 1e3)}});
  }
  problem["opponents"] = nlohmann::ordered_json::array();
  for (const Vec2& o : p.opponents) problem["opponents"].push_back(Point(o));
  j["problem"] = problem;
  j["case_base"] = DisplayPath(run.case_base_path, run.models_dir);
  j["params"] = DisplayPath(run.params_file, run.models_dir);
  j["cases"] = run.cases.size();

  const Case* c = run.Retrieved();
  if (c == nullptr) {
    j["retrieved"] = nullptr;
  } else {
    const CaseEvaluation& e = *run.result.Best();
    nlohmann::ordered_json r;
    r["name"] = c->name;
    r["source"] = c->source;
    r["transform"] = CaseTransformName(c->transform);
    r["notes"] = c->notes;
    r["band"] = BandName(e.band);
    r["ball_similarity"] = Unit(e.ball_similarity);
    r["cost"] = CostFunctionName(run.params.cost);
    r["cost_m"] = Metres(e.correspondence.cost.primary);
    r["sum_m"] = Metres(e.correspondence.sum_m);
    r["max_m"] = Metres(e.correspondence.max_m);
    r["teammates"] = e.teammates;
    r["conditions"] = e.conditions;
    r["correspondence"] = nlohmann::ordered_json::array();
    for (int i = 0; i < e.correspondence.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const ProblemTeammate& robot =
          p.teammates[static_cast<std::size_t>(e.correspondence.problem_index[k])];
      r["correspondence"].push_back({{"robot", robot.id},
                                     {"case_teammate", c->teammates[k].id},
                                     {"from", Point(robot.pose.p_F)},
                                     {"to", Point(e.correspondence.adapted_F[k])},
                                     {"walk_m", Metres(e.correspondence.distance_m[k])}});
    }
    r["conditions_met"] = nlohmann::ordered_json::array();
    for (const MetCondition& m : MetConditions(p, *c, run.params.thr_opponent)) {
      r["conditions_met"].push_back(
          {{"case_opponent", c->opponents[static_cast<std::size_t>(m.case_opponent)].id},
           {"problem_opponent", m.problem_opponent},
           {"membership", Unit(m.membership)}});
    }
    r["ball_path"] = nlohmann::ordered_json::array();
    for (const FuzzyTrajectory& t : run.result.ball_path.View()) {
      nlohmann::ordered_json tj;
      tj["action"] = ActionTypeName(t.action);
      tj["kicker"] = RobotId(run, t.kicker);
      tj["receiver"] = t.action == ActionType::kPass ? nlohmann::ordered_json(RobotId(run, t.receiver))
                                                     : nlohmann::ordered_json(nullptr);
      tj["start"] = Point(t.start_F);
      tj["end"] = Point(t.end_F);
      tj["length_m"] = Metres(t.length_m);
      tj["r_start_m"] = Metres(t.r_start_m);
      tj["r_end_m"] = Metres(t.r_end_m);
      tj["knee_m"] = Metres(t.knee_m);  // 0: rho grows over the whole length
      r["ball_path"].push_back(tj);
    }
    j["retrieved"] = r;
  }
  j["candidates"] = nlohmann::ordered_json::array();
  for (std::size_t r = 0; r < run.result.ranking.size(); ++r) {
    const CaseEvaluation& e = run.result.evaluations[static_cast<std::size_t>(run.result.ranking[r])];
    j["candidates"].push_back({{"rank", r + 1},
                               {"name", run.cases[static_cast<std::size_t>(e.case_index)].name},
                               {"band", BandName(e.band)},
                               {"conditions", e.conditions},
                               {"teammates", e.teammates},
                               {"cost_m", Metres(e.correspondence.cost.primary)},
                               {"ball_similarity", Unit(e.ball_similarity)}});
  }
  nlohmann::ordered_json counts;
  for (const Verdict v : kRejections) counts[std::string(VerdictName(v))] = Rejected(run, v);
  j["rejections"] = counts;
  j["rejected"] = nlohmann::ordered_json::array();
  for (const CaseEvaluation& e : run.result.evaluations) {
    if (e.verdict == Verdict::kCandidate) continue;
    const Case& cc = run.cases[static_cast<std::size_t>(e.case_index)];
    j["rejected"].push_back({{"name", cc.name},
                             {"verdict", VerdictName(e.verdict)},
                             {"explanation", Explain(e, cc, p, run.params)}});
  }
  return j;
}

}  // namespace foresight
