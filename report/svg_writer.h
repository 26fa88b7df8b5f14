// A small builder for self-contained SVG documents (no scripts, no external references).
// Coordinates are in the document's user units; callers map field metres to them.
#pragma once

#include <sstream>
#include <string>
#include <string_view>

namespace foresight {

class SvgWriter {
 public:
  SvgWriter(double width, double height);

  void Rect(double x, double y, double w, double h, std::string_view style);
  void Circle(double cx, double cy, double r, std::string_view style);
  void Line(double x1, double y1, double x2, double y2, std::string_view style);
  void Text(double x, double y, std::string_view text, std::string_view style);
  // `d` is SVG path data (M, L, A, Z ...), numbers formatted with Num.
  void Path(std::string_view d, std::string_view style);
  void OpenGroup(std::string_view attributes);
  void CloseGroup();
  void Title(std::string_view text);  // a tooltip for the enclosing group

  std::string Finish();  // the whole document

  // &, <, >, " and ' as entities: safe in XML and HTML text and attribute values.
  static std::string Escape(std::string_view text);
  static std::string Num(double value);  // compact, locale-independent, 3 decimals

 private:
  std::ostringstream body_;
  double width_, height_;
};

// Path data ("M x y L x y ...") of a polyline with gaps: Point() continues the line, Break()
// lifts the pen so that no segment bridges a missing or undrawable point.
class PolylinePath {
 public:
  void Point(double x, double y) {
    d_ += (pen_down_ ? " L " : (d_.empty() ? "M " : " M ")) + SvgWriter::Num(x) + " " +
          SvgWriter::Num(y);
    pen_down_ = true;
  }
  void Break() { pen_down_ = false; }
  bool empty() const { return d_.empty(); }
  const std::string& data() const { return d_; }

 private:
  std::string d_;
  bool pen_down_ = false;
};

}  // namespace foresight
