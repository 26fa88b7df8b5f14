// How deep the elements of an XML text nest, found by one linear scan before a third-party
// parser sees the text. urdfdom's XML parser (TinyXML2) descends recursively, one stack frame
// per level, and its tree walks grow faster than the depth: a URDF of 100,000 nested elements
// (1.3 MB) overflowed the stack and 30,000 took 19 s. A robot's URDF nests about 5 deep, so the
// JSON reader's limit (common/strict_json.h) is kept here too.
//
// The scan knows what XML puts between '<' and '>' that is no element: comments, CDATA,
// processing instructions, a DOCTYPE (with its internal subset) and quoted attribute values
// holding '>'. It only counts; whether the text is well-formed stays the parser's to say.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace foresight {

// The deepest nesting a URDF may have (the JSON reader's kMaxJsonDepth).
inline constexpr int kMaxXmlDepth = 64;

// nullopt if no element of `text` lies more than `max_depth` elements deep; otherwise the
// problem, "elements nested deeper than 64 levels (line N)", N the line of the element that
// went too deep.
std::optional<std::string> XmlNestingProblem(std::string_view text, int max_depth = kMaxXmlDepth);

}  // namespace foresight
