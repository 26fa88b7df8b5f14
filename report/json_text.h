// JSON written by hand, where a document is too large or too plain to build as a tree (the 3D
// viewer page, the scene trace, the passing replay): the one writer of its strings and numbers.
// A string is escaped as JSON requires (quotes, backslashes, control characters; invalid UTF-8
// replaced by U+FFFD); a number is written so that it reads back to the same double, and a NaN or
// an infinity, which JSON cannot hold, is refused with std::domain_error naming the value's
// place: it is a bug upstream (every loader refuses non-finite input), not a value to print.
#pragma once

#include <string>
#include <string_view>

namespace foresight {

// "text" with its quotes.
std::string JsonString(std::string_view text);

// The shortest text that reads back to `value` (common/checks.h's FormatNumber). `what` names
// the value for the error ("viewer field.goal.post_radius_m").
std::string JsonNumber(double value, std::string_view what);

// `value` with `decimals` decimals (a screen coordinate), refused as JsonNumber when not finite.
std::string JsonFixed(double value, int decimals, std::string_view what);

// round(value), refused as JsonNumber when not finite or beyond a long long.
long long JsonRounded(double value, std::string_view what);

// JSON placed inside an HTML <script> element: "</" would end it early; JSON may write "<\/".
std::string ScriptSafeJson(std::string json);

}  // namespace foresight
