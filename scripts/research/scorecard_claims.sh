#!/usr/bin/env bash
# The claim lines and the CBR team's counters of passing runs, side by side: a research aid for
# the CBR team's changes. usage: scorecard_claims.sh RUN_DIR...
set -euo pipefail
for dir in "$@"; do
  echo "== $dir"
  sed -n '/^claims/,/^the world/p' "$dir/scorecard.txt" | grep -v "^the world"
  python3 - "$dir/passing_cbr.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
keys = ["cases_retrieved", "no_case", "race_lost", "race_skipped", "aborts_ball_lost", "aborts_ball_moved",
        "aborts_path_blocked", "aborts_timeout", "robot_time_idle_s", "robot_time_execute_s"]
for s in d["scenarios"]:
    tc = s["team_counters"]
    print("  s%d " % s["scenario"] + " ".join("%s %.2f" % (k, tc[k]["mean"]) for k in keys if k in tc))
PY
done
