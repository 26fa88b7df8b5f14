// The scan for XML nesting before urdfdom: it counts elements as XML nests them, whatever
// comments, CDATA, declarations and quoted values hold, and it stays linear in the text.
#include "models/xml_nesting.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

namespace foresight {
namespace {

std::string Nested(int depth, const std::string& inner = "") {
  std::string text;
  for (int i = 0; i < depth; ++i) text += "<a>";
  text += inner;
  for (int i = 0; i < depth; ++i) text += "</a>";
  return text;
}

TEST(XmlNestingTest, TheLimitItselfPassesOneMoreFailsWithItsLine) {
  EXPECT_EQ(XmlNestingProblem(Nested(kMaxXmlDepth)), std::nullopt);
  EXPECT_EQ(XmlNestingProblem("<?xml version=\"1.0\"?>\n" + Nested(kMaxXmlDepth + 1)),
            "elements nested deeper than 64 levels (line 2)");
}

TEST(XmlNestingTest, SelfClosingElementsAndSiblingsAddNoDepth) {
  std::string siblings;
  for (int i = 0; i < 1000; ++i) siblings += "<b x='1'/><c>text</c>\n";
  EXPECT_EQ(XmlNestingProblem(Nested(kMaxXmlDepth - 1, siblings)), std::nullopt);
  EXPECT_EQ(XmlNestingProblem(Nested(kMaxXmlDepth - 1, "<b/><b></b><c/>")), std::nullopt);
}

TEST(XmlNestingTest, WhatIsNoElementIsNotCounted) {
  const std::string inside = Nested(10);
  for (const std::string& hidden :
       {"<!-- " + inside + " -->", "<![CDATA[" + inside + "]]>", "<?pi " + inside + " ?>",
        "<!DOCTYPE r [ <!ENTITY e '" + inside + "'> ]>", "<b v='" + inside + "'/>",
        "<b v=\"" + inside + "\"/>"}) {
    EXPECT_EQ(XmlNestingProblem(Nested(kMaxXmlDepth - 1, hidden)), std::nullopt) << hidden;
  }
  // A '>' or '/' inside a quoted value neither ends the tag nor closes the element.
  EXPECT_EQ(XmlNestingProblem(Nested(kMaxXmlDepth, "<b v='/'>")),
            "elements nested deeper than 64 levels (line 1)");
}

TEST(XmlNestingTest, AHundredThousandLevelsAreFoundAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(XmlNestingProblem(Nested(100000)), "elements nested deeper than 64 levels (line 1)");
  std::string flat;
  while (flat.size() < (16u << 20)) flat += "<link name=\"x\"><visual/></link>\n";
  EXPECT_EQ(XmlNestingProblem("<robot>" + flat + "</robot>"), std::nullopt);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));  // linear
}

}  // namespace
}  // namespace foresight
