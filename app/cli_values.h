// Strict parsing of command-line values: the whole text must be the number, in range, or the
// command fails with "--flag: must be ..., got 'TEXT'" (CLI11's conversions accept "-1" for an
// unsigned seed and wrap it around).
#pragma once

#include <cstdint>
#include <string>

namespace foresight {

int ParseCount(const std::string& flag, const std::string& text, int lo, int hi);
std::uint64_t ParseSeed(const std::string& text);  // for --seed: 0 .. 2^64 - 1
double ParseNumber(const std::string& flag, const std::string& text, double lo, double hi);

}  // namespace foresight
