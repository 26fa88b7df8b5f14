#include "validation/observed_kicks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
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

// One record of the file: its cells and the line it starts on.
struct CsvRecord {
  int line = 0;
  std::vector<std::string> cells;
};

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// The file's records after RFC 4180: cells separated by commas, records by LF (CRLF: the CR is
// dropped with the spaces around a cell), a cell in double quotes may hold commas, line breaks
// and "" for a quote. Lines holding nothing but spaces are skipped.
std::vector<CsvRecord> SplitCsv(const std::string& text, const std::string& file) {
  std::vector<CsvRecord> records;
  std::size_t i = 0;
  int line = 1;
  const std::size_t n = text.size();
  while (i < n) {
    CsvRecord record;
    record.line = line;
    bool any_text = false;
    while (true) {  // one cell per turn
      while (i < n && IsBlank(text[i])) ++i;
      std::string cell;
      if (i < n && text[i] == '"') {
        any_text = true;
        const int opened = line;
        ++i;
        while (true) {
          if (i >= n) {
            throw InputError(file + ": line " + std::to_string(opened) +
                             ": a quoted cell is never closed");
          }
          if (text[i] == '"') {
            if (i + 1 < n && text[i + 1] == '"') {
              cell += '"';
              i += 2;
              continue;
            }
            ++i;
            break;
          }
          if (text[i] == '\n') ++line;
          cell += text[i++];
        }
        while (i < n && IsBlank(text[i])) ++i;
        if (i < n && text[i] != ',' && text[i] != '\n') {
          throw InputError(file + ": line " + std::to_string(line) +
                           ": text after a quoted cell's closing quote");
        }
      } else {
        while (i < n && text[i] != ',' && text[i] != '\n') {
          if (text[i] == '"') {
            throw InputError(file + ": line " + std::to_string(line) +
                             ": a quote inside an unquoted cell (quote the whole cell)");
          }
          cell += text[i++];
        }
        const auto last = cell.find_last_not_of(" \t\r");
        cell = last == std::string::npos ? "" : cell.substr(0, last + 1);
        any_text = any_text || !cell.empty();
      }
      record.cells.push_back(std::move(cell));
      if (i < n && text[i] == ',') {
        ++i;
        any_text = true;  // a line of commas is a row of empty cells, not a blank line
        continue;
      }
      break;  // end of the line or of the file
    }
    if (i < n) {  // the line break
      ++i;
      ++line;
    }
    if (any_text) records.push_back(std::move(record));
  }
  return records;
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

std::map<std::string, int> ReadHeader(const std::vector<std::string>& names,
                                      const std::string& file) {
  std::map<std::string, int> columns;
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
KickObservation ObservationOfRow(const Row& row, double deceleration, ObservedRow& seen) {
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
  k.speed_from_rest = !speed;
  seen.launch_direction_deg = direction;
  if (rest_x) {
    const Vec2 travel = Vec2(*rest_x, *rest_y) - ball;
    k.roll_distance_m = travel.norm();
    k.has_roll_distance = speed.has_value();  // a derived speed cannot fit the deceleration
    k.launch_direction_rad = WrapAngle(std::atan2(travel.y(), travel.x()) - robot.theta_rad);
    k.launch_speed_mps = std::sqrt(2.0 * deceleration * k.roll_distance_m);
    // A ball that did not move has no bearing.
    if (k.roll_distance_m > 0.0) seen.rest_bearing_deg = k.launch_direction_rad * kRadToDeg;
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
  std::vector<CsvRecord> records = SplitCsv(ReadDataFile(file), file.string());
  if (records.empty() || records.front().line != 1) {
    throw InputError(file.string() + ": empty file, no header line");
  }
  const std::map<std::string, int> columns = ReadHeader(records.front().cells, file.string());
  ObservedKicks kicks;
  for (std::size_t r = 1; r < records.size(); ++r) {
    std::vector<std::string>& cells = records[r].cells;
    const std::string where = file.string() + ": line " + std::to_string(records[r].line) + ": ";
    if (cells.size() != columns.size()) {
      throw InputError(where + "has " + std::to_string(cells.size()) + " cells, the header " +
                       std::to_string(columns.size()));
    }
    const Row row(columns, std::move(cells), where);
    const std::string kick = row.Text("kick");
    if (kick.empty()) throw InputError(where + "kick: missing name");
    ObservedRow seen;
    seen.line = records[r].line;
    seen.kick = kick;
    const KickObservation k = ObservationOfRow(row, assumed_deceleration_mps2, seen);
    if (!kicks.by_kick.count(kick)) kicks.kick_names.push_back(kick);
    kicks.by_kick[kick].push_back(k);
    kicks.speeds_from_rest += k.speed_from_rest;
    kicks.row_list.push_back(std::move(seen));
    ++kicks.rows;
  }
  if (kicks.rows == 0) throw InputError(file.string() + ": no kicks after the header line");
  return kicks;
}

namespace {

// An angle in degrees for a message, one decimal.
std::string Deg(double deg) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", deg);
  return text;
}

// The angle from b to a in degrees, wrapped into [-180, 180).
double AngleBetweenDeg(double a_deg, double b_deg) {
  return WrapAngle((a_deg - b_deg) * kDegToRad) * kRadToDeg;
}

}  // namespace

void CheckObservedKicks(const ObservedKicks& kicks, const KickModel& model,
                        const std::filesystem::path& file) {
  const std::string name = file.string();
  // Rows whose launch and rest describe different kicks.
  for (const ObservedRow& row : kicks.row_list) {
    const std::optional<int> index = model.Find(row.kick);
    if (!index || !row.launch_direction_deg || !row.rest_bearing_deg) continue;
    const double sigma_deg = model.kicks[*index].sigma_direction_rad * kRadToDeg;
    const double allowed_deg = kMaxLaunchRestSigmas * sigma_deg;
    const double off_deg = AngleBetweenDeg(*row.launch_direction_deg, *row.rest_bearing_deg);
    if (std::abs(off_deg) <= allowed_deg) continue;
    const std::string where = name + ": line " + std::to_string(row.line) +
                              ": launch_direction_deg: " + FormatNumber(*row.launch_direction_deg);
    const double as_radians_deg = *row.launch_direction_deg * kRadToDeg;
    if (std::abs(*row.launch_direction_deg) <= std::numbers::pi &&
        std::abs(AngleBetweenDeg(as_radians_deg, *row.rest_bearing_deg)) <= allowed_deg) {
      throw InputError(where + " looks like radians: as radians it is " +
                       Deg(as_radians_deg) + " deg, which agrees with the rest position's "
                       "bearing " + Deg(*row.rest_bearing_deg) +
                       " deg; write degrees");
    }
    throw InputError(where + " deg contradicts the rest position's bearing " +
                     Deg(*row.rest_bearing_deg) + " deg by " +
                     Deg(std::abs(off_deg)) + " deg, more than " +
                     FormatNumber(kMaxLaunchRestSigmas) + " x sigma_direction (" +
                     Deg(allowed_deg) + " deg) of '" + row.kick + "' in the kick model");
  }
  // Kicks whose launch directions as a whole look like radians.
  for (const std::string& kick : kicks.kick_names) {
    const std::optional<int> index = model.Find(kick);
    if (!index) continue;
    const KickSpec& spec = model.kicks[*index];
    double sum_deg = 0.0;
    int count = 0;
    int first_line = 0;
    bool all_small = true;
    for (const ObservedRow& row : kicks.row_list) {
      if (row.kick != kick || !row.launch_direction_deg) continue;
      if (count == 0) first_line = row.line;
      all_small = all_small && std::abs(*row.launch_direction_deg) <= std::numbers::pi;
      sum_deg += *row.launch_direction_deg;
      ++count;
    }
    if (count == 0 || !all_small) continue;
    const double mean_deg = sum_deg / count;
    const double model_deg = spec.direction_rad * kRadToDeg;
    const double allowed_deg = kMaxLaunchRestSigmas * spec.sigma_direction_rad * kRadToDeg;
    if (std::abs(AngleBetweenDeg(mean_deg, model_deg)) > allowed_deg &&
        std::abs(AngleBetweenDeg(mean_deg * kRadToDeg, model_deg)) <= allowed_deg) {
      throw InputError(name + ": line " + std::to_string(first_line) +
                       ": launch_direction_deg: the " + std::to_string(count) + " launches of '" +
                       kick + "' look like radians: all lie within +-pi, their mean " +
                       FormatNumber(std::round(mean_deg * 1000.0) / 1000.0) + " is " + Deg(mean_deg * kRadToDeg) +
                       " deg as radians, within " + Deg(allowed_deg) +
                       " deg of the kick model's " + Deg(model_deg) +
                       " deg; write degrees");
    }
  }
}

void RederiveSpeedsFromRest(std::vector<KickObservation>& kicks, double deceleration_mps2,
                            double launch_offset_m) {
  for (KickObservation& k : kicks) {
    if (!k.speed_from_rest) continue;
    k.launch_speed_mps =
        std::sqrt(2.0 * deceleration_mps2 * std::max(0.0, k.roll_distance_m - launch_offset_m));
  }
}

}  // namespace foresight
