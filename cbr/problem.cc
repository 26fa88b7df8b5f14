#include "cbr/problem.h"

#include <cmath>
#include <set>
#include <string>

#include "common/checks.h"
#include "common/error.h"
#include "common/json_reader.h"
#include "models/field_spec.h"
#include "models/placement.h"

namespace foresight {
namespace {

Vec2 ReadPoint(const JsonObject& o, const FieldSpec& field) {
  const Vec2 p(o.Number("x_m"), o.Number("y_m"));
  WithFile(o.file(), [&] { RequireOnField(field, o.PathOf("x_m"), p); });
  return p;
}

Problem ReadProblem(const JsonDocument& doc, const std::filesystem::path& dir,
                    const std::filesystem::path& models_dir) {
  const JsonObject root = doc.Root();
  root.RejectUnknownKeys({"field", "defending", "ball", "teammates", "opponents"});
  const std::filesystem::path field_file = ResolveModelFile(
      root.StringOr("field", "four_legged"), DataFolder::kFields, dir, models_dir);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(field_file, ec)) {
    root.Fail("field", "refers to " + field_file.string() + ", which does not exist");
  }
  const FieldSpec field = LoadFieldSpec(field_file);

  Problem problem;
  const std::string goal = root.String("defending");
  const auto defending = ParseDefendingGoal(goal);
  if (!defending) root.Fail("defending", "must be \"cyan\" or \"yellow\", got \"" + goal + "\"");
  problem.defending = *defending;
  const JsonObject ball = root.Object("ball");
  ball.RejectUnknownKeys({"x_m", "y_m"});
  problem.p_F_ball = ReadPoint(ball, field);

  const auto teammates = root.ObjectArray("teammates");
  if (teammates.empty() || teammates.size() > 4) {
    root.Fail("teammates", "must list 1-4 robots, got " + std::to_string(teammates.size()));
  }
  std::set<int> ids;
  for (const JsonObject& t : teammates) {
    t.RejectUnknownKeys({"id", "x_m", "y_m", "theta_deg"});
    const int id = t.Integer("id");
    if (id < 1 || id > 4) t.Fail("id", "must be 1..4, got " + std::to_string(id));
    if (!ids.insert(id).second) t.Fail("id", std::to_string(id) + " is used twice");
    const Vec2 p = ReadPoint(t, field);
    const double theta_deg = t.Number("theta_deg");
    if (std::abs(theta_deg) > 360.0) {
      t.Fail("theta_deg", "must be in [-360, 360], got " + FormatNumber(theta_deg));
    }
    problem.teammates.push_back({id, Pose2{p, theta_deg * kDegToRad}});
  }
  const auto opponents = root.ObjectArray("opponents");
  if (opponents.size() > 4) {
    root.Fail("opponents", "must list 0-4 robots, got " + std::to_string(opponents.size()));
  }
  for (const JsonObject& o : opponents) {
    o.RejectUnknownKeys({"x_m", "y_m"});
    problem.opponents.push_back(ReadPoint(o, field));
  }
  return problem;
}

}  // namespace

Problem LoadProblem(const std::filesystem::path& file, const std::filesystem::path& models_dir) {
  return ReadProblem(JsonDocument::Load(file), file.parent_path(), models_dir);
}

Problem ParseProblem(std::string_view text, const std::string& origin,
                     const std::filesystem::path& dir, const std::filesystem::path& models_dir) {
  return ReadProblem(JsonDocument::Parse(text, origin), dir, models_dir);
}

}  // namespace foresight
