// The SVG builder: numbers, escaping, and a well-formed document.
#include "report/svg_writer.h"

#include <gtest/gtest.h>

namespace foresight {
namespace {

TEST(SvgWriterTest, NumbersAreCompactAndLocaleFree) {
  EXPECT_EQ(SvgWriter::Num(1.0), "1");
  EXPECT_EQ(SvgWriter::Num(0.1234), "0.123");
  EXPECT_EQ(SvgWriter::Num(-0.0001), "0");
  EXPECT_EQ(SvgWriter::Num(-2.5), "-2.5");
  EXPECT_EQ(SvgWriter::Num(1.0 / 0.0), "0");  // never "inf" in a document
}

TEST(SvgWriterTest, TextIsEscaped) {
  EXPECT_EQ(SvgWriter::Escape("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
}

TEST(SvgWriterTest, DocumentHasHeaderBodyAndEnd) {
  SvgWriter svg(100, 50);
  svg.Circle(10, 20, 3, "fill:red");
  svg.Text(5, 5, "x<y", "font-size:10px");
  const std::string doc = svg.Finish();
  EXPECT_EQ(doc.rfind("<?xml", 0), 0u);
  EXPECT_NE(doc.find("viewBox=\"0 0 100 50\""), std::string::npos);
  EXPECT_NE(doc.find("<circle cx=\"10\" cy=\"20\" r=\"3\" style=\"fill:red\"/>"),
            std::string::npos);
  EXPECT_NE(doc.find(">x&lt;y</text>"), std::string::npos);
  EXPECT_EQ(doc.substr(doc.size() - 7), "</svg>\n");
}

TEST(SvgWriterTest, PathKeepsItsDataAndStyle) {
  SvgWriter svg(100, 50);
  svg.Path("M 1 2 L 3 4 A 5 5 0 0 0 6 7 Z", "fill:none;stroke:#000");
  const std::string doc = svg.Finish();
  EXPECT_NE(doc.find("<path d=\"M 1 2 L 3 4 A 5 5 0 0 0 6 7 Z\" style=\"fill:none;stroke:#000\"/>"),
            std::string::npos);
}

}  // namespace
}  // namespace foresight
