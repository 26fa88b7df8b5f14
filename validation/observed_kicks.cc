#include "validation/observed_kicks.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "common/checks.h"
#include "common/data_file.h"
#include "common/error.h"
#include "common/geometry.h"

namespace foresight {

namespace {

const std::vector<std::string> kColumns = {
    "kick",     "robot_x_m", "robot_y_m",        "robot_theta_deg",
    "ball_x_m", "ball_y_m",  "launch_speed_mps", "launch_direction_deg",
    "rest_x_m", "rest_y_m"};
const std::vector<std::string> kRequired = {"kick",     "robot_x_m", "robot_y_m", "robot_theta_deg",
                                            "ball_x_m", "ball_y_m"};

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    const auto first = cell.find_first_not_of(" \t\r");
    const auto last = cell.find_last_not_of(" \t\r");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

// The cells of one row by column name, with errors that say where.
class Row {
 public:
  Row(const std::map<std::string, int>& columns, std::vector<std::string> cells, std::string where)
      : columns_(columns), cells_(std::move(cells)), where_(std::move(where)) {}

  std::string Text(const std::string& column) const {
    const auto it = columns_.find(column);
    return it == columns_.end() ? "" : cells_[it->second];
  }
  std::optional<double> Number(const std::string& column) const {
    const std::string text = Text(column);
    if (text.empty()) return std::nullopt;
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || !std::isfinite(value)) {
      throw InputError(where_ + column + ": not a finite number: '" + text + "'");
    }
    return value;
  }
  double Required(const std::string& column) const {
    const std::optional<double> value = Number(column);
    if (!value) throw InputError(where_ + column + ": missing value");
    return *value;
  }
  // The column's number when present, within [-limit, limit] (a plausibility range, so that an
  // absurd value is named instead of overflowing a fit later).
  std::optional<double> Within(const std::string& column, double limit) const {
    const std::optional<double> value = Number(column);
    if (value && std::abs(*value) > limit) {
      throw InputError(where_ + column + ": must be within [-" + FormatNumber(limit) + ", " +
                       FormatNumber(limit) + "], got " + Text(column));
    }
    return value;
  }
  double RequiredWithin(const std::string& column, double limit) const {
    if (!Within(column, limit)) throw InputError(where_ + column + ": missing value");
    return *Number(column);
  }
  const std::string& where() const { return where_; }

 private:
  const std::map<std::string, int>& columns_;
  std::vector<std::string> cells_;
  std::string where_;
};

std::map<std::string, int> ReadHeader(const std::string& line, const std::string& file) {
  std::map<std::string, int> columns;
  const std::vector<std::string> names = SplitCsvLine(line);
  for (std::size_t i = 0; i < names.size(); ++i) {
    bool known = false;
    for (const std::string& c : kColumns) known = known || c == names[i];
    if (!known) throw InputError(file + ": line 1: unknown column '" + names[i] + "'");
    if (columns.count(names[i])) {
      throw InputError(file + ": line 1: duplicate column '" + names[i] + "'");
    }
    columns[names[i]] = static_cast<int>(i);
  }
  for (const std::string& c : kRequired) {
    if (!columns.count(c)) throw InputError(file + ": line 1: missing column '" + c + "'");
  }
  return columns;
}

// One row as an observation; `speed_from_rest` says whether the speed had to be derived.
KickObservation ObservationOfRow(const Row& row, double deceleration, bool& speed_from_rest) {
  const Pose2 robot{Vec2(row.RequiredWithin("robot_x_m", kMaxObservedCoordinateM),
                         row.RequiredWithin("robot_y_m", kMaxObservedCoordinateM)),
                    row.RequiredWithin("robot_theta_deg", kMaxObservedAngleDeg) * kDegToRad};
  const Vec2 ball(row.RequiredWithin("ball_x_m", kMaxObservedCoordinateM),
                  row.RequiredWithin("ball_y_m", kMaxObservedCoordinateM));
  const std::optional<double> speed = row.Within("launch_speed_mps", kMaxObservedSpeedMps);
  const std::optional<double> direction = row.Within("launch_direction_deg", kMaxObservedAngleDeg);
  const std::optional<double> rest_x = row.Within("rest_x_m", kMaxObservedCoordinateM);
  const std::optional<double> rest_y = row.Within("rest_y_m", kMaxObservedCoordinateM);
  if (speed.has_value() != direction.has_value()) {
    throw InputError(row.where() + (speed ? "launch_direction_deg" : "launch_speed_mps") +
                     ": missing value (the launch needs speed and direction)");
  }
  if (rest_x.has_value() != rest_y.has_value()) {
    throw InputError(row.where() + (rest_x ? "rest_y_m" : "rest_x_m") + ": missing value");
  }
  if (!speed && !rest_x) {
    throw InputError(row.where() + "launch_speed_mps: the row has neither a launch nor a rest");
  }
  if (speed && *speed < 0.0) {
    throw InputError(row.where() + "launch_speed_mps: must be >= 0, got " +
                     row.Text("launch_speed_mps"));
  }
  KickObservation k;
  speed_from_rest = !speed;
  if (rest_x) {
    const Vec2 travel = Vec2(*rest_x, *rest_y) - ball;
    k.roll_distance_m = travel.norm();
    k.has_roll_distance = speed.has_value();  // a derived speed cannot fit the deceleration
    k.launch_direction_rad = WrapAngle(std::atan2(travel.y(), travel.x()) - robot.theta_rad);
    k.launch_speed_mps = std::sqrt(2.0 * deceleration * k.roll_distance_m);
  }
  if (speed) {
    k.launch_speed_mps = *speed;
    k.launch_direction_rad = WrapAngle(*direction * kDegToRad);
  }
  return k;
}

}  // namespace

ObservedKicks ReadObservedKicks(const std::filesystem::path& file,
                                double assumed_deceleration_mps2) {
  std::istringstream in(ReadDataFile(file));
  std::string line;
  if (!std::getline(in, line)) throw InputError(file.string() + ": empty file, no header line");
  const std::map<std::string, int> columns = ReadHeader(line, file.string());
  ObservedKicks kicks;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::vector<std::string> cells = SplitCsvLine(line);
    const std::string where = file.string() + ": line " + std::to_string(number) + ": ";
    if (cells.size() != columns.size()) {
      throw InputError(where + "has " + std::to_string(cells.size()) + " cells, the header " +
                       std::to_string(columns.size()));
    }
    const Row row(columns, std::move(cells), where);
    const std::string kick = row.Text("kick");
    if (kick.empty()) throw InputError(where + "kick: missing name");
    bool from_rest = false;
    const KickObservation k = ObservationOfRow(row, assumed_deceleration_mps2, from_rest);
    if (!kicks.by_kick.count(kick)) kicks.kick_names.push_back(kick);
    kicks.by_kick[kick].push_back(k);
    kicks.speeds_from_rest += from_rest;
    ++kicks.rows;
  }
  if (kicks.rows == 0) throw InputError(file.string() + ": no kicks after the header line");
  return kicks;
}

}  // namespace foresight
