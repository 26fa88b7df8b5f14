// A message as the user sees it, one line: control characters (a name with a newline in it)
// escaped as \n or \xHH, the formatting characters that reorder or break text (U+202E) as
// \uXXXX, bytes that are no UTF-8 as \xHH (common/one_line.cc lists them), and cut after
// max_bytes with the message's full size said. The command
// line prints its errors so and the Python module raises them so; text output prints names from
// data files so (a case name is the user's).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace foresight {

inline constexpr std::size_t kMaxMessageBytes = 2000;
std::string OneLine(std::string_view message, std::size_t max_bytes = kMaxMessageBytes);

// Text of several lines as a terminal should show it: every control character but the newline
// escaped as \xHH (a name holding an escape sequence cannot recolour or rewrite the screen), the
// rest as OneLine escapes it.
std::string PrintableLines(std::string_view text);

// A name from a data file (a check, a situation, a case) as every output shows it: OneLine's
// escapes, never cut. The text is then printable and every character valid in XML 1.0.
std::string PrintableName(std::string_view name);

}  // namespace foresight
