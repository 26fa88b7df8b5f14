#include "experiments/passing_variants.h"

#include <set>

#include "common/error.h"
#include "common/json_reader.h"
#include "common/checks.h"
#include "models/model_paths.h"

namespace foresight {

namespace {

void ReadRetrieval(const JsonObject& o, PassingVariant& v) {
  o.RejectUnknownKeys({"cost", "order", "free_path", "opponent_similarity"});
  if (o.Has("cost")) {
    const std::string name = o.String("cost");
    v.cost = ParseCostFunction(name);
    if (!v.cost) o.Fail("cost", "must be one of " + CostFunctionNames() + ", got " + QuoteJson(name));
  }
  if (o.Has("order")) {
    const std::vector<std::string> names = o.StringArray("order");
    std::array<RankCriterion, 3> order{};
    std::set<std::string> seen(names.begin(), names.end());
    if (names.size() != order.size() || seen.size() != order.size()) {
      o.Fail("order", "must list " + RankCriterionNames() + " once each");
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      const auto c = ParseRankCriterion(names[i]);
      if (!c) o.Fail("order", "items must be " + RankCriterionNames() + ", got " + QuoteJson(names[i]));
      order[i] = *c;
    }
    v.order = order;
  }
  if (o.Has("free_path")) v.free_path = o.BoolOr("free_path", true);
  if (o.Has("opponent_similarity")) v.opponent_similarity = o.BoolOr("opponent_similarity", true);
}

void ReadTeam(const JsonObject& o, PassingVariant& v) {
  o.RejectUnknownKeys({"positioning", "retrievers", "pass_timing", "ball_race", "kick_race"});
  if (o.Has("positioning")) {
    const std::string name = o.String("positioning");
    v.positioning = ParsePositioning(name);
    if (!v.positioning) {
      o.Fail("positioning", "must be \"dependent\" or \"independent\", got " + QuoteJson(name));
    }
  }
  if (o.Has("retrievers")) {
    v.retrievers = o.Integer("retrievers");
    if (*v.retrievers < 1 || *v.retrievers > 4) {
      o.Fail("retrievers", "must be 1-4, got " + std::to_string(*v.retrievers));
    }
  }
  if (o.Has("pass_timing")) v.pass_timing = o.BoolOr("pass_timing", false);
  if (o.Has("ball_race")) v.ball_race = o.BoolOr("ball_race", true);
  if (o.Has("kick_race")) v.kick_race = o.BoolOr("kick_race", true);
}

void ReadSimulation(const JsonObject& o, PassingVariant& v) {
  o.RejectUnknownKeys({"message_loss_rate", "ball_noise_sigma_m", "robot_noise_sigma_m"});
  const auto read = [&o](const char* key, double hi, std::optional<double>& out) {
    if (!o.Has(key)) return;
    out = o.Number(key);
    if (!(*out >= 0.0 && *out <= hi)) {
      o.Fail(key, "must be within [0, " + FormatNumber(hi) + "], got " + FormatNumber(*out));
    }
  };
  read("message_loss_rate", 1.0, v.message_loss_rate);
  read("ball_noise_sigma_m", 1.0, v.ball_noise_sigma_m);
  read("robot_noise_sigma_m", 1.0, v.robot_noise_sigma_m);
}

void ReadCases(const JsonObject& o, PassingVariant& v) {
  o.RejectUnknownKeys({"mirror_y"});
  if (o.Has("mirror_y")) v.mirror_y = o.BoolOr("mirror_y", true);
}

}  // namespace

PassingSetup PassingVariant::Apply(const PassingSetup& base) const {
  PassingSetup s = base;
  if (cost) s.retrieval.cost = *cost;
  if (order) s.retrieval.order = *order;
  if (free_path) s.retrieval.free_path = *free_path;
  if (opponent_similarity) s.retrieval.opponent_similarity = *opponent_similarity;
  if (positioning) s.cbr.positioning = *positioning;
  if (retrievers) s.cbr.retrievers = *retrievers;
  if (pass_timing) s.cbr.pass_timing.enabled = *pass_timing;
  if (ball_race) s.cbr.ball_race = *ball_race;
  if (kick_race) s.cbr.kick_race = *kick_race;
  if (message_loss_rate) s.sim.message_loss_rate = *message_loss_rate;
  if (ball_noise_sigma_m) s.sim.ball_noise_sigma_m = *ball_noise_sigma_m;
  if (robot_noise_sigma_m) s.sim.robot_noise_sigma_m = *robot_noise_sigma_m;
  if (mirror_y && !*mirror_y) s.case_base.cases = s.case_base.cases.WithoutMirrorY();
  s.cbr.Validate();
  s.sim.Validate();
  return s;
}

std::vector<PassingVariant> LoadPassingVariants(const std::string& reference,
                                                const std::filesystem::path& models_dir) {
  const std::filesystem::path file =
      ResolveModelFile(reference, DataFolder::kExperiments, ".", models_dir);
  const JsonDocument doc = JsonDocument::Load(file);
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"variants"});  // "notes" is always allowed
  std::vector<PassingVariant> variants;
  std::set<std::string> names;
  for (const JsonObject& item : root.ObjectArray("variants")) {
    item.RejectUnknownKeys({"name", "retrieval", "team", "simulation", "cases"});  // and "notes"
    PassingVariant v;
    v.name = item.String("name");
    if (v.name.empty() || !names.insert(v.name).second) {
      item.Fail("name", "must be a unique, non-empty name, got " + QuoteJson(v.name));
    }
    v.notes = item.StringOr("notes", "");
    if (item.Has("retrieval")) ReadRetrieval(item.Object("retrieval"), v);
    if (item.Has("team")) ReadTeam(item.Object("team"), v);
    if (item.Has("simulation")) ReadSimulation(item.Object("simulation"), v);
    if (item.Has("cases")) ReadCases(item.Object("cases"), v);
    variants.push_back(std::move(v));
  }
  if (variants.empty()) root.Fail("variants", "must list at least one variant");
  return variants;
}

}  // namespace foresight
