// Parsing the project's JSON files strictly and in time linear in their size.
//
// Strictness beyond the JSON grammar: no key twice in one object (nlohmann would keep the last
// silently, so a typo'd override would win unseen), nesting at most kMaxJsonDepth deep (so
// nothing downstream recurses without end), no NUL byte, nothing after the value. The tree is
// built by the project's own SAX handler over nlohmann's `sax_parse`: every value is made once
// and stored in its parent, and a key is checked against its object's keys by one look-up, so
// no container is scanned again when a value is added to it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace foresight {

// Limits of a data file: the project's files are a few kB and a few levels deep, so these are
// far above any real file (assumption) and far below what exhausts memory or the stack.
inline constexpr std::uintmax_t kMaxJsonBytes = 16u << 20;  // 16 MiB
inline constexpr int kMaxJsonDepth = 64;

// What one parse did, counted (not timed): the characters nlohmann's lexer read and the SAX
// events the handler took (each makes or closes one value, or stores one key). Linear parsing
// means both grow in proportion to the text.
struct JsonParseWork {
  std::size_t characters_read = 0;
  std::size_t handler_events = 0;
};

// The tree of `text`; bad syntax (with line and column), a NUL byte, nesting deeper than
// kMaxJsonDepth or a key twice in one object is an InputError starting "ORIGIN: invalid JSON".
// `work`, when given, receives what the parse did.
nlohmann::json ParseStrictJson(std::string_view text, const std::string& origin,
                               JsonParseWork* work = nullptr);

}  // namespace foresight
