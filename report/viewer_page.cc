#include "report/viewer_page.h"

#include <cassert>
#include <nlohmann/json.hpp>

#include "report/html_report.h"
#include "report/json_text.h"
#include "report/scene_trace_json.h"
#include "report/viewer_assets.h"

namespace foresight {

namespace {

std::string Pairs(const ViewerNumbers& rows) {
  std::string out = "[";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    out += (i ? ",[" : "[") + JsonString(rows[i].first) + "," + JsonString(rows[i].second) + "]";
  }
  return out + "]";
}

// {"name":number,...} of named numbers, each refused when not finite (report/json_text.h).
std::string Numbers(std::initializer_list<std::pair<const char*, double>> named, const char* what) {
  std::string out = "{";
  for (const auto& [name, value] : named) {
    if (out.size() > 1) out += ',';
    out += JsonString(name) + ":" + JsonNumber(value, std::string(what) + "." + name);
  }
  return out + "}";
}

std::string FieldJson(const FieldSpec& f) {
  const GoalSpec& g = f.goal;
  std::string out = Numbers({{"field_length_m", f.field_length_m},
                             {"field_width_m", f.field_width_m},
                             {"line_width_m", f.line_width_m},
                             {"carpet_length_m", f.carpet_length_m},
                             {"carpet_width_m", f.carpet_width_m}},
                            "viewer field");
  out.pop_back();
  return out + ",\"goal\":" +
         Numbers({{"post_radius_m", g.post_radius_m},
                  {"post_centre_x_m", g.post_centre_x_m},
                  {"post_centre_y_m", g.post_centre_y_m},
                  {"net_depth_m", g.net_depth_m},
                  {"net_height_m", g.net_height_m}},
                 "viewer field.goal") +
         "}";
}

std::string SceneJson(const ViewerScene& scene) {
  std::string out = "{\"title\":" + JsonString(scene.title);
  out += ",\"about\":" + Pairs(scene.about);
  out += ",\"field\":" + FieldJson(*scene.field);
  out += ",\"ball_radius_m\":" + JsonNumber(scene.field->ball.radius_m, "viewer ball_radius_m");
  out += ",\n\"robot\":" + (scene.robot ? RobotShapesJson(*scene.robot) : std::string("null"));
  out += ",\n\"regions\":[";
  for (std::size_t i = 0; i < scene.regions.size(); ++i) {
    const ViewerRegion& r = scene.regions[i];
    std::string box = Numbers({{"x_min", r.box.x_min_m},
                               {"x_max", r.box.x_max_m},
                               {"y_min", r.box.y_min_m},
                               {"y_max", r.box.y_max_m}},
                              "viewer region");
    out += std::string(i ? "," : "") + "{\"label\":" + JsonString(r.label) +
           ",\"team\":" + std::to_string(r.team) + "," + box.substr(1);
  }
  out += "],\n\"trials\":[";
  for (std::size_t i = 0; i < scene.trials.size(); ++i) {
    const ViewerTrial& t = scene.trials[i];
    out += (i ? ",\n{" : "\n{") + std::string("\"label\":") + JsonString(t.label);
    out += ",\"numbers\":" + Pairs(t.numbers) + ",\"events\":[";
    for (std::size_t k = 0; k < t.events.size(); ++k) {
      out += std::string(k ? "," : "") + "[" + JsonNumber(t.events[k].first, "viewer event time") +
             "," + JsonString(t.events[k].second) + "]";
    }
    out += "],\n\"trace\":" + SceneTraceJson(t.trace) + "}";
  }
  return out + "]}";
}

void Script(std::string& html, const char* id, std::string_view text) {
  assert(text.find("</script") == std::string_view::npos);
  html += "<script type=\"text/plain\" id=\"";
  html += id;
  html += "\">";
  html += text;
  html += "</script>\n";
}

// Loads the inlined modules from blob: URLs, each import rewritten to its blob (a page opened
// from disk has no server to resolve 'three' or a relative path).
constexpr const char* kBootstrap = R"JS(
(function () {
  const text = id => document.getElementById(id).textContent;
  const blob = source => URL.createObjectURL(new Blob([source], {type: 'text/javascript'}));
  const swap = (source, from, to) => source.split(from).join(JSON.stringify(to));
  const core = blob(text('three-core'));
  const three = blob(swap(text('three-module'), '"./three.core.min.js"', core));
  const orbit = blob(swap(text('three-orbit'), "'three'", three));
  const viewer = blob(swap(swap(text('viewer-js'), "'three'", three),
                           "'three/addons/controls/OrbitControls.js'", orbit));
  import(viewer).catch(e => {
    document.getElementById('state').textContent = 'error: ' + e;
    document.title = 'viewer error: ' + e;
  });
})();
)JS";

constexpr const char* kBody = R"HTML(<div id="app">
<div id="view"></div>
<aside id="side">
<h1 id="title"></h1>
<label>Trial <select id="trial"></select></label>
<label><input type="checkbox" id="overlay"> all trials</label>
<label><input type="checkbox" id="follow"> follow the ball</label>
<table id="numbers"></table>
<div id="phase"></div>
<h2>Contacts (impulse)</h2>
<ol id="contacts"></ol>
<div id="events-box"><h2>Events</h2><pre id="events"></pre></div>
<h2>Run</h2>
<table id="about"></table>
<p class="hint">Drag to orbit, right-drag to pan, wheel to zoom. Space plays and pauses, the
arrow keys step one frame. The address can say where to start: #trial=2&amp;t=1.25.</p>
</aside>
<div id="controls">
<button id="back" title="one frame back (left arrow)">&lt; frame</button>
<button id="play" title="play or pause (space)">▶ play</button>
<button id="forward" title="one frame on (right arrow)">frame &gt;</button>
<input type="range" id="slider" min="0" max="1" step="0.001" value="0">
<span id="time">0.000 s</span>
<select id="speed" title="playback speed">
<option value="1">1x</option><option value="0.5">0.5x</option><option value="0.25">0.25x</option>
<option value="0.1">0.1x</option><option value="0.02">0.02x</option>
</select>
</div>
</div>
<pre id="state" hidden></pre>
)HTML";

}  // namespace

std::string ViewerLibraryVersion() {
  const nlohmann::json package = nlohmann::json::parse(kThreePackageJson);
  return "three.js " + package.at("version").get<std::string>();
}

std::string ViewerHtml(const ViewerScene& scene) {
  assert(scene.field != nullptr && !scene.trials.empty());
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>";
  html += HtmlReport::Escape(scene.title);
  html += "</title>\n<style>";
  html += kViewerCss;
  html += "</style>\n</head><body>\n";
  html += kBody;
  html += "<script>document.getElementById('title').textContent = " +
          ScriptSafeJson(JsonString(scene.title)) + ";</script>\n";
  html += "<script type=\"application/json\" id=\"scene-data\">" + ScriptSafeJson(SceneJson(scene)) +
          "</script>\n";
  // three.js is MIT licensed (Copyright 2010-2026 Three.js Authors); its files keep their notes.
  html += "<!-- " + ViewerLibraryVersion() + ", MIT licence, https://threejs.org -->\n";
  Script(html, "three-core", kThreeCoreJs);
  Script(html, "three-module", kThreeModuleJs);
  Script(html, "three-orbit", kOrbitControlsJs);
  Script(html, "viewer-js", kViewerJs);
  html += "<script>";
  html += kBootstrap;
  html += "</script>\n</body></html>\n";
  return html;
}

}  // namespace foresight
