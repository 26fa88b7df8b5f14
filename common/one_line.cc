// Text as a terminal or an XML file may show it. Kept: printable ASCII and valid UTF-8 but the
// characters below. Escaped: the C0 and C1 controls and DEL (\n, \xHH; an ESC would recolour
// the terminal), the bidirectional and line-breaking formatting characters U+061C, U+200E,
// U+200F, U+2028, U+2029, U+202A..U+202E and U+2066..U+2069 (U+202E shows "abc" as "cba") and
// the non-characters U+FFFE and U+FFFF as \uXXXX, and bytes that are no valid UTF-8 as \xHH,
// so what is shown is all printable and a valid XML 1.0 character.
#include <cstdio>
#include <string>

#include "common/one_line.h"

namespace foresight {

namespace {

struct CodePoint {
  char32_t value = 0;
  std::size_t bytes = 0;  // 0: text[at] starts no valid UTF-8 sequence
};

bool Continuation(unsigned char c) { return (c & 0xc0) == 0x80; }

// The UTF-8 sequence at text[at] (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF).
CodePoint Decode(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
  const unsigned char lead = byte(0);
  const std::size_t bytes = lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : lead >= 0xc0 ? 2 : 0;
  if (bytes == 0 || lead > 0xf4 || at + bytes > text.size()) return {};
  char32_t value = lead & (0x7f >> bytes);
  for (std::size_t k = 1; k < bytes; ++k) {
    if (!Continuation(byte(k))) return {};
    value = (value << 6) | (byte(k) & 0x3f);
  }
  const char32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
  if (value < least[bytes] || value > 0x10ffff || (value >= 0xd800 && value <= 0xdfff)) return {};
  return {value, bytes};
}

bool Hidden(char32_t c) {
  return (c >= 0x80 && c <= 0x9f) || c == 0x061c || c == 0x200e || c == 0x200f ||
         (c >= 0x2028 && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069) || c == 0xfffe ||
         c == 0xffff;
}

void AppendEscaped(std::string& out, const char* format, unsigned value) {
  char escaped[12];
  std::snprintf(escaped, sizeof escaped, format, value);
  out += escaped;
}

void AppendShown(std::string& out, std::string_view text, bool keep_newline) {
  out.reserve(out.size() + text.size());
  for (std::size_t at = 0; at < text.size();) {
    const char c = text[at];
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x80) {
      if ((u >= 0x20 && u != 0x7f) || (keep_newline && c == '\n')) {
        out += c;
      } else if (c == '\n') {
        out += "\\n";
      } else {
        AppendEscaped(out, "\\x%02x", u);
      }
      ++at;
      continue;
    }
    const CodePoint point = Decode(text, at);
    if (point.bytes == 0) {
      AppendEscaped(out, "\\x%02x", u);
      ++at;
    } else {
      if (Hidden(point.value)) {
        AppendEscaped(out, "\\u%04x", static_cast<unsigned>(point.value));
      } else {
        out.append(text.substr(at, point.bytes));
      }
      at += point.bytes;
    }
  }
}

}  // namespace

std::string PrintableLines(std::string_view text) {
  std::string shown;
  AppendShown(shown, text, true);
  return shown;
}

std::string PrintableName(std::string_view name) {
  std::string shown;
  AppendShown(shown, name, false);
  return shown;
}

std::string OneLine(std::string_view message, std::size_t max_bytes) {
  std::string line;
  AppendShown(line, message.substr(0, max_bytes), false);
  if (message.size() > max_bytes) {
    line += "... (" + std::to_string(message.size()) + " bytes)";
  }
  return line;
}

}  // namespace foresight
