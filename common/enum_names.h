// One table per enum: each value with the name it has in files, flags and reports. The table is
// the single place a name is spelled; Name, Parse, All and List are derived from it, so a value
// added to the enum needs one line here and nowhere else (a value missing from the table asserts).
//
//   inline constexpr EnumNames<Category, 4> kCategoryNames{{
//       {Category::kInfield, "infield"}, {Category::kOppGoal, "opp_goal"}, ...}};
//   kCategoryNames.Name(Category::kOut) == "out";  kCategoryNames.Parse("out") == Category::kOut
#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace foresight {

template <typename Enum, std::size_t N>
struct EnumNames {
  std::array<std::pair<Enum, std::string_view>, N> entries;

  constexpr std::string_view Name(Enum value) const {
    for (const auto& [e, name] : entries) {
      if (e == value) return name;
    }
    assert(false && "enum value missing from its name table");
    return "?";
  }

  constexpr std::optional<Enum> Parse(std::string_view name) const {
    for (const auto& [e, n] : entries) {
      if (n == name) return e;
    }
    return std::nullopt;
  }

  // Every value, in table order.
  std::vector<Enum> All() const {
    std::vector<Enum> all;
    for (const auto& entry : entries) all.push_back(entry.first);
    return all;
  }

  // "a, b, c": for help texts and error messages.
  std::string List() const {
    std::string list;
    for (const auto& entry : entries) {
      if (!list.empty()) list += ", ";
      list += entry.second;
    }
    return list;
  }
};

}  // namespace foresight
