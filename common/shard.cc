#include "common/shard.h"

#include <charconv>

#include "common/error.h"

namespace foresight {

namespace {

// The whole of `text` as a non-negative decimal integer, or -1.
int WholeNumber(std::string_view text) {
  int value = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty() || text[0] == '-')
    return -1;
  return value;
}

}  // namespace

std::string Shard::Text() const {
  return std::to_string(index) + "/" + std::to_string(count);
}

Shard ParseShard(const std::string& field, const std::string& text) {
  const auto slash = text.find('/');
  const std::string_view view(text);
  const int index = slash == std::string::npos ? -1 : WholeNumber(view.substr(0, slash));
  const int count = slash == std::string::npos ? -1 : WholeNumber(view.substr(slash + 1));
  if (index < 0 || count < 1 || count > kMaxShards || index >= count) {
    std::string shown = text.substr(0, 40);
    for (char& c : shown) {
      if (static_cast<unsigned char>(c) < 0x20) c = '?';
    }
    throw InputError(field + ": must be I/N with 0 <= I < N <= " + std::to_string(kMaxShards) +
                     " (shard I of N), got '" + shown + "'");
  }
  return {index, count};
}

}  // namespace foresight
