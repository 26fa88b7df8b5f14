// The viewer page (report/viewer_page.h) is one self-contained file: three.js and the page's
// script inline, nothing fetched, the scene's text unable to end its script early.
#include "report/viewer_page.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "models/field_spec.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

ViewerScene OneTrial(const FieldSpec& field) {
  ViewerScene scene;
  scene.title = "kick <one> & two";
  scene.about = {{"situation", "a</script><b>"}};
  scene.field = &field;
  ViewerTrial trial;
  trial.label = "trial 0";
  trial.numbers = {{"rest", "(1.000, 0.000) m"}};
  SceneFrame frame;
  trial.trace.rate_hz = 100.0;
  trial.trace.phases = {"roll"};
  trial.trace.frames = {frame};
  trial.events = {{0.5, "A kick </script>"}};
  scene.trials = {trial};
  return scene;
}

std::string SceneData(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"scene-data\">";
  const std::size_t a = html.find(open) + open.size();
  return html.substr(a, html.find("</script>", a) - a);
}

TEST(ViewerPageTest, IsOneFileWithThreeJsInlineAndNothingFetched) {
  const FieldSpec field = LoadFieldSpec(testing::ModelsDir() / "fields" / "spl.json");
  const std::string html = ViewerHtml(OneTrial(field));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find(ViewerLibraryVersion()), std::string::npos);
  EXPECT_EQ(ViewerLibraryVersion(), "three.js 0.185.1");  // report/viewer/package-lock.json
  EXPECT_NE(html.find("WebGLRenderer"), std::string::npos);
  EXPECT_NE(html.find("class OrbitControls"), std::string::npos);
  for (const char* fetch : {"src=\"http", "src=\"//", "href=\"http", "<link "}) {
    EXPECT_EQ(html.find(fetch), std::string::npos) << fetch;
  }
  // The title is escaped; the scene's texts cannot close its script element.
  EXPECT_NE(html.find("<title>kick &lt;one&gt; &amp; two</title>"), std::string::npos);
  const nlohmann::json scene = nlohmann::json::parse(SceneData(html));
  EXPECT_EQ(scene["about"][0][1], "a</script><b>");
  EXPECT_EQ(scene["trials"][0]["events"][0][1], "A kick </script>");
  EXPECT_EQ(scene["field"]["goal"]["net_height_m"], field.goal.net_height_m);
  EXPECT_TRUE(scene["robot"].is_null());
}

}  // namespace
}  // namespace foresight
