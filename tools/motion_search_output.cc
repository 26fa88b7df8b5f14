#include "tools/motion_search_output.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "common/data_file.h"
#include "common/error.h"
#include "common/geometry.h"

namespace foresight {

namespace {

// The double nearest to `value` written with `decimals` decimals, so that the file shows
// -44.9798, not the -44.979800000000004 that rounding by multiplication leaves.
double Rounded(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return std::strtod(text, nullptr);
}

nlohmann::ordered_json KeyframesJson(const KickMotion& motion) {
  nlohmann::ordered_json keyframes = nlohmann::ordered_json::array();
  for (const KickKeyframe& key : motion.keyframes) {
    nlohmann::ordered_json positions = nlohmann::ordered_json::array();
    for (double q : key.positions_rad) positions.push_back(Rounded(q * kRadToDeg, 4));
    keyframes.push_back({{"time_s", Rounded(key.time_s, 6)}, {"positions_deg", positions}});
  }
  return keyframes;
}

nlohmann::ordered_json DegreesJson(const std::vector<std::pair<std::string, double>>& angles_rad) {
  nlohmann::ordered_json degrees = nlohmann::ordered_json::object();
  for (const auto& [name, angle_rad] : angles_rad) degrees[name] = Rounded(angle_rad * kRadToDeg, 4);
  return degrees;
}

nlohmann::ordered_json OffsetsJson(const KickMotion& motion) {
  return DegreesJson(motion.balance.offsets_rad);
}

}  // namespace

std::string CandidateLine(const SearchCandidate& c) {
  char line[320];
  if (c.refusal != Refusal::kNone && c.summary.trials == 0) {
    std::snprintf(line, sizeof line, "r%d c%-4d refused (%s): speed share %.3f, clearance %.4f m",
                  c.round, c.index, std::string(RefusalName(c.refusal)).c_str(), c.speed_share,
                  c.clearance_m);
    return line;
  }
  const TrialSummary& s = c.summary;
  std::snprintf(line, sizeof line,
                "r%d c%-4d %s %.4f  launch %.3f sd %.3f m/s  dir %+.1f sd %.1f deg  fell %d/%d  "
                "missed %d  speed share %.3f",
                c.round, c.index, c.refusal == Refusal::kNone ? "score" : "refused (balance)",
                c.score, s.launch_speed_mean_mps, s.launch_speed_sd_mps,
                s.launch_direction_mean_rad * kRadToDeg, s.launch_direction_sd_rad * kRadToDeg,
                s.fell, s.trials, s.trials - s.launched, c.speed_share);
  return line;
}

std::string RoundText(int round, const MotionSearchResult& result, int keep) {
  int scored = 0, in_round = 0;
  int refused[4] = {0, 0, 0, 0};
  for (const SearchCandidate& c : result.candidates) {
    if (c.round != round) continue;
    ++in_round;
    if (c.refusal == Refusal::kNone) {
      ++scored;
    } else {
      ++refused[static_cast<int>(c.refusal)];
    }
  }
  std::ostringstream out;
  out << "round " << round << ": " << in_round << " candidates, " << scored
      << " scored, refused: speed " << refused[static_cast<int>(Refusal::kSpeed)]
      << ", clearance " << refused[static_cast<int>(Refusal::kClearance)] << ", balance "
      << refused[static_cast<int>(Refusal::kBalance)] << "; best, ranked on the round's own trials:\n";
  for (int k = 0; k < keep && k < static_cast<int>(result.best.size()); ++k) {
    out << "  " << CandidateLine(result.candidates[static_cast<std::size_t>(result.best[k])])
        << "\n";
  }
  return out.str();
}

nlohmann::ordered_json SearchJson(const MotionSearchSettings& settings,
                                  const MotionSearchResult& result) {
  nlohmann::ordered_json j;
  j["settings"] = settings.file.string();
  j["kick"] = settings.kick;
  j["base"] = RobotBaseName(settings.base);
  j["seed"] = settings.seed;
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const SearchCandidate& c : result.candidates) {
    nlohmann::ordered_json item;
    item["round"] = c.round;
    item["index"] = c.index;
    item["refused"] = RefusalName(c.refusal);
    item["speed_share"] = c.speed_share;
    item["clearance_m"] = c.clearance_m;
    if (c.summary.trials > 0) {
      const TrialSummary& s = c.summary;
      if (c.refusal == Refusal::kNone) item["score"] = c.score;  // a refused one has none
      item["trials"] = s.trials;
      item["launched"] = s.launched;
      item["fell"] = s.fell;
      item["launch_speed_mean_mps"] = s.launch_speed_mean_mps;
      item["launch_speed_sd_mps"] = s.launch_speed_sd_mps;
      item["launch_direction_mean_deg"] = s.launch_direction_mean_rad * kRadToDeg;
      item["launch_direction_sd_deg"] = s.launch_direction_sd_rad * kRadToDeg;
      item["low_share"] = c.low_share;
      item["max_tilt_deg"] = s.max_tilt_rad * kRadToDeg;
    }
    all.push_back(std::move(item));
  }
  j["candidates"] = std::move(all);
  nlohmann::ordered_json best = nlohmann::ordered_json::array();
  for (int index : result.best) {
    const SearchCandidate& c = result.candidates[static_cast<std::size_t>(index)];
    best.push_back({{"round", c.round},
                    {"index", c.index},
                    {"score", c.score},
                    {"keyframes", KeyframesJson(c.motion)},
                    {"balance_offsets_deg", OffsetsJson(c.motion)}});
  }
  j["best"] = std::move(best);
  return j;
}

std::string MotionFileText(const std::filesystem::path& template_file, const KickMotion& motion) {
  // Read as every data file is (a FIFO in its place is refused, not waited on); the caller read
  // it strictly already, and ordered_json keeps its keys in the file's order.
  nlohmann::ordered_json j =
      nlohmann::ordered_json::parse(ReadDataFile(template_file), nullptr, false);
  if (j.is_discarded()) throw InputError(template_file.string() + ": not JSON");
  j["name"] = motion.name;
  j["ball_x_m"] = motion.p_R_ball.x();
  j["ball_y_m"] = motion.p_R_ball.y();
  if (motion.stance.IsOwn()) {
    j["stance"]["base_height_m"] = motion.stance.base_height_m;
    j["stance"]["pose_deg"] = DegreesJson(motion.stance.pose_rad);
  } else {
    j.erase("stance");
  }
  if (motion.balance.Has()) {
    j["balance"]["shift_s"] = motion.balance.shift_s;
    j["balance"]["settle_s"] = motion.balance.settle_s;
    j["balance"]["offsets_deg"] = OffsetsJson(motion);
  } else {
    j.erase("balance");
  }
  j["joints"] = motion.joints;
  j["keyframes"] = KeyframesJson(motion);
  return j.dump(2) + "\n";
}

}  // namespace foresight
