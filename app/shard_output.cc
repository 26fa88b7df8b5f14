#include "app/shard_output.h"

#include <iostream>

#include "app/cli_values.h"
#include "common/error.h"

namespace foresight {

void AddShardOption(CLI::App& command, std::string& shard) {
  command.add_option("--shard", shard,
                     "Run only shard I of N (I/N, from 0) and write DIR/shard.json; "
                     "`foresight merge` makes the report from all N");
}

std::optional<Shard> ParseShardFlag(const std::string& text) {
  if (text.empty()) return std::nullopt;
  return ParseShard("--shard", text);
}

void WriteShardFolder(OutputSet& outputs, const std::string& out_dir, ShardHeader header,
                      const nlohmann::json& results, std::chrono::steady_clock::time_point start,
                      const std::string& item_name) {
  header.run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::filesystem::path file = std::filesystem::path(out_dir) / kShardFileName;
  outputs.Put("--out", std::vector<ReportFile>{
                           {std::string(kShardFileName), ShardFileText(header, results)}});
  outputs.Commit();
  std::cout << header.command << ": shard " << header.shard.Text() << ": " << results.size()
            << " of " << header.items << " " << item_name << " in " << file.string()
            << "\nmerge all " << header.shard.count
            << " shards with: foresight merge --out DIR SHARD_DIR...\n"
            << std::flush;
  if (!std::cout) throw InputError("cannot write to standard output");
}

double ShardsRunTime(const std::vector<ShardPart>& parts) {
  double sum = 0.0;
  for (const ShardPart& part : parts) sum += part.header.run_time_s;
  return sum;
}

void RequireShardItems(const ShardPart& first, int items, const std::string& unit) {
  if (first.header.items == items) return;
  throw InputError(first.file.string() + ": items: " + std::to_string(first.header.items) + " " +
                   unit + ", but the run has " + std::to_string(items) +
                   " here (other data files?)");
}

std::string SettingString(const ShardPart& part, const std::string& flag) {
  const auto& settings = part.header.settings;
  if (!settings.contains(flag) || !settings[flag].is_string()) {
    throw InputError(part.file.string() + ": settings." + flag + ": missing or not a string");
  }
  return settings[flag].get<std::string>();
}

bool SettingFlag(const ShardPart& part, const std::string& flag) {
  const auto& settings = part.header.settings;
  if (!settings.contains(flag) || !settings[flag].is_boolean()) {
    throw InputError(part.file.string() + ": settings." + flag + ": missing or not true/false");
  }
  return settings[flag].get<bool>();
}

}  // namespace foresight
