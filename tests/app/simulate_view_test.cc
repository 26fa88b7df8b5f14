// `foresight simulate --view` in a real browser: the page the command writes is opened in
// Debian's headless chromium, played to a time, and what it shows, read back from its own
// three.js objects (<pre id="state">, report/viewer_page.h), is compared with the trace embedded
// in it, decoded here independently of the page's script. scripts/setup.sh installs chromium, so
// a missing chromium fails the test with a message saying so; only FORESIGHT_SKIP_CHROMIUM=1 in
// the environment (a machine that cannot have a browser, docs/COMMANDS.md) skips it instead.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "tests/app/run_foresight.h"

namespace {

using foresight::testing::ReadFile;
using foresight::testing::RunResult;
namespace fs = std::filesystem;

std::optional<std::string> FindChromium() {
  if (const char* env = std::getenv("FORESIGHT_CHROMIUM"); env != nullptr && *env != '\0') {
    return std::string(env);
  }
  const char* path = std::getenv("PATH");
  std::string dirs = path != nullptr ? path : "/usr/bin:/bin";
  for (std::size_t start = 0; start <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    for (const char* name : {"chromium", "chromium-browser"}) {
      const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
      if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    start = end + 1;
  }
  return std::nullopt;
}

// The JSON between `open` and `close` in `text` (empty if absent), with the HTML entities a
// serialised text node carries turned back into characters.
std::string Between(const std::string& text, const std::string& open, const std::string& close) {
  const std::size_t a = text.find(open);
  if (a == std::string::npos) return "";
  const std::size_t b = text.find(close, a + open.size());
  if (b == std::string::npos) return "";
  std::string s = text.substr(a + open.size(), b - a - open.size());
  for (const auto& [entity, c] : std::vector<std::pair<std::string, std::string>>{
           {"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}}) {
    for (std::size_t at = s.find(entity); at != std::string::npos; at = s.find(entity, at + 1)) {
      s.replace(at, entity.size(), c);
    }
  }
  return s;
}

// One trial's trace decoded from the format of report/scene_trace_json.h.
struct Trace {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> ball;
  std::vector<std::vector<double>> links;  // 7 numbers per link; empty: none this frame
  std::vector<std::string> link_names;
  nlohmann::json contacts;
};

Trace Decode(const nlohmann::json& tr) {
  Trace out;
  const double m = tr["units"]["m"], s = tr["units"]["s"];
  for (std::size_t i = 0; i < tr["t"].size(); ++i) {
    out.t_s.push_back(tr["t"][i].get<double>() / s);
    const auto& b = tr["ball"][i];
    out.ball.emplace_back(b[0].get<double>() / m, b[1].get<double>() / m, b[2].get<double>() / m);
    out.links.push_back(tr["links_pose"][i].get<std::vector<double>>());
  }
  out.link_names = tr["links"].get<std::vector<std::string>>();
  out.contacts = tr["contacts"];
  for (auto& pose : out.links) {
    for (double& v : pose) v /= m;  // positions only are compared below
  }
  return out;
}

// The frame i with t_i <= t < t_{i+1} and the share of the way on: linear interpolation.
std::pair<std::size_t, double> Locate(const Trace& tr, double t) {
  std::size_t i = 0;
  while (i + 1 < tr.t_s.size() && tr.t_s[i + 1] <= t) ++i;
  if (i + 1 >= tr.t_s.size()) return {i, 0.0};
  return {i, (t - tr.t_s[i]) / (tr.t_s[i + 1] - tr.t_s[i])};
}

Eigen::Vector3d BallAt(const Trace& tr, double t) {
  const auto [i, s] = Locate(tr, t);
  const std::size_t j = std::min(i + 1, tr.t_s.size() - 1);
  return tr.ball[i] + s * (tr.ball[j] - tr.ball[i]);
}

// A link's origin; a frame without the robot holds the last one that had it.
Eigen::Vector3d LinkAt(const Trace& tr, double t, std::size_t link) {
  auto [i, s] = Locate(tr, t);
  while (tr.links[i].empty() && i > 0) --i, s = 0.0;
  std::size_t j = std::min(i + 1, tr.t_s.size() - 1);
  if (tr.links[j].empty()) j = i;
  const auto at = [&](std::size_t k) {
    return Eigen::Vector3d(tr.links[k][7 * link], tr.links[k][7 * link + 1],
                           tr.links[k][7 * link + 2]);
  };
  return at(i) + s * (at(j) - at(i));
}

Eigen::Vector3d Vec(const nlohmann::json& a) {
  return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
}

class SimulateViewTest : public foresight::testing::ForesightRun {
 protected:
  // The page's state after chromium opened it at `fragment` and let its clock run.
  nlohmann::json PageState(const std::string& chromium, const fs::path& page,
                           const std::string& fragment) const {
    const fs::path dom = root_ / "capture" / "dom.html";
    const std::string command =
        "timeout 300 " + foresight::testing::Quote(chromium) +
        " --headless --no-sandbox --disable-gpu --enable-unsafe-swiftshader "
        "--user-data-dir=" + foresight::testing::Quote((root_ / "chromium").string()) +
        " --virtual-time-budget=30000 --dump-dom " +
        foresight::testing::Quote("file://" + page.string() + "#" + fragment) + " >" +
        foresight::testing::Quote(dom.string()) + " 2>/dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    const std::string html = ReadFile(dom);
    const std::string state = Between(html, "<pre id=\"state\" hidden=\"\">", "</pre>");
    if (state.empty() || state[0] != '{') {
      ADD_FAILURE() << "no state in the page: " << state.substr(0, 300);
      return nlohmann::json::object();
    }
    return nlohmann::json::parse(state);
  }
};

TEST_F(SimulateViewTest, ChromiumPlaysTheFiveKicksWhereTheTraceSays) {
  if (const char* skip = std::getenv("FORESIGHT_SKIP_CHROMIUM");
      skip != nullptr && std::string(skip) == "1") {
    GTEST_SKIP() << "FORESIGHT_SKIP_CHROMIUM=1: the browser test of the 3D viewer is skipped";
  }
  const std::optional<std::string> chromium = FindChromium();
  ASSERT_TRUE(chromium.has_value())
      << "chromium is not installed: run scripts/setup.sh (it installs Debian's chromium), set "
         "FORESIGHT_CHROMIUM to a chromium binary, or set FORESIGHT_SKIP_CHROMIUM=1 to skip this "
         "test on a machine without a browser";
  const RunResult r = Run({"simulate", "--situation",
                           (fs::path(FORESIGHT_TEST_MODELS_DIR) / "calibration" / "nao.json")
                               .string(),
                           "--kick", "forward", "--trials", "5", "--view", "v.html",
                           // The fixed base: the page's timings below are the bolted robot's
                           // (its trial hands the ball to a world without the robot).
                           "--base", "fixed"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path page = work() / "v.html";
  const std::string html = ReadFile(page);
  const nlohmann::json scene = nlohmann::json::parse(
      Between(html, "<script type=\"application/json\" id=\"scene-data\">", "</script>"));
  ASSERT_EQ(scene["trials"].size(), 5u);

  // Trial 3 a few milliseconds into the strike (the contact with the largest impulse; a foot
  // may graze the ball earlier as the motion winds up): the foot and the ball move fast there.
  const int trial = 3;
  const Trace tr = Decode(scene["trials"][trial]["trace"]);
  const double units_s = scene["trials"][trial]["trace"]["units"]["s"].get<double>();
  std::string foot;
  double t_strike = -1.0, largest = 0.0;
  for (const auto& c : tr.contacts) {
    const bool robot = c[2] != "post" && c[2] != "net" && c[2] != "obstacle";
    if (c[1] == "ball" && robot && c[6].get<double>() > largest) {
      largest = c[6].get<double>();
      foot = c[2];
      t_strike = c[0].get<double>() / units_s;
    }
  }
  ASSERT_FALSE(foot.empty()) << "the trace has no strike";
  const auto link = std::find(tr.link_names.begin(), tr.link_names.end(), foot);
  ASSERT_NE(link, tr.link_names.end());
  const std::size_t k = static_cast<std::size_t>(link - tr.link_names.begin());
  const double t = t_strike + 0.0037;  // between two frames at 100 per second

  const nlohmann::json state =
      PageState(*chromium, page, "trial=" + std::to_string(trial) + "&play=" + std::to_string(t));
  ASSERT_TRUE(state.contains("ball")) << state.dump();
  EXPECT_EQ(state["trial"], trial);
  EXPECT_NEAR(state["t"].get<double>(), t, 1e-9);
  const Eigen::Vector3d page_ball = Vec(state["ball"]), page_foot = Vec(state["links"][foot]);
  // Rounding in the trace (0.05 mm) and single-precision drawing: well under a millimetre.
  constexpr double kToleranceM = 5e-4;
  EXPECT_LT((page_ball - BallAt(tr, t)).norm(), kToleranceM);
  EXPECT_LT((page_foot - LinkAt(tr, t, k)).norm(), kToleranceM);
  // The check sees a frame's difference: 10 ms later the foot and the ball are elsewhere.
  EXPECT_GT((page_foot - LinkAt(tr, t + 0.01, k)).norm(), 2.0 * kToleranceM);
  EXPECT_GT((page_ball - BallAt(tr, t + 0.01)).norm(), 2.0 * kToleranceM);

  // Trial 0 paused at its end: its ball rests where its last frame says.
  const Trace tr0 = Decode(scene["trials"][0]["trace"]);
  const nlohmann::json end = PageState(*chromium, page, "trial=0&t=" + std::to_string(tr0.t_s.back()));
  ASSERT_TRUE(end.contains("ball")) << end.dump();
  EXPECT_LT((Vec(end["ball"]) - tr0.ball.back()).norm(), kToleranceM);
  EXPECT_GT((Vec(end["ball"]) - BallAt(tr, tr0.t_s.back())).norm(), 2.0 * kToleranceM)
      << "trials 0 and 3 should rest apart; the page would not show which trial it plays";
}

}  // namespace
