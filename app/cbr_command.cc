#include "app/cbr_command.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "app/cbr_atlas.h"
#include "app/cbr_drawing.h"
#include "app/cbr_retrieve_output.h"
#include "app/cli_values.h"
#include "cbr/case_base.h"
#include "cbr/case_holding.h"
#include "cbr/case_opponents.h"
#include "cbr/case_reach.h"
#include "cbr/own_situation.h"
#include "cbr/problem.h"
#include "cbr/retrieval.h"
#include "cbr/retrieval_params.h"
#include "common/error.h"
#include "common/one_line.h"
#include "experiments/passing.h"
#include "models/model_paths.h"
#include "report/output_set.h"
#include "report/report_format.h"

namespace foresight {

namespace {

namespace fs = std::filesystem;

// The hand-written cases, whichever goal each defends (the mirrors turn, walk and kick as far).
std::vector<Case> HandWritten(const CaseBase& cases) {
  std::vector<Case> out;
  for (const DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
    for (const Case& c : cases.Defending(goal)) {
      if (c.transform == CaseTransform::kOriginal) out.push_back(c);
    }
  }
  return out;
}

fs::path ModelsDir(const std::string& models_dir) {
  return models_dir.empty() ? DefaultModelsDir() : fs::path(models_dir);
}

fs::path CaseBasePath(const CbrOptions& o, const fs::path& models) {
  return o.case_base.empty() ? DefaultCaseBasePath(models) : fs::path(o.case_base);
}

fs::path ParamsPath(const CbrOptions& o, const fs::path& models) {
  return o.params_file.empty() ? models / "cbr" / "retrieval.json" : fs::path(o.params_file);
}

// Names come from the user's case files: their control characters are shown escaped.
void Print(const std::string& text) {
  std::cout << PrintableLines(text) << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
}

// The retrieval parameters of `o` for the case base's robot: kick trajectories end where the
// kicks of `kicks` end (cbr/retrieval_params.h UseKickModelReach).
RetrievalParams ParamsFor(const CbrOptions& o, const fs::path& models, const FieldSpec& field,
                          const KickModel& kicks) {
  RetrievalParams params = LoadRetrievalParams(ParamsPath(o, models), field);
  UseKickModelReach(kicks, &params);
  return params;
}

// The kick model `cbr check --kicks` names, or the case base's; every kick a case plays must be
// in it.
KickModel CheckKicks(const CbrOptions& o, const fs::path& models, const LoadedCaseBase& base) {
  if (o.kicks_file.empty()) return base.rules.kicks;
  const fs::path file = ResolveModelFile(o.kicks_file, DataFolder::kKicks, ".", models);
  KickModel kicks = LoadKickModel(file);
  RequireCaseKicks(base.cases, kicks, file);
  return kicks;
}

// Loads the problem, the case base and the parameters `o` names, retrieves, and hands the run to
// `use` (the run points into the case base, which lives only during the call).
template <class Use>
auto WithRetrieval(const CbrOptions& o, const fs::path& models, Use&& use) {
  const Problem problem = LoadProblem(o.problem_file, models);
  const CbrRetriever retriever = LoadCbrRetriever(o, models);
  return use(RetrieveRun(retriever, problem, o.problem_file), retriever.base);
}

int RunRetrieve(const CbrOptions& o, const fs::path& models) {
  OutputSet outputs;  // located and checked before the work; no output replaces an input
  outputs.AddInput("the input --problem", o.problem_file);
  outputs.AddInput("the input --params", o.params_file);
  outputs.AddFile("--svg", o.svg_file);
  return WithRetrieval(o, models, [&](const CbrRetrieveRun& run, const LoadedCaseBase& base) {
    // Everything is made before anything is written, so a failure leaves no file behind.
    const std::string printed =
        o.json ? CbrRetrieveJson(run).dump(2, ' ', false,
                                           nlohmann::ordered_json::error_handler_t::replace) +
                     "\n"
               : CbrRetrieveText(run, o.verbose);
    if (outputs.Has("--svg")) outputs.Put("--svg", CbrRetrieveSvg(run, base.rules.field));
    outputs.Commit();
    Print(printed);
    return 0;
  });
}

// The overlaps `cbr check` lists before it says how many more there are: enough to see what is
// wrong, short enough to read (a case base of thousands of copies gives one page, not gigabytes).
constexpr std::size_t kMaxListedOverlaps = 20;

// A case whose opponents none of the case base's configurations can field at once describes a
// situation that never arises (cbr/case_opponents.h). Appends its findings to `s`; the count.
int CheckFielding(const LoadedCaseBase& base, const fs::path& models, std::string& s) {
  if (base.configurations.empty()) {
    s += "opponent regions: not checked (the case base names no configurations)\n";
    return 0;
  }
  std::vector<std::vector<FieldBox>> regions;
  std::string names;
  for (const std::string& config : base.configurations) {
    regions.push_back(DefaultOpponentRegions(config, models));
    names += (names.empty() ? "" : ", ") + OneLine(config);
  }
  int unfielded = 0;
  for (const Case& c : HandWritten(base.cases)) {
    const bool fielded = std::any_of(regions.begin(), regions.end(), [&](const auto& r) {
      return FieldsCaseOpponents(c, r);
    });
    if (fielded) continue;
    ++unfielded;
    s += "error: case " + OneLine(c.name) + ": no configuration (" + names +
         ") has its opponents each in a home region of its own: a situation that never arises\n";
  }
  s += Format("cases whose opponents no configuration fields (%s): %d of %zu\n", names.c_str(),
              unfielded, base.cases.HandWrittenCount());
  return unfielded;
}

int RunCheck(const CbrOptions& o, const fs::path& models) {
  const fs::path path = CaseBasePath(o, models);
  const LoadedCaseBase base = LoadCaseBase(path, models);
  const CaseBase& cases = base.cases;
  std::string s = "case base: " + DisplayPath(path, models) + "\n";
  s += Format("hand-written cases: %zu\n", cases.HandWrittenCount());
  s += Format("stored cases: %zu (%zu defending cyan, %zu defending yellow)\n", cases.size(),
              cases.Defending(DefendingGoal::kCyan).size(),
              cases.Defending(DefendingGoal::kYellow).size());
  // The attacking side of the field: x from -0.9 m to the goal line for a team defending cyan,
  // mirrored for yellow (the shipped cases' region, models/cases/README.md).
  const double half = base.rules.field.HalfLength();
  s += Format(
      "ball scope coverage, x in [-0.9, %.1f] m towards the attacked goal: %.1f %% "
      "(cyan), %.1f %% (yellow)\n",
      half, 100.0 * BallScopeCoverage(base, DefendingGoal::kCyan, -0.9, half, 0.05),
      100.0 * BallScopeCoverage(base, DefendingGoal::kYellow, -half, 0.9, 0.05));
  // Overlaps are legal (the copy only costs retrieval time, cbr/case_base.h): warnings only.
  const std::vector<std::string> warnings = CheckCaseBase(cases);
  const std::size_t listed = std::min(warnings.size(), kMaxListedOverlaps);
  for (std::size_t i = 0; i < listed; ++i) s += "warning: " + warnings[i] + "\n";
  if (listed < warnings.size()) {
    s += Format("warning: %zu more groups of identical stored cases not listed\n",
                warnings.size() - listed);
  }
  s += Format("groups of identical stored cases: %zu\n", warnings.size());
  // A case whose own opponent is on its own ball path is dead data: it is never retrieved in the
  // situation it was written for. That fails the check.
  const KickModel kicks = CheckKicks(o, models, base);
  const RetrievalParams params = ParamsFor(o, models, base.rules.field, kicks);
  int blocked = 0;
  for (const DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
    for (const Case& c : cases.Defending(goal)) {
      if (c.transform != CaseTransform::kOriginal) continue;
      const PathCheck own = OwnPathCheck(c, params);
      if (own.free) continue;
      ++blocked;
      const CaseOpponent& opp = c.opponents[static_cast<std::size_t>(own.opponent)];
      s += Format(
          "error: case %s: its own opponent %d at (%.2f, %.2f) is on its ball path "
          "(trajectory %d, mu %.3f > thr_t %.3f): not retrieved where it was written "
          "for\n",
          OneLine(c.name).c_str(), opp.id, opp.p_F.x(), opp.p_F.y(), own.trajectory, own.membership,
          params.thr_trajectory);
    }
  }
  s += Format("cases blocked by their own opponents: %d of %zu\n", blocked,
              cases.HandWrittenCount());
  // A case that asks a kick for more than it carries is a plan the robot cannot play.
  int unplayable = 0;
  if (!params.reach_sigmas) {
    s += "kick reach: not checked (the retrieval parameters set no reach_sigmas)\n";
  } else {
    for (const Case& c : HandWritten(cases)) {
      const std::vector<ReachFinding> findings = CheckCaseReach(c, kicks, params);
      unplayable += findings.empty() ? 0 : 1;
      for (const ReachFinding& f : findings) {
        s += "error: case " + OneLine(c.name) + ": " + DescribeFinding(f, params) + "\n";
      }
    }
    s += Format("cases asking more than their kicks carry (%s, reach at %g sd): %d of %zu\n",
                kicks.robot.c_str(), *params.reach_sigmas, unplayable, cases.HandWrittenCount());
  }
  // A case that holds the ball longer than the rules allow is a plan the robot cannot play.
  const HoldParams hold = DefaultHoldParams(models);
  int overheld = 0;
  for (const Case& c : HandWritten(cases)) {
    const std::vector<HoldingFinding> findings = CheckCaseHolding(c, kicks, params, hold);
    overheld += findings.empty() ? 0 : 1;
    for (const HoldingFinding& f : findings) {
      s += "error: case " + OneLine(c.name) + ": " + DescribeFinding(f, hold) + "\n";
    }
  }
  s += Format("cases holding the ball beyond the holding limit (%.2f s): %d of %zu\n",
              hold.hold_limit_s, overheld, cases.HandWrittenCount());
  const int unfielded = CheckFielding(base, models, s);
  const bool ok = blocked == 0 && unplayable == 0 && overheld == 0 && unfielded == 0;
  s += ok ? "case base OK\n" : "case base FAILED\n";
  Print(s);
  return ok ? 0 : 1;
}

int RunAtlas(const CbrOptions& o, const fs::path& models) {
  OutputSet outputs = ReportFolderOutput(o.out_dir);  // before the work, not after
  CbrAtlasInput input;
  input.case_base_path = CaseBasePath(o, models);
  input.params_file = ParamsPath(o, models);
  input.models_dir = models;
  const LoadedCaseBase base = LoadCaseBase(input.case_base_path, models);
  input.base = &base;
  input.params = ParamsFor(o, models, base.rules.field, base.rules.kicks);
  const std::string html = CbrAtlasHtml(input);
  const fs::path page = fs::path(o.out_dir) / "atlas.html";
  outputs.Put("--out", std::vector<ReportFile>{{page.filename().string(), html}});
  outputs.Commit();
  Print(Format("atlas of %zu hand-written cases (%zu stored): ", base.cases.HandWrittenCount(),
               base.cases.size()) +
        page.string() + "\n");
  return 0;
}

}  // namespace

void AddCbrCommand(CLI::App& app, CbrOptions& options) {
  CLI::App* cbr = app.add_subcommand(
      "cbr", "Case-based coordinated action selection (Ros et al. 2009): retrieve, check, atlas");
  cbr->require_subcommand(1);
  const auto add_base = [&](CLI::App* cmd) {
    cmd->add_option("--case-base", options.case_base,
                    "Case base folder or settings file (default: MODELS/cases)");
  };
  options.retrieve = cbr->add_subcommand("retrieve", "Retrieve the case for a problem file");
  options.retrieve->add_option("--problem", options.problem_file, "Problem file (JSON)")
      ->required();
  add_base(options.retrieve);
  options.retrieve->add_option("--params", options.params_file,
                               "Retrieval parameters (default: MODELS/cbr/retrieval.json)");
  options.retrieve->add_flag("--json", options.json, "Print everything as JSON instead of text");
  options.retrieve->add_flag("--verbose", options.verbose,
                             "Also print why each rejected case was rejected");
  options.retrieve->add_option("--svg", options.svg_file,
                               "Draw the problem, the retrieved case and its ball path");
  options.check = cbr->add_subcommand("check", "Load and validate a case base (CI)");
  add_base(options.check);
  options.check->add_option("--params", options.params_file,
                            "Retrieval parameters for the free-path test (default: "
                            "MODELS/cbr/retrieval.json)");
  options.check->add_option("--kicks", options.kicks_file,
                            "Kick model the cases' kicks are checked against: a name under "
                            "MODELS/kicks or a file (default: the case base's)");
  options.atlas = cbr->add_subcommand("atlas", "Draw every hand-written case on one HTML page");
  options.atlas->add_option("--out", options.out_dir, "Output folder (replaced whole)")->required();
  add_base(options.atlas);
  options.atlas->add_option("--params", options.params_file,
                            "Retrieval parameters for the ball paths (default: "
                            "MODELS/cbr/retrieval.json)");
}

CbrRetriever LoadCbrRetriever(const CbrOptions& options, const std::filesystem::path& models) {
  CbrRetriever r;
  r.case_base_path = CaseBasePath(options, models);
  r.params_file = ParamsPath(options, models);
  r.models_dir = models;
  r.base = LoadCaseBase(r.case_base_path, models);
  r.params = ParamsFor(options, models, r.base.rules.field, r.base.rules.kicks);
  return r;
}

CbrRetrieveRun RetrieveRun(const CbrRetriever& retriever, const Problem& problem,
                           const std::filesystem::path& problem_file) {
  CbrRetrieveRun run;
  run.problem_file = problem_file;
  run.case_base_path = retriever.case_base_path;
  run.params_file = retriever.params_file;
  run.models_dir = retriever.models_dir;
  run.problem = problem;
  run.base = &retriever.base;
  run.params = retriever.params;
  run.cases = retriever.base.cases.Defending(problem.defending);
  run.result = Retrieve(run.cases, run.problem, run.params);
  return run;
}

nlohmann::ordered_json CbrRetrieveJsonFor(const CbrOptions& options,
                                          const std::filesystem::path& models) {
  return WithRetrieval(options, models, [](const CbrRetrieveRun& run, const LoadedCaseBase&) {
    return CbrRetrieveJson(run);
  });
}

int RunCbrCommand(const CbrOptions& options, const std::string& models_dir) {
  const fs::path models = ModelsDir(models_dir);
  if (options.retrieve->parsed()) return RunRetrieve(options, models);
  if (options.check->parsed()) return RunCheck(options, models);
  if (options.atlas->parsed()) return RunAtlas(options, models);
  throw InputError("cbr: a subcommand is required (retrieve, check or atlas)");
}

}  // namespace foresight
