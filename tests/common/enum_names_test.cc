// The enum name table: names, parsing, the list for messages.
#include "common/enum_names.h"

#include <gtest/gtest.h>

namespace foresight {
namespace {

enum class Colour { kRed, kCyan };
constexpr EnumNames<Colour, 2> kColours{{{{Colour::kRed, "red"}, {Colour::kCyan, "cyan"}}}};

TEST(EnumNamesTest, NameAndParseAreInverse) {
  static_assert(kColours.Name(Colour::kCyan) == "cyan");
  for (Colour c : kColours.All()) EXPECT_EQ(kColours.Parse(kColours.Name(c)), c);
  EXPECT_FALSE(kColours.Parse("Cyan").has_value());
  EXPECT_FALSE(kColours.Parse("").has_value());
  EXPECT_EQ(kColours.List(), "red, cyan");
}

}  // namespace
}  // namespace foresight
