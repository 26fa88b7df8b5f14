// The printable form of names and messages: what a terminal or an XML file would take for a
// command (ESC, U+202E, a newline, bytes that are no UTF-8) is escaped, and every other
// character, ASCII or UTF-8, is kept as it is.
#include "common/one_line.h"

#include <gtest/gtest.h>

#include <string>

namespace foresight {
namespace {

TEST(OneLineTest, ControlCharactersAreEscapedAndNewlinesKeptOnlyInLines) {
  EXPECT_EQ(PrintableName("a\x1b[31mred\x01\x7f\tb"), "a\\x1b[31mred\\x01\\x7f\\x09b");
  EXPECT_EQ(PrintableName("two\nlines\r"), "two\\nlines\\x0d");
  EXPECT_EQ(PrintableLines("two\nlines\x1b"), "two\nlines\\x1b");
}

TEST(OneLineTest, FormattingCharactersThatReorderOrBreakTextAreEscaped) {
  // U+202E (right-to-left override) shows "case.json" reversed; U+2028 breaks the line;
  // U+0085 (NEL) and U+009B (CSI) are C1 controls.
  EXPECT_EQ(PrintableName("evil\u202Egnp.exe"), "evil\\u202egnp.exe");
  EXPECT_EQ(PrintableName("a\u2028b\u200Fc\u2066d"), "a\\u2028b\\u200fc\\u2066d");
  EXPECT_EQ(PrintableName("x\u0085y\u009Bz"), "x\\u0085y\\u009bz");
  EXPECT_EQ(PrintableLines("l\u202Er\n"), "l\\u202er\n");
}

TEST(OneLineTest, UnicodeTextIsKeptAndBytesThatAreNoUtf8AreEscaped) {
  EXPECT_EQ(PrintableName("Müller 日本 🙂"), "Müller 日本 🙂");
  EXPECT_EQ(PrintableName("a\xff" "b\xc3"), "a\\xffb\\xc3");  // a stray byte, a cut sequence
  EXPECT_EQ(PrintableName("\xc0\xaf"), "\\xc0\\xaf");       // an overlong '/'
  EXPECT_EQ(PrintableName("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
}

TEST(OneLineTest, OneLineCutsLongMessagesAndSaysTheirSize) {
  EXPECT_EQ(OneLine(std::string(10, 'x'), 4), "xxxx... (10 bytes)");
  EXPECT_EQ(OneLine("a\u202Eb"), "a\\u202eb");
}

}  // namespace
}  // namespace foresight
