// Number formatting shared by every report and command output: locale "C", printf-style, so
// the same run gives the same bytes everywhere.
#pragma once

#include <cstdio>
#include <string>

namespace foresight {

// printf-style formatting into a std::string.
template <class... Args>
std::string Format(const char* format, Args... args) {
  const int length = std::snprintf(nullptr, 0, format, args...);
  std::string text(static_cast<std::size_t>(length > 0 ? length : 0) + 1, '\0');
  std::snprintf(text.data(), text.size(), format, args...);
  text.pop_back();
  return text;
}

// `value` with `decimals` decimals; a value that rounds to zero is written without a sign.
inline std::string Fixed(double value, int decimals) {
  std::string text = Format("%.*f", decimals, value);
  if (text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

}  // namespace foresight
