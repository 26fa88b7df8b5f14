#include "models/xml_nesting.h"

#include <algorithm>
#include <cstddef>

#include "common/strict_json.h"

namespace foresight {

static_assert(kMaxXmlDepth == kMaxJsonDepth, "one nesting limit for every data file");

namespace {

class XmlScan {
 public:
  explicit XmlScan(std::string_view text) : text_(text) {}

  std::optional<std::string> Problem(int max_depth) {
    int depth = 0;
    while (Advance('<')) {
      if (Starts("<!--")) {
        Skip("-->");
      } else if (Starts("<![CDATA[")) {
        Skip("]]>");
      } else if (Starts("<?")) {
        Skip("?>");
      } else if (Starts("<!")) {
        SkipDeclaration();
      } else if (Starts("</")) {
        --depth;
        Skip(">");
      } else if (OpenTag() && ++depth > max_depth) {
        return "elements nested deeper than " + std::to_string(max_depth) + " levels (line " +
               std::to_string(line_) + ")";
      }
    }
    return std::nullopt;
  }

 private:
  bool Starts(std::string_view prefix) const { return text_.substr(at_).starts_with(prefix); }

  // Moves to the next `c` (false at the end), counting lines.
  bool Advance(char c) {
    while (at_ < text_.size() && text_[at_] != c) Step();
    return at_ < text_.size();
  }

  void Step() {
    if (text_[at_] == '\n') ++line_;
    ++at_;
  }

  // Moves past the next `end` (to the end of the text if there is none).
  void Skip(std::string_view end) {
    while (at_ < text_.size() && !Starts(end)) Step();
    at_ = std::min(text_.size(), at_ + end.size());
  }

  // <!DOCTYPE ... [ internal subset ] >: '>' inside the brackets ends no declaration.
  void SkipDeclaration() {
    int brackets = 0;
    for (; at_ < text_.size(); Step()) {
      const char c = text_[at_];
      if (c == '[') ++brackets;
      if (c == ']') --brackets;
      if (c == '>' && brackets <= 0) break;
    }
    if (at_ < text_.size()) ++at_;
  }

  // Moves past a start tag; true unless it closes itself (<a/>). Quoted values may hold '>'.
  bool OpenTag() {
    char quote = '\0', last = '\0';
    for (Step(); at_ < text_.size(); Step()) {
      const char c = text_[at_];
      if (quote != '\0') {
        if (c == quote) quote = '\0';
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>') {
        ++at_;
        return last != '/';
      }
      if (c != ' ' && c != '\t' && c != '\n' && c != '\r') last = c;
    }
    return true;  // unterminated: the parser says so
  }

  std::string_view text_;
  std::size_t at_ = 0;
  int line_ = 1;
};

}  // namespace

std::optional<std::string> XmlNestingProblem(std::string_view text, int max_depth) {
  return XmlScan(text).Problem(max_depth);
}

}  // namespace foresight
