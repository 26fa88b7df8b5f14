// The strict parser (common/strict_json.h): the tree nlohmann builds, the strict checks, and work
// (counted, not timed) that grows in proportion to the input, whatever its shape.
#include "common/strict_json.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

#include "tests/support/model_test_util.h"

namespace foresight {
namespace {

using ::testing::HasSubstr;
using testing::InputErrorMessage;

TEST(StrictJsonTest, BuildsTheTreeNlohmannBuilds) {
  const std::string text = R"({"a": [1, -2, 3.5, 18446744073709551615, "s\n\u00e9", true, null,
      [], {}, [[{"deep": {"x": [0]}}]]], "b": {"z": 1, "y": {"k": false}}, "": "empty key"})";
  EXPECT_EQ(ParseStrictJson(text, "t.json"), nlohmann::json::parse(text));
  for (const std::string scalar : {"5", "\"text\"", "null", "[]", "{}", "  [1, {\"a\": []}] "}) {
    EXPECT_EQ(ParseStrictJson(scalar, "s.json"), nlohmann::json::parse(scalar)) << scalar;
  }
}

TEST(StrictJsonTest, AKeyTwiceIsFoundInAnyObjectAtAnyDepthAfterAnyNumberOfMembers) {
  std::string many = "{";
  for (int i = 0; i < 5000; ++i) many += "\"k" + std::to_string(i) + "\": " + std::to_string(i) + ", ";
  many += "\"k17\": 0}";
  EXPECT_EQ(InputErrorMessage([&] { ParseStrictJson(many, "m.json"); }),
            "m.json: invalid JSON: the key \"k17\" appears twice in one object");
  EXPECT_EQ(InputErrorMessage([] {
              ParseStrictJson(R"({"a": [{"b": [{"c": 1, "d": 2, "c": 3}]}]})", "d.json");
            }),
            "d.json: invalid JSON: the key \"c\" appears twice in one object");
  EXPECT_NO_THROW(ParseStrictJson(R"({"a": {"c": 1}, "b": {"c": 1}, "c": [{"c": 1}, {"c": 2}]})",
                                  "ok.json"));
}

TEST(StrictJsonTest, DepthCountsTheContainersAroundAValue) {
  const auto arrays = [](int depth, const std::string& inside) {
    return std::string(depth, '[') + inside + std::string(depth, ']');
  };
  EXPECT_NO_THROW(ParseStrictJson(arrays(kMaxJsonDepth, "1"), "ok.json"));
  EXPECT_NO_THROW(ParseStrictJson(arrays(kMaxJsonDepth + 1, ""), "ok.json"));
  EXPECT_EQ(InputErrorMessage([&] { ParseStrictJson(arrays(kMaxJsonDepth + 1, "1"), "d.json"); }),
            "d.json: invalid JSON: nested deeper than 64 levels");
  EXPECT_EQ(InputErrorMessage([&] {
              ParseStrictJson(arrays(kMaxJsonDepth, "{\"k\": 1}"), "k.json");
            }),
            "k.json: invalid JSON: nested deeper than 64 levels");
}

TEST(StrictJsonTest, SyntaxErrorsAndOverflowsKeepTheirPlace) {
  EXPECT_THAT(InputErrorMessage([] { ParseStrictJson("{\n  \"a\": 1\n  \"b\": 2\n}", "b.json"); }),
              HasSubstr("b.json: invalid JSON at line 3, column 5: "));
  const std::string overflow =
      InputErrorMessage([] { ParseStrictJson("{\"x_m\": 1e999}", "o.json"); });
  EXPECT_THAT(overflow, HasSubstr("o.json: invalid JSON at line 1, column "));
  EXPECT_THAT(overflow, HasSubstr("field \"x_m\": "));
  EXPECT_THAT(overflow, HasSubstr("1e999"));
  EXPECT_THAT(InputErrorMessage([] { ParseStrictJson("{} {}", "t.json"); }),
              HasSubstr("t.json: invalid JSON at line 1, column "));
}

// A file that is no JSON is not quoted whole: nlohmann's "last read" keeps its last 40 bytes.
TEST(StrictJsonTest, ASyntaxErrorQuotesOnlyTheBytesBeforeIt) {
  const std::string text = "\"" + std::string(5000, 'a') + "bcdefghij\x01\"";
  const std::string message = InputErrorMessage([&] { ParseStrictJson(text, "n.json"); });
  EXPECT_THAT(message, HasSubstr("n.json: invalid JSON at line 1, column 5011: "));
  EXPECT_THAT(message, HasSubstr("; last read: '..." + std::string(23, 'a') + "bcdefghij"));
  EXPECT_LT(message.size(), 300u) << message;
  EXPECT_THAT(InputErrorMessage([] { ParseStrictJson("{\"a\": xyz}", "s.json"); }),
              HasSubstr("last read: '\"a\": x'"));
}

// Documents of n repetitions of one shape; every key has the same length, so the text of 2n is
// twice that of n (up to the frame).
std::string Key(int i) {
  char key[16];
  std::snprintf(key, sizeof key, "\"k%07d\"", i);
  return key;
}

std::string Repeated(int n, const std::string& open, const std::function<std::string(int)>& item,
                     const std::string& close) {
  std::string text = open;
  for (int i = 0; i < n; ++i) text += (i == 0 ? "" : ",") + item(i);
  return text + close;
}

JsonParseWork Work(const std::string& text) {
  JsonParseWork work;
  ParseStrictJson(text, "w.json", &work);
  return work;
}

// The handler takes one event per value made, per key and per container closed, and the lexer
// reads each character about once: what a document of n items costs is a fixed count per item,
// written out per shape below. (This pins the handler's calls; the time of whole 16 MiB files
// of these shapes is measured in docs/PERFORMANCE.md.)
TEST(StrictJsonTest, EachItemCostsAFixedNumberOfHandlerEvents) {
  struct Shape {
    std::string name;
    std::function<std::string(int)> document;
    std::function<std::size_t(std::size_t)> events;
  };
  const std::vector<Shape> shapes = {
      {"empty objects in notes",
       [](int n) { return Repeated(n, "{\"notes\": [", [](int) { return "{}"; }, "]}"); },
       [](std::size_t n) { return 2 * n + 5; }},  // root, key, array, n x (open, close), 2 closes
      {"members of one object",
       [](int n) { return Repeated(n, "{", [](int i) { return Key(i) + ": {}"; }, "}"); },
       [](std::size_t n) { return 3 * n + 2; }},  // n x (key, open, close), root open and close
      {"objects with members in an array",
       [](int n) {
         return Repeated(n, "[", [](int i) { return "{" + Key(i) + ": 1, \"b\": [2]}"; }, "]");
       },
       [](std::size_t n) { return 8 * n + 2; }},  // open, key, 1, key, open, 2, close, close
      {"nested pairs",
       [](int n) { return Repeated(n, "[", [](int) { return "[{\"a\": [{}]}]"; }, "]"); },
       [](std::size_t n) { return 9 * n + 2; }},  // [ { key [ { } ] } ]
  };
  for (const Shape& shape : shapes) {
    for (const int n : {1000, 20000}) {
      const std::string text = shape.document(n);
      const JsonParseWork work = Work(text);
      EXPECT_EQ(work.handler_events, shape.events(static_cast<std::size_t>(n))) << shape.name;
      EXPECT_GE(work.characters_read, text.size()) << shape.name;
      EXPECT_LE(work.characters_read, text.size() + 1) << shape.name;  // and the end
    }
  }
}

}  // namespace
}  // namespace foresight
