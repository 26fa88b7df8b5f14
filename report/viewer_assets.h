// The viewer page's scripts, embedded at build time by report/viewer/embed_assets.cmake from
// report/viewer/ (the page's own viewer.js and viewer.css) and three.js's build files installed
// there by npm (scripts/setup.sh).
#pragma once

#include <string_view>

namespace foresight {

extern const std::string_view kThreeCoreJs;      // three/build/three.core.min.js
extern const std::string_view kThreeModuleJs;    // three/build/three.module.min.js
extern const std::string_view kOrbitControlsJs;  // three/examples/jsm/controls/OrbitControls.js
extern const std::string_view kThreePackageJson; // three/package.json (its version)
extern const std::string_view kViewerJs;         // report/viewer/viewer.js
extern const std::string_view kViewerCss;        // report/viewer/viewer.css

}  // namespace foresight
