// Recorded viewer trials (report/viewer_page.h) in a shard file (report/shard_file.h): the trace in
// its own format (report/scene_trace_json.h, integers in fixed units) and read back to the trace
// that format describes, so a page made from a merged run has the bytes of the unsharded run's
// page (rounding a value read back to its units gives the same integer). Every value is checked
// against what the writer produces: a tampered or damaged trace is refused with its place.
#pragma once

#include <nlohmann/json.hpp>

#include "models/scene_trace.h"
#include "report/shard_file.h"
#include "report/viewer_page.h"

namespace foresight {

nlohmann::json SceneTraceShardJson(const SceneTrace& trace);
SceneTrace ReadShardSceneTrace(const ShardValue& value);

// A viewer trial: {"label", "numbers": [[name, text], ...], "trace"} (a kick's trial: no events).
nlohmann::json ViewerTrialShardJson(const ViewerTrial& trial);
ViewerTrial ReadShardViewerTrial(const ShardValue& value);

}  // namespace foresight
