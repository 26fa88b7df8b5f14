#include "report/svg_writer.h"

#include <cmath>
#include <cstdio>

namespace foresight {

SvgWriter::SvgWriter(double width, double height) : width_(width), height_(height) {}

std::string SvgWriter::Num(double value) {
  if (!std::isfinite(value)) return "0";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", value);
  std::string s = buffer;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string SvgWriter::Escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void SvgWriter::Rect(double x, double y, double w, double h, std::string_view style) {
  body_ << "<rect x=\"" << Num(x) << "\" y=\"" << Num(y) << "\" width=\"" << Num(w)
        << "\" height=\"" << Num(h) << "\" style=\"" << style << "\"/>\n";
}

void SvgWriter::Circle(double cx, double cy, double r, std::string_view style) {
  body_ << "<circle cx=\"" << Num(cx) << "\" cy=\"" << Num(cy) << "\" r=\"" << Num(r)
        << "\" style=\"" << style << "\"/>\n";
}

void SvgWriter::Line(double x1, double y1, double x2, double y2, std::string_view style) {
  body_ << "<line x1=\"" << Num(x1) << "\" y1=\"" << Num(y1) << "\" x2=\"" << Num(x2) << "\" y2=\""
        << Num(y2) << "\" style=\"" << style << "\"/>\n";
}

void SvgWriter::Text(double x, double y, std::string_view text, std::string_view style) {
  body_ << "<text x=\"" << Num(x) << "\" y=\"" << Num(y) << "\" style=\"" << style << "\">"
        << Escape(text) << "</text>\n";
}

void SvgWriter::Path(std::string_view d, std::string_view style) {
  body_ << "<path d=\"" << Escape(d) << "\" style=\"" << style << "\"/>\n";
}

void SvgWriter::OpenGroup(std::string_view attributes) {
  body_ << "<g " << attributes << ">\n";
}
void SvgWriter::CloseGroup() {
  body_ << "</g>\n";
}
void SvgWriter::Title(std::string_view text) {
  body_ << "<title>" << Escape(text) << "</title>\n";
}

std::string SvgWriter::Finish() {
  std::ostringstream doc;
  doc << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Num(width_) << "\" height=\""
      << Num(height_) << "\" viewBox=\"0 0 " << Num(width_) << " " << Num(height_) << "\" "
      << "font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      << body_.str() << "</svg>\n";
  return doc.str();
}

}  // namespace foresight
