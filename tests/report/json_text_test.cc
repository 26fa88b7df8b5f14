// The one writer of hand-built JSON (report/json_text.h): strings escaped as JSON requires,
// numbers that read back to the same double, NaN and infinities refused with the value's place
// (they wrote "nan" into the viewer pages, which no JSON reader accepts), and the viewer page
// and the scene trace writing through it.
#include "report/json_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "report/scene_trace_json.h"
#include "report/viewer_page.h"

namespace foresight {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The message of the std::domain_error that `write` throws ("" if none).
template <class Write>
std::string Refusal(Write write) {
  try {
    write();
  } catch (const std::domain_error& e) {
    return e.what();
  }
  return "";
}

TEST(JsonTextTest, StringsAreEscapedAndReadBack) {
  for (const std::string text :
       {std::string("plain"), std::string("a \"quote\" and \\"), std::string("tab\tnew\nline\x01"),
        std::string("</script>"), std::string("caf\xc3\xa9")}) {
    EXPECT_EQ(nlohmann::json::parse(JsonString(text)).get<std::string>(), text) << text;
  }
  // Bytes that are not UTF-8 become U+FFFD instead of breaking the document.
  EXPECT_EQ(nlohmann::json::parse(JsonString("a\xff")).get<std::string>(), "a\xef\xbf\xbd");
}

TEST(JsonTextTest, NumbersReadBackExactlyAndNonFiniteOnesAreRefused) {
  for (const double x : {0.0, -1.5, 0.1, 1.0 / 3.0, 6.02214076e23, -2.5e-300}) {
    EXPECT_EQ(nlohmann::json::parse(JsonNumber(x, "x")).get<double>(), x);
  }
  EXPECT_EQ(JsonNumber(0.95, "x"), "0.95");
  EXPECT_EQ(Refusal([] { JsonNumber(kNan, "viewer field.field_length_m"); }),
            "JSON cannot hold nan (viewer field.field_length_m)");
  EXPECT_EQ(Refusal([] { JsonNumber(-kInf, "t"); }), "JSON cannot hold -inf (t)");
  EXPECT_EQ(Refusal([] { JsonFixed(kInf, 2, "replay event time"); }),
            "JSON cannot hold inf (replay event time)");
  EXPECT_EQ(JsonFixed(-0.001, 2, "x"), "0.00");
  EXPECT_EQ(Refusal([] { JsonRounded(kNan, "link pose"); }), "JSON cannot hold nan (link pose)");
  EXPECT_NE(Refusal([] { JsonRounded(1e300, "link pose"); }), "");
  EXPECT_EQ(JsonRounded(-2.5, "x"), -3);
}

TEST(JsonTextTest, ScriptSafeJsonCannotEndTheScript) {
  const std::string safe = ScriptSafeJson(JsonString("a</script>b</"));
  EXPECT_EQ(safe.find("</"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(safe).get<std::string>(), "a</script>b</");
}

TEST(JsonTextTest, AViewerPageOrTraceWithANanIsRefusedNotWritten) {
  FieldSpec field;
  field.field_length_m = kNan;
  ViewerScene scene;
  scene.title = "t";
  scene.field = &field;
  scene.trials.push_back({});
  EXPECT_EQ(Refusal([&] { ViewerHtml(scene); }),
            "JSON cannot hold nan (viewer field.field_length_m)");
  SceneTrace trace;
  trace.frames.push_back({});
  trace.frames[0].ball.p_F.x() = kInf;
  EXPECT_EQ(Refusal([&] { SceneTraceJson(trace); }),
            "JSON cannot hold inf (scene trace ball pose)");
}

// The page's own data (title, numbers, events) with characters JSON and HTML care about reads
// back unchanged from the page.
TEST(JsonTextTest, AViewerPagesTextIsEscaped) {
  FieldSpec field;
  ViewerScene scene;
  scene.title = "a \"title\" </script>";
  scene.field = &field;
  ViewerTrial trial;
  trial.label = "trial \\ 0";
  trial.numbers = {{"rest", "(1, \"2\")"}};
  trial.events = {{0.5, "A kick \"forward\"\n"}};
  scene.trials.push_back(trial);
  const std::string html = ViewerHtml(scene);
  const std::string open = "<script type=\"application/json\" id=\"scene-data\">";
  const std::size_t a = html.find(open) + open.size();
  const nlohmann::json j = nlohmann::json::parse(html.substr(a, html.find("</script>", a) - a));
  EXPECT_EQ(j["title"], scene.title);
  EXPECT_EQ(j["trials"][0]["label"], "trial \\ 0");
  EXPECT_EQ(j["trials"][0]["numbers"][0][1], "(1, \"2\")");
  EXPECT_EQ(j["trials"][0]["events"][0][1], "A kick \"forward\"\n");
  EXPECT_EQ(j["trials"][0]["events"][0][0], 0.5);
}

}  // namespace
}  // namespace foresight
