#include "report/chart_axes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

namespace foresight {

AxisTicks NiceTicks(double lo, double hi, int target, bool integers) {
  AxisTicks ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) return ticks;
  const double span = hi - lo;
  if (span <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) return ticks;
  const double raw = span / std::max(target, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / magnitude;
  double step = (r < 1.5 ? 1.0 : r < 3.5 ? 2.0 : r < 7.5 ? 5.0 : 10.0) * magnitude;
  if (integers) step = std::max(step, 1.0);
  return TicksWithStep(lo, hi, step);
}

AxisTicks TicksWithStep(double lo, double hi, double step) {
  AxisTicks ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(step > 0.0) || !std::isfinite(step)) {
    return ticks;
  }
  ticks.step = step;
  ticks.decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  const double first = std::ceil(lo / step - 1e-9);
  const double last = std::floor(hi / step + 1e-9);
  for (double i = first; i <= last && ticks.values.size() < 1000; i += 1.0) {
    const double v = i * step;
    ticks.values.push_back(std::abs(v) < 1e-9 * step ? 0.0 : v);
  }
  return ticks;
}

AxisTicks CoveringTicks(AxisRange* range, int target, bool integers) {
  const AxisTicks ticks = NiceTicks(range->lo, range->hi, target, integers);
  if (ticks.values.empty()) return ticks;
  *range = ExtendToStep(*range, ticks.step);
  return TicksWithStep(range->lo, range->hi, ticks.step);
}

std::string FormatTick(double value, int decimals) {
  if (!std::isfinite(value)) return "";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", std::clamp(decimals, 0, 12), value);
  std::string s = buffer;
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

AxisRange PaddedRange(double lo, double hi, double pad) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  if (hi < lo) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const double half = lo == 0.0 ? 0.5 : 0.1 * std::abs(lo);
    lo -= half;
    hi += half;
  }
  const double margin = pad * (hi - lo);
  return {lo - margin, hi + margin};
}

AxisRange ExtendToStep(AxisRange range, double step) {
  if (!(step > 0.0) || !std::isfinite(range.lo) || !std::isfinite(range.hi)) return range;
  return {std::floor(range.lo / step + 1e-9) * step, std::ceil(range.hi / step - 1e-9) * step};
}

std::string_view PaletteColour(int index) {
  static constexpr std::array<std::string_view, 7> kColours = {
      "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};
  const int n = static_cast<int>(kColours.size());
  return kColours[static_cast<std::size_t>(((index % n) + n) % n)];
}

double TextWidthPx(std::string_view text, double font_px) {
  double em = 0.0;
  for (unsigned char c : text) {
    if ((c & 0xC0) == 0x80) continue;  // UTF-8 continuation byte
    if (c >= '0' && c <= '9') {
      em += 0.64;
    } else if (c == '.' || c == ',' || c == ' ' || c == ':' || c == 'i' || c == 'l') {
      em += 0.32;
    } else if (c >= 'A' && c <= 'Z') {
      em += 0.70;
    } else {
      em += 0.60;
    }
  }
  return em * font_px;
}

void DrawMarker(SvgWriter& svg, double x, double y, double radius, int shape,
                std::string_view style) {
  using N = SvgWriter;
  const double r = radius;
  switch (((shape % 4) + 4) % 4) {
    case 0:
      svg.Circle(x, y, r, style);
      break;
    case 1:
      svg.Rect(x - 0.9 * r, y - 0.9 * r, 1.8 * r, 1.8 * r, style);
      break;
    case 2:
      svg.Path("M " + N::Num(x) + " " + N::Num(y - 1.25 * r) + " L " + N::Num(x + 1.25 * r) + " " +
                   N::Num(y) + " L " + N::Num(x) + " " + N::Num(y + 1.25 * r) + " L " +
                   N::Num(x - 1.25 * r) + " " + N::Num(y) + " Z",
               style);
      break;
    default:
      svg.Path("M " + N::Num(x) + " " + N::Num(y - 1.3 * r) + " L " + N::Num(x + 1.15 * r) + " " +
                   N::Num(y + 0.75 * r) + " L " + N::Num(x - 1.15 * r) + " " +
                   N::Num(y + 0.75 * r) + " Z",
               style);
  }
}

double DrawLegend(SvgWriter* svg, double x, double y, double max_width,
                  const std::vector<LegendEntry>& entries) {
  constexpr double kRow = 16.0, kGap = 5.0, kSpacing = 16.0, kFont = 11.0;
  if (entries.empty()) return 0.0;
  double cx = x;
  int row = 0;
  for (const LegendEntry& e : entries) {
    const double symbol = e.kind == LegendEntry::Kind::kLine    ? 22.0
                          : e.kind == LegendEntry::Kind::kPoint ? 10.0
                                                                : 14.0;
    const double width = symbol + kGap + TextWidthPx(e.label, kFont);
    if (cx > x && cx + width > x + max_width) {
      cx = x;
      ++row;
    }
    const double cy = y + row * kRow + kRow / 2.0;
    if (svg != nullptr) {
      switch (e.kind) {
        case LegendEntry::Kind::kSwatch:
          svg->Rect(cx, cy - 5.0, symbol, 10.0, e.style);
          break;
        case LegendEntry::Kind::kLine:
          svg->Line(cx, cy, cx + symbol, cy, e.style);
          break;
        case LegendEntry::Kind::kPoint:
          DrawMarker(*svg, cx + symbol / 2.0, cy, 3.5, e.shape, e.style);
          break;
      }
      svg->Text(cx + symbol + kGap, cy + 4.0, e.label, "font-size:11px;fill:#222222");
    }
    cx += width + kSpacing;
  }
  return (row + 1) * kRow;
}

PlotFrame::PlotFrame(PlotSpec spec)
    : spec_(std::move(spec)), svg_(spec_.size.width_px, spec_.size.height_px) {
  const double w = spec_.size.width_px, h = spec_.size.height_px;
  double y_label_width = 0.0;
  for (double v : spec_.y_ticks.values) {
    y_label_width =
        std::max(y_label_width, TextWidthPx(FormatTick(v, spec_.y_ticks.decimals), 11.0));
  }
  left_ = 8.0 + (spec_.y_label.empty() ? 0.0 : 18.0) + y_label_width + 8.0;
  double right_margin = 16.0;
  if (!spec_.x_ticks.values.empty()) {
    const std::string last = FormatTick(spec_.x_ticks.values.back(), spec_.x_ticks.decimals);
    right_margin = std::max(right_margin, TextWidthPx(last, 11.0) / 2.0 + 4.0);
  }
  right_ = w - right_margin;
  const double title_height = spec_.title.empty() ? 8.0 : 28.0;
  const double legend_height = LegendHeight(spec_.legend, right_ - left_);
  top_ = title_height + legend_height + (legend_height > 0.0 ? 4.0 : 0.0) + 8.0;
  bottom_ = h - (spec_.x_label.empty() ? 26.0 : 44.0);
  right_ = std::max(right_, left_ + 10.0);
  bottom_ = std::max(bottom_, top_ + 10.0);

  svg_.Rect(0, 0, w, h, "fill:#ffffff");
  if (!spec_.title.empty()) svg_.Text((left_ + right_) / 2.0, 19.0, spec_.title, kTitleStyle);
  DrawLegend(&svg_, left_, title_height, right_ - left_, spec_.legend);
  for (double v : spec_.x_ticks.values) svg_.Line(X(v), top_, X(v), bottom_, kGridStyle);
  for (double v : spec_.y_ticks.values) svg_.Line(left_, Y(v), right_, Y(v), kGridStyle);
}

double PlotFrame::X(double x) const {
  const double span = spec_.x.hi - spec_.x.lo;
  return span > 0.0 ? left_ + (x - spec_.x.lo) / span * (right_ - left_) : left_;
}

double PlotFrame::Y(double y) const {
  const double span = spec_.y.hi - spec_.y.lo;
  return span > 0.0 ? bottom_ - (y - spec_.y.lo) / span * (bottom_ - top_) : bottom_;
}

void PlotFrame::NoData() {
  svg_.Text((left_ + right_) / 2.0, (top_ + bottom_) / 2.0, "no data", kNoDataStyle);
}

std::string PlotFrame::Finish() {
  const std::string tick_x = std::string(kTickStyle) + ";text-anchor:middle";
  const std::string tick_y = std::string(kTickStyle) + ";text-anchor:end";
  svg_.Line(left_, top_, left_, bottom_, kAxisStyle);
  svg_.Line(left_, bottom_, right_, bottom_, kAxisStyle);
  for (double v : spec_.x_ticks.values) {
    svg_.Line(X(v), bottom_, X(v), bottom_ + 4.0, kAxisStyle);
    svg_.Text(X(v), bottom_ + 16.0, FormatTick(v, spec_.x_ticks.decimals), tick_x);
  }
  for (double v : spec_.y_ticks.values) {
    svg_.Line(left_ - 4.0, Y(v), left_, Y(v), kAxisStyle);
    svg_.Text(left_ - 7.0, Y(v) + 4.0, FormatTick(v, spec_.y_ticks.decimals), tick_y);
  }
  if (!spec_.x_label.empty()) {
    svg_.Text((left_ + right_) / 2.0, spec_.size.height_px - 9.0, spec_.x_label, kLabelStyle);
  }
  if (!spec_.y_label.empty()) {
    svg_.OpenGroup("transform=\"translate(20," + SvgWriter::Num((top_ + bottom_) / 2.0) +
                   ") rotate(-90)\"");
    svg_.Text(0, 0, spec_.y_label, kLabelStyle);
    svg_.CloseGroup();
  }
  return svg_.Finish();
}

}  // namespace foresight
