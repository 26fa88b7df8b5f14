// The HTML report page: escaping, inline figures, tables, and a page without scripts.
#include "report/html_report.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "report/svg_writer.h"

namespace foresight {
namespace {

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

// Every element opened is closed, in order (void elements and "/>" excepted).
void ExpectBalanced(const std::string& html) {
  const std::set<std::string> kVoid = {"meta", "br", "hr", "img", "input", "link", "wbr"};
  std::vector<std::string> open;
  for (auto pos = html.find('<'); pos != std::string::npos; pos = html.find('<', pos + 1)) {
    const std::size_t end = html.find('>', pos);
    ASSERT_NE(end, std::string::npos);
    if (html[pos + 1] == '!' || html[pos + 1] == '?' || html[end - 1] == '/') continue;
    if (html[pos + 1] == '/') {
      ASSERT_FALSE(open.empty()) << html.substr(pos, 40);
      EXPECT_EQ(html.substr(pos + 2, end - pos - 2), open.back());
      open.pop_back();
    } else {
      const std::size_t name_end = html.find_first_of(" >", pos);
      const std::string name = html.substr(pos + 1, name_end - pos - 1);
      if (kVoid.count(name) == 0) open.push_back(name);
    }
  }
  EXPECT_TRUE(open.empty()) << (open.empty() ? "" : open.back());
}

std::string SampleSvg() {
  SvgWriter svg(40, 20);
  svg.Text(2, 10, "a<b", "font-size:11px");
  return svg.Finish();
}

TEST(HtmlReportTest, EscapesAllFiveCharacters) {
  EXPECT_EQ(HtmlReport::Escape("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  EXPECT_EQ(HtmlReport::Escape("plain 0.78 m/s"), "plain 0.78 m/s");
}

TEST(HtmlReportTest, AllTextIsEscaped) {
  HtmlReport report("Kicks <b>&</b>");
  report.Heading(2, "<i>heading</i>");
  report.Paragraph("p < q && r > s");
  report.Warning("don't <script>");
  report.KeyValues({{"<k>", "<v>"}});
  report.Table({"<h>"}, {{"<c>"}});
  report.Figure(SampleSvg(), "<cap>");
  const std::string html = report.Finish();
  for (const char* raw : {"<b>", "<i>", "<k>", "<v>", "<h>", "<c>", "<cap>", "<script"}) {
    EXPECT_EQ(html.find(raw), std::string::npos) << raw;
  }
  EXPECT_EQ(Count(html, "Kicks &lt;b&gt;&amp;&lt;/b&gt;"), 2);  // <title> and <h1>
  EXPECT_NE(html.find("<h2>&lt;i&gt;heading&lt;/i&gt;</h2>"), std::string::npos);
  EXPECT_NE(html.find("p &lt; q &amp;&amp; r &gt; s"), std::string::npos);
  EXPECT_NE(html.find("don&#39;t &lt;script&gt;"), std::string::npos);
  EXPECT_NE(html.find("<figcaption>&lt;cap&gt;</figcaption>"), std::string::npos);
  ExpectBalanced(html);
}

TEST(HtmlReportTest, PageIsSelfContainedWithInlineFigures) {
  HtmlReport report("Calibration");
  report.Paragraph("text");
  report.Warning("the normal model does not fit");
  report.Figure(SampleSvg(), "one");
  report.FigureRow({{SampleSvg(), "left"}, {SampleSvg(), "right"}});
  const std::string html = report.Finish();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<meta charset=\"utf-8\">"), std::string::npos);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  EXPECT_EQ(Count(html, "<svg "), 3);
  EXPECT_EQ(Count(html, "<figure>"), 3);
  EXPECT_EQ(Count(html, "class=\"figrow\""), 1);
  EXPECT_NE(html.find("<figure>\n<svg "), std::string::npos);  // the declaration is gone
  EXPECT_NE(html.find(">a&lt;b</text>"), std::string::npos);   // figures as given
  EXPECT_NE(html.find("class=\"warning\""), std::string::npos);
  EXPECT_NE(html.find("<style>"), std::string::npos);
  for (const char* external : {"<script", "src=", "href", "<link", "@import", "url("}) {
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  }
  EXPECT_EQ(html.substr(html.size() - 8), "</html>\n");
  ExpectBalanced(html);
}

TEST(HtmlReportTest, FigureGridWrapsFiguresInColumns) {
  HtmlReport report("Grid");
  report.FigureGrid({{SampleSvg(), "a"}, {SampleSvg(), "b & c"}}, 300);
  const std::string html = report.Finish();
  EXPECT_EQ(Count(html, "<figure>"), 2);
  EXPECT_NE(html.find("minmax(300px, 1fr)"), std::string::npos);
  EXPECT_NE(html.find("<figcaption>b &amp; c</figcaption>"), std::string::npos);
}

TEST(HtmlReportTest, NumericCellsAreRightAligned) {
  HtmlReport report("t");
  report.Table({"quantity", "value"}, {{"launch speed", "0.78"},
                                       {"offset", "-3"},
                                       {"p", "1.2e-3"},
                                       {"share", "12 %"},
                                       {"speed", "0.78 m/s"},
                                       {"CI", "[0.71, 0.85]"},
                                       {"direction", "[+1.8, +4.1]"},
                                       {"missing", "-"},
                                       {"verdict", "normal model rejected"}});
  report.KeyValues({{"trials", "200"}, {"model", "kick_forward.yaml"}});
  const std::string html = report.Finish();
  EXPECT_EQ(Count(html, "<td class=\"num\">"), 8 + 1);
  EXPECT_NE(html.find("<td>normal model rejected</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>launch speed</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>kick_forward.yaml</td>"), std::string::npos);
  EXPECT_NE(html.find("<th scope=\"col\">quantity</th>"), std::string::npos);
  EXPECT_NE(html.find("text-align: right"), std::string::npos);
  ExpectBalanced(html);
}

TEST(HtmlReportTest, HeadingLevelsAreClamped) {
  HtmlReport report("t");
  report.Heading(1, "a");
  report.Heading(3, "b");
  report.Heading(9, "c");
  const std::string html = report.Finish();
  EXPECT_NE(html.find("<h2>a</h2>"), std::string::npos);
  EXPECT_NE(html.find("<h3>b</h3>"), std::string::npos);
  EXPECT_NE(html.find("<h4>c</h4>"), std::string::npos);
  EXPECT_EQ(Count(html, "<h1>"), 1);
}

}  // namespace
}  // namespace foresight
