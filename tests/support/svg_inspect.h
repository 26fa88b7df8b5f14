// Reading the SVG the charts and maps write, in tests: counting parts, reading an attribute of
// a tag, finding the tags inside <g class="..."> groups.
#pragma once

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace foresight::testing {

// How often `what` occurs in `text` (overlapping occurrences count).
inline int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

// The value of attribute `name` in the tag starting at `pos`; NaN (and a test failure) if the
// tag has no such attribute.
inline double Attr(const std::string& svg, std::size_t pos, const std::string& name) {
  const std::size_t end = svg.find('>', pos);
  const std::size_t at = svg.find(" " + name + "=\"", pos);
  EXPECT_LT(at, end) << name;
  return at < end ? std::stod(svg.substr(at + name.size() + 3))
                  : std::numeric_limits<double>::quiet_NaN();
}

// The first tag `tag` inside each group <g class="klass">, in document order.
inline std::vector<std::size_t> TagsInGroups(const std::string& svg, const std::string& klass,
                                             const std::string& tag) {
  std::vector<std::size_t> out;
  const std::string open = "<g class=\"" + klass + "\">";
  for (auto pos = svg.find(open); pos != std::string::npos; pos = svg.find(open, pos + 1)) {
    const std::size_t t = svg.find("<" + tag + " ", pos);
    EXPECT_LT(t, svg.find("</g>", pos));
    out.push_back(t);
  }
  return out;
}

}  // namespace foresight::testing
