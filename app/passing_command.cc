#include "app/passing_command.h"

#include <chrono>
#include <optional>

#include "app/cli_values.h"
#include "app/experiment_output.h"
#include "app/passing_view.h"
#include "app/shard_output.h"
#include "experiments/passing_comparison.h"
#include "experiments/passing_example.h"
#include "experiments/passing_figures.h"
#include "experiments/passing_replay.h"
#include "experiments/passing_report.h"
#include "experiments/passing_scorecard.h"
#include "experiments/passing_scorecard_report.h"
#include "experiments/passing_shard.h"
#include "models/model_paths.h"

namespace foresight {

namespace {

// One team's report files, named PREFIX.json, PREFIX_trials.csv, ...
void AddPassingFiles(const std::filesystem::path& dir, const std::string& prefix,
                     const PassingRun& run, const PassingOptions& o,
                     const std::filesystem::path& models, ReportFiles& files) {
  files.push_back({dir / (prefix + ".json"), PassingJson(run).dump(2) + "\n"});
  files.push_back({dir / (prefix + "_trials.csv"), PassingTrialsCsv(run)});
  files.push_back({dir / (prefix + "_events.csv"), PassingEventsCsv(run)});
  files.push_back({dir / (prefix + "_outcomes.svg"), PassingOutcomesSvg(run)});
  files.push_back({dir / (prefix + "_possession.svg"), PassingPossessionSvg(run)});
  files.push_back({dir / (prefix + "_time.svg"), PassingTimeSvg(run)});
  for (std::size_t i = 0; i < run.result.scenarios.size(); ++i) {
    const std::string& name = run.result.scenarios[i].name;
    files.push_back({dir / (prefix + "_example_" + name + ".svg"), PassingExampleSvg(run, i)});
    files.push_back({dir / (prefix + "_replay_" + name + ".html"), PassingReplayHtml(run, i)});
    files.push_back(
        {dir / (prefix + "_view_" + name + ".html"), PassingViewHtml(run, i, o, models)});
  }
}

// The played trials of every team of the run (setup.teams' order) and each team's run time.
struct PassingTrials {
  std::vector<PassingResult> results;
  std::vector<double> run_times_s;
};

// The paper's tables for the scorecard when both teams play (loaded before the trials, so a bad
// file fails at once).
std::optional<PaperTables> LoadScorecardTables(const PassingSetup& setup,
                                               const std::filesystem::path& models) {
  if (setup.teams.size() < 2) return std::nullopt;
  return LoadPaperTables(setup.params.paper_tables, models);
}

const PassingRun& RunOf(const std::vector<PassingRun>& runs, const std::string& team) {
  for (const PassingRun& run : runs) {
    if (run.team == team) return run;
  }
  return runs.front();  // unreachable: both teams play when there is a scorecard
}

// The scorecard of the two teams against the paper: JSON, text and HTML.
void AddScorecardFiles(const std::filesystem::path& dir, const PaperTables& paper,
                       const std::vector<PassingRun>& runs, const std::filesystem::path& models,
                       ReportFiles& files, std::string& text) {
  const PassingScorecard card = BuildPassingScorecard(
      paper, DisplayPath(paper.file, models), RunOf(runs, "cbr"), RunOf(runs, "reactive"));
  const std::string card_text = PassingScorecardText(card);
  files.push_back({dir / "scorecard.json", PassingScorecardJson(card).dump(2) + "\n"});
  files.push_back({dir / "scorecard.txt", card_text});
  files.push_back({dir / "scorecard.html", PassingScorecardHtml(card)});
  text += card_text;
}

// Every team's report and, for two teams, their paired comparison and the scorecard against the
// paper, written to --out.
void WritePassingReport(OutputSet& outputs, const PassingOptions& o, const PassingInputs& in,
                        PassingTrials trials, const std::optional<PaperTables>& paper,
                        const std::filesystem::path& models) {
  const PassingSetup& setup = in.setup;
  const std::uint64_t seed = ParseSeed(o.seed);
  const std::filesystem::path dir(o.out_dir);
  const bool both = setup.teams.size() > 1;
  ReportFiles files;
  std::string text;
  std::vector<PassingRun> runs;
  for (std::size_t t = 0; t < setup.teams.size(); ++t) {
    const std::string& team = setup.teams[t];
    PassingRun run;
    run.provenance = PassingProvenance(
        o, in, team,
        DisplayPath(team == "cbr" ? setup.cbr.file : setup.reactive.file, models), seed, models);
    run.setup = &setup;
    run.team = team;
    run.result = std::move(trials.results[t]);
    run.summaries = SummarisePassing(run.result, setup.params.confidence);
    run.provenance.run_time_s = trials.run_times_s[t];
    AddPassingFiles(dir, both ? "passing_" + team : "passing", run, o, models, files);
    text += PassingText(run);
    runs.push_back(std::move(run));
  }
  if (both) {
    const std::vector<std::string> opponents = setup.config.OpponentNames();
    const PassingComparison comparison =
        ComparePassing(setup.teams[0], runs[0].result, setup.teams[1], runs[1].result, opponents,
                       setup.params.confidence);
    files.push_back({dir / "passing_teams.svg", PassingTeamsSvg(runs[0], runs[1])});
    files.push_back({dir / "passing_comparison.json",
                     PassingComparisonJson(comparison).dump(2) + "\n"});
    text += PassingComparisonText(comparison);
    if (paper) AddScorecardFiles(dir, *paper, runs, models, files, text);
  }
  WriteReport(outputs, o.out_dir, files, text,
              both ? "passing_" + setup.teams[0] + "_outcomes.svg" : "passing_outcomes.svg");
}

// The flags that decide a passing run's results, as a shard records them.
nlohmann::ordered_json Settings(const PassingOptions& o) {
  nlohmann::ordered_json settings = PassingSettings(o);
  settings["--team"] = o.team;
  return settings;
}

}  // namespace

void AddPassingCommand(CLI::App& experiment, PassingOptions& o) {
  CLI::App* cmd = experiment.add_subcommand(
      "passing", "2-vs-2 attacks against DG or 2D opponents (Ros et al. 2009, sec. 5.2)");
  AddPassingRunOptions(*cmd, o);
  cmd->add_option("--team", o.team, "Attacking team: " + PassingTeamNames())
      ->capture_default_str();
}

int RunPassingCommand(const PassingOptions& o, const std::filesystem::path& models) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t seed = ParseSeed(o.seed);
  const int threads = ParseCount("--threads", o.threads, 0, 1024);
  const std::optional<Shard> shard = ParseShardFlag(o.shard);
  const PassingInputs in = LoadPassingInputs(o, o.team, models);
  const PassingSetup& setup = in.setup;
  const std::optional<PaperTables> paper = LoadScorecardTables(setup, models);
  OutputSet outputs = ReportFolderOutput(o.out_dir);  // before the work, not after
  PassingTrials trials;
  for (std::size_t t = 0; t < setup.teams.size(); ++t) {
    const std::string& team = setup.teams[t];
    trials.results.push_back(
        RunPassing(setup, team, *in.executor, seed, threads,
                   CommandProgress("passing " + team, "trials"),
                   TeamShard(setup, static_cast<int>(t), shard.value_or(Shard{}))));
    trials.run_times_s.push_back(SecondsSince(start));
  }
  if (shard) {
    const ShardHeader header{kPassingCommand, FORESIGHT_VERSION, *shard, Settings(o),
                             PassingItems(setup, static_cast<int>(setup.teams.size()))};
    WriteShardFolder(outputs, o.out_dir, header,
                     PassingShardResults(setup, setup.teams, trials.results, *shard), start,
                     "trials");
    return 0;
  }
  WritePassingReport(outputs, o, in, std::move(trials), paper, models);
  return 0;
}

int MergePassingCommand(const std::vector<ShardPart>& parts, OutputSet& outputs,
                        const std::string& out_dir, const std::filesystem::path& models) {
  PassingOptions o = PassingOptionsOf(parts.front(), out_dir);
  o.team = SettingString(parts.front(), "--team");
  const PassingInputs in = LoadPassingInputs(o, o.team, models);
  const PassingSetup& setup = in.setup;
  RequireShardItems(parts.front(), PassingItems(setup, static_cast<int>(setup.teams.size())),
                    "trials");
  const std::optional<PaperTables> paper = LoadScorecardTables(setup, models);
  PassingTrials trials;
  trials.results = MergePassingShards(setup, setup.teams, parts);
  trials.run_times_s.assign(setup.teams.size(), ShardsRunTime(parts));
  WritePassingReport(outputs, o, in, std::move(trials), paper, models);
  return 0;
}

}  // namespace foresight
