// The 3D viewer page (docs/VIEWER.md): one self-contained HTML file that replays scene traces
// (models/scene_trace.h) with three.js: the field, both goals with their nets, the robot drawn
// from its URDF's shapes and meshes, the ball, contacts flashing with their impulse, the trials'
// numbers beside, several trials with a picker and an overlay; or a match's robots as bodies,
// the regions on the carpet and the event log. three.js (npm, pinned in
// report/viewer/package.json) and the page's own script (report/viewer/viewer.js) are inlined
// at build time, so the file opens from disk without a network.
//
// The page can be driven from its address for tests and links: #trial=2&t=1.25 shows trial 2
// (0-based) at 1.25 s, paused; #trial=2&play=1.25 plays from the start and pauses at 1.25 s. It
// writes its state, read from its three.js objects, as JSON into <pre id="state"> whenever it
// pauses (the ball's centre, every link's origin, the time and the trial), and its title then
// ends with "[paused t=...]".
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "models/field_spec.h"
#include "models/field_box.h"
#include "models/robot_model.h"
#include "models/scene_trace.h"

namespace foresight {

using ViewerNumbers = std::vector<std::pair<std::string, std::string>>;

struct ViewerTrial {
  std::string label;
  ViewerNumbers numbers;  // shown beside the scene: launch, direction, rest, outcome...
  SceneTrace trace;
  std::vector<std::pair<double, std::string>> events;  // a match's event log (time, text)
};

struct ViewerRegion {
  std::string label;
  FieldBox box;
  int team = 0;  // colour as SceneBody::team
};

struct ViewerScene {
  std::string title;
  ViewerNumbers about;  // the run: command, inputs, seed
  const FieldSpec* field = nullptr;
  const RobotModel* robot = nullptr;  // draws the traces' links (null: no robot links)
  std::vector<ViewerRegion> regions;
  std::vector<ViewerTrial> trials;
};

std::string ViewerHtml(const ViewerScene& scene);

// The trace's three.js assets: which version is inlined (for the docs and the page's footer).
std::string ViewerLibraryVersion();

}  // namespace foresight
