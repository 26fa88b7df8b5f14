#include "report/html_report.h"

#include <algorithm>
#include <cctype>

#include "report/svg_writer.h"

namespace foresight {
namespace {

constexpr std::string_view kStyle = R"(
body { margin: 0; background: #ffffff; color: #1a1a1a;
  font-family: system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif;
  font-size: 15px; line-height: 1.45; }
main { max-width: 1100px; margin: 0 auto; padding: 16px 24px 48px; }
h1 { font-size: 1.6em; margin: 0.4em 0 0.6em; }
h2 { font-size: 1.3em; margin: 1.6em 0 0.5em; border-bottom: 1px solid #e0e0e0; padding-bottom: 0.2em; }
h3 { font-size: 1.1em; margin: 1.3em 0 0.4em; }
h4 { font-size: 1em; margin: 1.1em 0 0.3em; }
p { margin: 0.5em 0; max-width: 80ch; }
.warning { background: #fff4d6; border: 1px solid #e6a700; border-left: 5px solid #e69500;
  border-radius: 3px; padding: 8px 12px; margin: 0.8em 0; }
table { border-collapse: collapse; margin: 0.6em 0 1em; font-size: 14px; }
th, td { border: 1px solid #d9d9d9; padding: 4px 10px; vertical-align: top; }
thead th { background: #f3f3f3; text-align: left; }
table.kv th { background: #f7f7f7; text-align: left; font-weight: 600; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
figure { margin: 0.8em 0 1.2em; }
figure svg { max-width: 100%; height: auto; display: block; }
figcaption { font-size: 13px; color: #444444; margin-top: 4px; max-width: 80ch; }
.figrow { display: flex; flex-wrap: wrap; gap: 16px; align-items: flex-start; }
.figrow figure { margin: 0.4em 0; }
.figgrid { display: grid; gap: 14px 16px; align-items: start; }
.figgrid figure { margin: 0; min-width: 0; }
.figgrid figcaption { max-width: none; }
)";

// "0.78", "-3", "1.2e-3", "12 %", "0.78 m/s", "[0.71, 0.85]", "~4": a number first and at most a
// short unit's worth of letters. A lone dash (a missing number) counts too.
bool LooksNumeric(std::string_view cell) {
  const auto begin = cell.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return false;
  std::string_view s = cell.substr(begin);
  if (s == "-" || s == "\u2013" || s == "\u2014") return true;
  for (int stripped = 0; stripped < 3; ++stripped) {  // e.g. "[+" or "~-"
    const std::size_t before = s.size();
    for (std::string_view prefix :
         {"[", "(", "~", "<", ">", "+", "-", "\u2212", "\u00b1", "\u2248", "\u2264", "\u2265"}) {
      if (s.starts_with(prefix)) {
        s.remove_prefix(prefix.size());
        break;
      }
    }
    if (s.size() == before) break;
  }
  if (s.starts_with(".")) s.remove_prefix(1);
  if (s.empty() || !std::isdigit(static_cast<unsigned char>(s.front()))) return false;
  int letters = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const bool exponent =
        (c == 'e' || c == 'E') && i > 0 && std::isdigit(static_cast<unsigned char>(s[i - 1])) != 0;
    if (std::isalpha(c) != 0 && !exponent) ++letters;
  }
  return letters <= 6;
}

// The SVG without an XML declaration (or doctype) before the <svg> element.
std::string_view InlineSvg(std::string_view svg) {
  for (;;) {
    const auto start = svg.find_first_not_of(" \t\r\n");
    if (start == std::string_view::npos) return {};
    svg.remove_prefix(start);
    if (svg.starts_with("\xEF\xBB\xBF")) {
      svg.remove_prefix(3);
    } else if (svg.starts_with("<?")) {
      const auto end = svg.find("?>");
      if (end == std::string_view::npos) return {};
      svg.remove_prefix(end + 2);
    } else if (svg.starts_with("<!DOCTYPE") || svg.starts_with("<!doctype")) {
      const auto end = svg.find('>');
      if (end == std::string_view::npos) return {};
      svg.remove_prefix(end + 1);
    } else {
      return svg;
    }
  }
}

std::string FigureHtml(std::string_view svg, std::string_view caption) {
  std::string out = "<figure>\n";
  out += InlineSvg(svg);
  if (!out.ends_with("\n")) out += "\n";
  if (!caption.empty()) out += "<figcaption>" + HtmlReport::Escape(caption) + "</figcaption>\n";
  return out + "</figure>\n";
}

}  // namespace

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

std::string HtmlReport::Escape(std::string_view text) {
  return SvgWriter::Escape(text);
}

void HtmlReport::Heading(int level, std::string_view text) {
  const std::string tag = std::string("h") + std::to_string(std::clamp(level, 2, 4));
  body_ += "<" + tag + ">" + Escape(text) + "</" + tag + ">\n";
}

void HtmlReport::Link(std::string_view href, std::string_view text) {
  body_ += "<p><a href=\"" + Escape(href) + "\">" + Escape(text) + "</a></p>\n";
}

void HtmlReport::Paragraph(std::string_view text) {
  body_ += "<p>" + Escape(text) + "</p>\n";
}

void HtmlReport::Warning(std::string_view text) {
  body_ +=
      "<div class=\"warning\" role=\"note\"><strong>Warning:</strong> " + Escape(text) + "</div>\n";
}

void HtmlReport::KeyValues(const std::vector<std::pair<std::string, std::string>>& rows) {
  if (rows.empty()) return;
  body_ += "<table class=\"kv\">\n<tbody>\n";
  for (const auto& [key, value] : rows) {
    body_ += "<tr><th scope=\"row\">" + Escape(key) + "</th><td" +
             (LooksNumeric(value) ? " class=\"num\"" : "") + ">" + Escape(value) + "</td></tr>\n";
  }
  body_ += "</tbody>\n</table>\n";
}

void HtmlReport::Table(const std::vector<std::string>& header,
                       const std::vector<std::vector<std::string>>& rows) {
  body_ += "<table>\n";
  if (!header.empty()) {
    body_ += "<thead><tr>";
    for (const std::string& h : header) body_ += "<th scope=\"col\">" + Escape(h) + "</th>";
    body_ += "</tr></thead>\n";
  }
  body_ += "<tbody>\n";
  for (const auto& row : rows) {
    body_ += "<tr>";
    for (const std::string& cell : row) {
      body_ +=
          std::string(LooksNumeric(cell) ? "<td class=\"num\">" : "<td>") + Escape(cell) + "</td>";
    }
    body_ += "</tr>\n";
  }
  body_ += "</tbody>\n</table>\n";
}

void HtmlReport::Figure(std::string_view svg_document, std::string_view caption) {
  body_ += FigureHtml(svg_document, caption);
}

void HtmlReport::FigureRow(
    const std::vector<std::pair<std::string, std::string>>& svgs_and_captions) {
  body_ += "<div class=\"figrow\">\n";
  for (const auto& [svg, caption] : svgs_and_captions) body_ += FigureHtml(svg, caption);
  body_ += "</div>\n";
}

void HtmlReport::FigureGrid(
    const std::vector<std::pair<std::string, std::string>>& svgs_and_captions,
    int min_column_px) {
  body_ += "<div class=\"figgrid\" style=\"grid-template-columns: repeat(auto-fill, minmax(" +
           std::to_string(std::max(min_column_px, 1)) + "px, 1fr))\">\n";
  for (const auto& [svg, caption] : svgs_and_captions) body_ += FigureHtml(svg, caption);
  body_ += "</div>\n";
}

std::string HtmlReport::Finish() const {
  std::string out;
  out.reserve(body_.size() + kStyle.size() + 512);
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<title>" + Escape(title_) + "</title>\n";
  out += "<style>";
  out += kStyle;
  out += "</style>\n</head>\n<body>\n<main>\n";
  out += "<h1>" + Escape(title_) + "</h1>\n";
  out += body_;
  out += "</main>\n</body>\n</html>\n";
  return out;
}

}  // namespace foresight
