#!/usr/bin/env bash
# Sharded runs on one machine with GNU parallel (issue 17): scripts/slurm/parallel.sh runs 4
# shards of a small calibrate, fidelity, stability, strategies, passing (both teams) and ablations
# run, 2 at a time, and merges them; the report must have the bytes of the unsharded run (run
# time aside).
#
# Usage: parallel_test.sh FORESIGHT_BINARY
set -euo pipefail
foresight=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
command -v parallel >/dev/null || { echo "parallel_test: GNU parallel is missing (scripts/setup.sh)"; exit 1; }

check() {  # NAME ARGS...: the unsharded run, 4 shards with parallel, the merge, the comparison
  local name=$1
  shift
  "$foresight" "$@" --threads 1 --out "$name-whole" >"$name-whole.txt"
  FORESIGHT=$foresight bash "$root/scripts/slurm/parallel.sh" 4 2 "$name" "$@" >"$name-merged.txt"
  bash "$here/same_report.sh" "$name-whole" "$name/report"
  # The terminal text too (its last line names the folder).
  cmp <(sed '$d' "$name-whole.txt") <(sed '$d' "$name-merged.txt")
}

# calibrate: the merge writes what `calibrate --report DIR --out DIR/nao_calibrated.json` writes,
# so the unsharded run writes there and moves aside. Calibrate and fidelity play the fixed base,
# the cheap approximation (a tenth of a floating trial's cost): shards split the trials alike on
# both bases.
"$foresight" calibrate --robot nao --all --trials 24 --resamples 200 --base fixed --threads 1 \
  --report calibrate/report --out calibrate/report/nao_calibrated.json >calibrate-whole.txt
mv calibrate/report calibrate-whole
FORESIGHT=$foresight bash "$root/scripts/slurm/parallel.sh" 4 2 calibrate calibrate --robot nao \
  --all --trials 24 --resamples 200 --base fixed >calibrate-merged.txt
bash "$here/same_report.sh" calibrate-whole calibrate/report
cmp calibrate-whole.txt calibrate-merged.txt

check fidelity fidelity --situations quick --trials 4 --converged 200 --base fixed
check stability experiment stability --quick --repeats 10
check strategies experiment strategies --starts 200
check passing experiment passing --config dg --team both --scenarios 1,4 --trials 6
check ablations experiment ablations --config 2d --scenarios 3 --trials 4
echo "parallel_test: calibrate, fidelity, stability, strategies, passing and ablations: 4 shards merged = the unsharded bytes"
