#include "common/json_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "common/error.h"
#include "tests/support/model_test_util.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorMessage;
using ::testing::Not;
using ::testing::StartsWith;

constexpr const char* kDocument = R"({
  "name": "demo",
  "length_m": 2.5,
  "count": 7,
  "notes": "free text is allowed at the top level",
  "inner": {"speed_mps": 1.5},
  "items": [{"speed_mps": 1.0}, {"speed_mps": "fast"}]
})";

TEST(JsonReaderTest, ReadsNumbersIntegersStringsAndObjects) {
  const JsonDocument doc = JsonDocument::Parse(kDocument, "demo.json");
  const JsonObject root = doc.Root();
  EXPECT_EQ(root.String("name"), "demo");
  EXPECT_DOUBLE_EQ(root.Number("length_m"), 2.5);
  EXPECT_EQ(root.Integer("count"), 7);
  EXPECT_DOUBLE_EQ(root.Object("inner").Number("speed_mps"), 1.5);
  ASSERT_EQ(root.ObjectArray("items").size(), 2u);
  EXPECT_DOUBLE_EQ(root.ObjectArray("items")[0].Number("speed_mps"), 1.0);
  EXPECT_TRUE(root.Has("inner"));
  EXPECT_FALSE(root.Has("outer"));
}

TEST(JsonReaderTest, FallbacksApplyOnlyToAbsentKeys) {
  const JsonDocument doc = JsonDocument::Parse(kDocument, "demo.json");
  const JsonObject root = doc.Root();
  EXPECT_DOUBLE_EQ(root.NumberOr("absent", -4.0), -4.0);
  EXPECT_DOUBLE_EQ(root.NumberOr("length_m", -4.0), 2.5);
  EXPECT_EQ(root.StringOr("absent", "fallback"), "fallback");
  EXPECT_EQ(root.StringOr("name", "fallback"), "demo");
  EXPECT_TRUE(root.ObjectArray("absent").empty());
}

TEST(JsonReaderTest, PathsOfNestedKeysNameTheArrayIndex) {
  const JsonDocument doc = JsonDocument::Parse(kDocument, "demo.json");
  const JsonObject second = doc.Root().ObjectArray("items")[1];
  EXPECT_EQ(second.PathOf("speed_mps"), "items[1].speed_mps");
  EXPECT_EQ(doc.Root().Object("inner").PathOf("speed_mps"), "inner.speed_mps");
  EXPECT_EQ(second.file(), "demo.json");
}

TEST(JsonReaderTest, WrongTypeNamesFileFieldPathAndValue) {
  const JsonDocument doc = JsonDocument::Parse(kDocument, "demo.json");
  const JsonObject second = doc.Root().ObjectArray("items")[1];
  const std::string message = InputErrorMessage([&] { second.Number("speed_mps"); });
  EXPECT_THAT(message, StartsWith("demo.json: items[1].speed_mps: "));
  EXPECT_THAT(message, HasSubstr("must be a number"));
  EXPECT_THAT(message, HasSubstr("\"fast\""));
}

TEST(JsonReaderTest, StringWhereObjectExpectedIsRejected) {
  const JsonDocument doc = JsonDocument::Parse(kDocument, "demo.json");
  const std::string message = InputErrorMessage([&] { doc.Root().Object("name"); });
  EXPECT_THAT(message, HasSubstr("demo.json: name: must be a JSON object"));
  EXPECT_THAT(message, HasSubstr("\"demo\""));
}

TEST(JsonReaderTest, NonIntegerWhereIntegerExpectedIsRejected) {
  const JsonDocument doc = JsonDocument::Parse(R"({"count": 2.5, "big": 10000000000})", "n.json");
  EXPECT_THAT(InputErrorMessage([&] { doc.Root().Integer("count"); }),
              HasSubstr("n.json: count: must be an integer, got 2.5"));
  EXPECT_THAT(InputErrorMessage([&] { doc.Root().Integer("big"); }),
              HasSubstr("n.json: big: out of range: 10000000000"));
}

TEST(JsonReaderTest, MissingKeyIsNamed) {
  const JsonDocument doc = JsonDocument::Parse(kDocument, "demo.json");
  EXPECT_EQ(InputErrorMessage([&] { doc.Root().Object("inner").Number("angle_deg"); }),
            "demo.json: inner.angle_deg: missing");
}

TEST(JsonReaderTest, UnknownKeyIsRejectedButNotesAreAllowed) {
  const JsonDocument doc = JsonDocument::Parse(kDocument, "demo.json");
  const JsonObject root = doc.Root();
  EXPECT_NO_THROW(root.RejectUnknownKeys({"name", "length_m", "count", "inner", "items"}));
  EXPECT_EQ(InputErrorMessage([&] {
              root.RejectUnknownKeys({"name", "count", "inner", "items"});
            }),
            "demo.json: length_m: unknown field");
}

TEST(JsonReaderTest, NotesAreOnlyAllowedAsTheKeyNotes) {
  const JsonDocument doc = JsonDocument::Parse(R"({"note": "typo of notes"})", "t.json");
  EXPECT_EQ(InputErrorMessage([&] { doc.Root().RejectUnknownKeys({}); }),
            "t.json: note: unknown field");
}

TEST(JsonReaderTest, SyntaxErrorGivesLineAndColumn) {
  // The comma after "a": 1 is missing; the parser fails on the string "b" (columns 3 to 5 of
  // line 3) and reports where it stopped reading: the token's last character.
  const std::string text = "{\n  \"a\": 1\n  \"b\": 2\n}\n";
  const std::string message = InputErrorMessage([&] { JsonDocument::Parse(text, "broken.json"); });
  EXPECT_THAT(message, StartsWith("broken.json: invalid JSON at line 3, column 5: "));
  EXPECT_THAT(message, Not(HasSubstr("[json.exception")));
}

TEST(JsonReaderTest, SyntaxErrorOnFirstLineCountsColumnsFromOne) {
  const std::string message =
      InputErrorMessage([] { JsonDocument::Parse("{\"a\": tru}", "x.json"); });
  EXPECT_THAT(message, HasSubstr("x.json: invalid JSON at line 1, column "));
  EXPECT_THAT(message, HasSubstr("tru"));
}

TEST(JsonReaderTest, LoadReportsSyntaxErrorsWithTheFilePath) {
  const std::filesystem::path file =
      testing::WriteTempFile("json_reader_broken.json", "{\n  \"a\": [1, 2,,]\n}\n");
  const std::string message = InputErrorMessage([&] { JsonDocument::Load(file); });
  EXPECT_THAT(message, StartsWith(file.string() + ": invalid JSON at line 2, column "));
}

TEST(JsonReaderTest, MissingFileIsAnInputErrorNamingThePath) {
  const std::filesystem::path file = testing::ModelsDir() / "fields" / "no_such_field.json";
  EXPECT_EQ(InputErrorMessage([&] { JsonDocument::Load(file); }),
            file.string() + ": cannot open file");
}

TEST(JsonReaderTest, DirectoryIsNotADocument) {
  const std::filesystem::path dir = testing::ModelsDir() / "fields";
  EXPECT_EQ(InputErrorMessage([&] { JsonDocument::Load(dir); }), dir.string() + ": is a directory");
}

TEST(JsonReaderTest, TopLevelMustBeAnObject) {
  const JsonDocument doc = JsonDocument::Parse("[1, 2, 3]", "array.json");
  EXPECT_EQ(InputErrorMessage([&] { doc.Root(); }), "array.json: top level: must be a JSON object");
}

TEST(JsonReaderTest, ArrayItemsMustBeObjects) {
  const JsonDocument doc = JsonDocument::Parse(R"({"items": [{"a": 1}, 5]})", "items.json");
  EXPECT_THAT(InputErrorMessage([&] { doc.Root().ObjectArray("items"); }),
              HasSubstr("items.json: items[1]: must be a JSON object, got 5"));
}

TEST(JsonReaderTest, OverflowingNumberCannotEnterAsInfinity) {
  // nlohmann::json throws json::out_of_range (406) for a number that overflows a double; the
  // reader must wrap it in the project's InputError (docs/ARCHITECTURE.md, "Errors").
  const std::string message = InputErrorMessage([] {
    const JsonDocument doc = JsonDocument::Parse(R"({"speed_mps": 1e999})", "inf.json");
    doc.Root().Number("speed_mps");
  });
  EXPECT_THAT(message, HasSubstr("inf.json"));
  EXPECT_THAT(message, HasSubstr("1e999"));
}

}  // namespace
TEST(JsonReaderTest, QuotesValuesShortAndOnOneLine) {
  EXPECT_EQ(QuoteJson(nlohmann::json("85%")), "\"85%\"");
  EXPECT_EQ(QuoteJson(nlohmann::json(2.5)), "2.5");
  EXPECT_EQ(QuoteJson(nlohmann::json("a\nb")), "\"a\\nb\"");
  EXPECT_EQ(QuoteJson(nlohmann::json::parse("[[1], 2, {}]")), "an array of 3 items");
  EXPECT_EQ(QuoteJson(nlohmann::json::parse(R"({"a": 1, "b": 2})")), "an object with 2 keys");
  const std::string quoted = QuoteJson(nlohmann::json(std::string(500, 'x')));
  EXPECT_EQ(quoted, "\"" + std::string(60, 'x') + "\"... (500 bytes)");
}

TEST(JsonReaderTest, DepthIsBoundedAtTheLimitNotBelow) {
  const auto nested = [](int depth) {
    return "{\"a\": " + std::string(depth - 1, '[') + std::string(depth - 1, ']') + "}";
  };
  EXPECT_NO_THROW(JsonDocument::Parse(nested(kMaxJsonDepth + 1), "ok.json"));
  EXPECT_EQ(InputErrorMessage([&] { JsonDocument::Parse(nested(kMaxJsonDepth + 2), "deep.json"); }),
            "deep.json: invalid JSON: nested deeper than 64 levels");
}

TEST(JsonReaderTest, AKeyTwiceInOneObjectIsAnErrorInAnotherObjectNot) {
  EXPECT_NO_THROW(JsonDocument::Parse(R"({"a": {"x": 1}, "b": {"x": 2}})", "ok.json"));
  EXPECT_EQ(InputErrorMessage([] { JsonDocument::Parse(R"({"a": {"x": 1, "x": 2}})", "d.json"); }),
            "d.json: invalid JSON: the key \"x\" appears twice in one object");
}

TEST(JsonReaderTest, NulBytesAndTrailingTextAreRejected) {
  EXPECT_THAT(InputErrorMessage([] { JsonDocument::Parse(std::string("{}\0", 3), "n.json"); }),
              HasSubstr("n.json: invalid JSON at line 1, column 3: a NUL byte"));
  EXPECT_THAT(InputErrorMessage([] { JsonDocument::Parse("{} x", "t.json"); }),
              StartsWith("t.json: invalid JSON at line 1, column "));
}

TEST(JsonReaderTest, OnlyRegularFilesOfBoundedSizeAreRead) {
  EXPECT_EQ(InputErrorMessage([] { JsonDocument::Load("/dev/zero"); }),
            "/dev/zero: is not a regular file (a device or a pipe?)");
  const std::filesystem::path big = testing::WriteTempFile(
      "json_reader_big.json", "{\"a\": \"" + std::string(kMaxJsonBytes, 'x') + "\"}");
  EXPECT_THAT(InputErrorMessage([&] { JsonDocument::Load(big); }),
              HasSubstr("more than the 16777216 a data file may have"));
  std::filesystem::remove(big);
}

}  // namespace foresight
