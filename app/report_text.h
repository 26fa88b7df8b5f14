// Small helpers shared by the commands' text, JSON and SVG output.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

namespace foresight {

// printf-style formatting into a std::string (locale "C" numbers, as the rest of the output).
template <class... Args>
std::string Format(const char* format, Args... args) {
  const int length = std::snprintf(nullptr, 0, format, args...);
  std::string text(static_cast<std::size_t>(length > 0 ? length : 0) + 1, '\0');
  std::snprintf(text.data(), text.size(), format, args...);
  text.pop_back();
  return text;
}

// A data file as reports show it: relative to the models folder when inside it, so the same
// run gives the same bytes in every checkout.
std::string DisplayPath(const std::filesystem::path& file, const std::filesystem::path& models_dir);

}  // namespace foresight
