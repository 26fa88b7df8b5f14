// A self-contained HTML page (no scripts, no network): headings, text, tables, key-value
// metadata and inline SVG figures. Text is escaped; figures are inserted as given (the output
// of SvgWriter::Finish, whose XML declaration is dropped so the SVG can sit inline).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace foresight {

class HtmlReport {
 public:
  explicit HtmlReport(std::string title);

  void Heading(int level, std::string_view text);  // level 2..4 (the title is the h1)
  void Paragraph(std::string_view text);
  // A paragraph that is one link to `href` (a file beside the page).
  void Link(std::string_view href, std::string_view text);
  // A highlighted box for what the reader must not miss (e.g. "the normal model does not fit").
  void Warning(std::string_view text);
  void KeyValues(const std::vector<std::pair<std::string, std::string>>& rows);
  // Numeric-looking cells are right-aligned.
  void Table(const std::vector<std::string>& header,
             const std::vector<std::vector<std::string>>& rows);
  void Figure(std::string_view svg_document, std::string_view caption);
  // Several figures side by side (they wrap on narrow screens).
  void FigureRow(const std::vector<std::pair<std::string, std::string>>& svgs_and_captions);
  // Figures in a grid of equal columns at least `min_column_px` wide (as many as fit); long
  // captions wrap inside their column instead of widening it.
  void FigureGrid(const std::vector<std::pair<std::string, std::string>>& svgs_and_captions,
                  int min_column_px);

  std::string Finish() const;  // the whole document, "<!DOCTYPE html>" first

  static std::string Escape(std::string_view text);

 private:
  std::string title_;
  std::string body_;
};

}  // namespace foresight
