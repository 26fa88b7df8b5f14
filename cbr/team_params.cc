#include "cbr/team_params.h"

#include "common/checks.h"
#include "common/error.h"
#include "common/json_reader.h"
#include "models/model_paths.h"

namespace foresight {

std::string_view PositioningName(Positioning positioning) {
  return positioning == Positioning::kDependent ? "dependent" : "independent";
}

std::optional<Positioning> ParsePositioning(std::string_view name) {
  if (name == "dependent") return Positioning::kDependent;
  if (name == "independent") return Positioning::kIndependent;
  return std::nullopt;
}

void CbrTeamParams::Validate() const {
  RequireInRange("retrievers", retrievers, 1, 4);
  RequireInRange("belief_period_s", belief_period_s, 0.01, 10.0);
  RequireInRange("presence_timeout_s", presence_timeout_s, belief_period_s, 60.0);
  RequireInRange("await_case_timeout_s", await_case_timeout_s, 0.01, 60.0);
  RequireInRange("adapt_timeout_s", adapt_timeout_s, 0.1, 600.0);
  RequireInRange("execute_timeout_s", execute_timeout_s, 0.1, 600.0);
  RequireInRange("wait_end_timeout_s", wait_end_timeout_s, 0.01, 600.0);
  RequireInRange("no_case_retry_s", no_case_retry_s, 0.0, 60.0);
  RequireInRange("arrive_tolerance_m", arrive_tolerance_m, 0.001, 2.0);
  RequireInRange("ball_lost_margin_m", ball_lost_margin_m, 0.0, 1.0);
  RequireInRange("pass_seen_m", pass_seen_m, 0.01, 10.0);
  RequireInRange("keep_close_m", keep_close_m, 0.0, 10.0);
}

CbrTeamParams LoadCbrTeamParams(const std::string& reference,
                                const std::filesystem::path& models_dir) {
  CbrTeamParams p;
  p.file = ResolveModelFile(reference, DataFolder::kCbr, ".", models_dir);
  const JsonDocument doc = JsonDocument::Load(p.file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"notes", "sources", "retrievers", "positioning", "belief_period_s",
                          "presence_timeout_s", "await_case_timeout_s", "adapt_timeout_s",
                          "execute_timeout_s", "wait_end_timeout_s", "no_case_retry_s",
                          "arrive_tolerance_m", "ball_lost_margin_m",
                          "pass_seen_m", "keep_close_m", "pass_timing", "ball_race", "kick_race"});
  RequireSources(root, {"retrievers", "positioning", "belief_period_s", "presence_timeout_s",
                        "await_case_timeout_s", "adapt_timeout_s", "execute_timeout_s",
                        "wait_end_timeout_s", "no_case_retry_s", "arrive_tolerance_m",
                        "ball_lost_margin_m", "pass_seen_m", "keep_close_m",
                        "pass_timing", "ball_race", "kick_race"});
  p.retrievers = root.Integer("retrievers");
  const std::string positioning = root.String("positioning");
  if (auto parsed = ParsePositioning(positioning)) {
    p.positioning = *parsed;
  } else {
    root.Fail("positioning", "must be \"dependent\" or \"independent\", got " +
                                 QuoteJson(positioning));
  }
  p.belief_period_s = root.Number("belief_period_s");
  p.presence_timeout_s = root.Number("presence_timeout_s");
  p.await_case_timeout_s = root.Number("await_case_timeout_s");
  p.adapt_timeout_s = root.Number("adapt_timeout_s");
  p.execute_timeout_s = root.Number("execute_timeout_s");
  p.wait_end_timeout_s = root.Number("wait_end_timeout_s");
  p.no_case_retry_s = root.Number("no_case_retry_s");
  p.arrive_tolerance_m = root.Number("arrive_tolerance_m");
  p.ball_lost_margin_m = root.Number("ball_lost_margin_m");
  p.pass_seen_m = root.Number("pass_seen_m");
  p.keep_close_m = root.Number("keep_close_m");
  p.ball_race = root.Bool("ball_race");
  p.kick_race = root.Bool("kick_race");
  const JsonObject timing = root.Object("pass_timing");
  timing.RejectUnknownKeys({"enabled", "reaction_s", "samples", "time_step_s", "min_success"});
  p.pass_timing.enabled = timing.BoolOr("enabled", false);
  p.pass_timing.reaction_s = timing.Number("reaction_s");
  p.pass_timing.time_step_s = timing.Number("time_step_s");
  p.pass_timing.min_success = timing.Number("min_success");
  const int samples = timing.Integer("samples");
  WithFile(p.file.string(), [&] {
    RequireInRange("pass_timing.samples", samples, 1, 100000);
    RequireInRange("pass_timing.reaction_s", p.pass_timing.reaction_s, 0.0, 60.0);
    RequireInRange("pass_timing.time_step_s", p.pass_timing.time_step_s, 0.001, 1.0);
    RequireInRange("pass_timing.min_success", p.pass_timing.min_success, 0.0, 1.0);
  });
  DrawPassSamples(samples, &p.pass_timing);
  WithFile(p.file.string(), [&] { p.Validate(); });
  return p;
}

}  // namespace foresight
