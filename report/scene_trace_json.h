// The scene trace's file format (docs/VIEWER.md, "Trace format"): one compact JSON object whose
// numbers are integers in fixed units, so a trial of a few seconds at 100 frames per second stays
// a few hundred kB:
//   positions 0.1 mm (kTraceUnitsPerM), quaternion components 1e-4 (kTraceUnitsPerQuat),
//   spins 0.01 rad/s, impulses 1 uN s, times 1 us.
// The rounding is the trace's only loss: a position is within 0.05 mm of the simulated one.
#pragma once

#include <string>

#include "models/robot_model.h"
#include "models/scene_trace.h"

namespace foresight {

inline constexpr double kTraceUnitsPerM = 1e4;
inline constexpr double kTraceUnitsPerQuat = 1e4;
inline constexpr double kTraceUnitsPerRadps = 1e2;
inline constexpr double kTraceUnitsPerNs = 1e6;
inline constexpr double kTraceUnitsPerS = 1e6;
inline constexpr const char* kSceneTraceFormat = "foresight scene trace 1";

std::string SceneTraceJson(const SceneTrace& trace);

// A robot's drawable shapes per link (boxes, spheres, cylinders, meshes with their triangles)
// in the same units, for the viewer.
std::string RobotShapesJson(const RobotModel& model);

}  // namespace foresight
