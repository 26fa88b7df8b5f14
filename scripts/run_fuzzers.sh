#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build (make fuzz) on its seed corpus from models/.
# Usage: scripts/run_fuzzers.sh BUILD_DIR RUNS [SEED]   (FUZZ_TARGETS="kicks field" runs only those)
#   RUNS inputs per target with libFuzzer seed SEED (default 1): the same inputs on every machine,
#   so a CI run is reproducible. A finding (crash, sanitizer report, uncaught exception, timeout)
#   stops with exit 1 and leaves the input in BUILD_DIR/findings/.
set -euo pipefail
build=$1
runs=$2
seed=${3:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
m=$root/models
declare -A seeds=(
  [situation]="$m/situations/*.json $m/calibration/*.json $m/fidelity/situations/*.json"
  [field]="$m/fields/*.json"
  [kicks]="$m/kicks/*.json"
  [evaluation]="$m/evaluation/*.json"
  [physics]="$m/physics/*.json"
  [robot]="$m/robots/*/robot.json"
  [motion]="$m/robots/*/motions/*.json"
  [urdf]="$m/robots/*/*.urdf $root/fuzz/seeds/urdf_self_loop_leak.urdf"
  [mesh]="$m/robots/*/meshes/*.obj $root/fuzz/seeds/mesh_assimp_leak.obj"
  [fidelity_set]="$m/fidelity/*.json"
  [check_spec]="$m/check_specs/*.json"
  [stability]="$m/experiments/stability*.json"
  [strategies]="$m/experiments/strategies.json"
  [observed_kicks]="$root/fuzz/seeds/observed_kicks.csv"
  [case]="$m/cases/*.json"
  [problem]="$root/fuzz/seeds/problem.json $m/cbr/problems/*.json"
  [case_base]="$m/cases/case_base.json"
  [retrieval]="$m/cbr/retrieval.json"
  [match_robot]="$m/match/aibo_ers7.json"
  [match_simulation]="$m/match/simulation.json"
  [match_config]="$m/match/dg.json $m/match/2d.json"
  [match_scenario]="$m/match/scenarios/*.json"
  [reactive]="$m/match/reactive.json"
  [passing]="$m/experiments/passing.json"
  [cbr_team]="$m/cbr/team.json"
  [cbr_variants]="$m/experiments/cbr_variants.json"
  [shard_file]="$root/fuzz/seeds/shard_*.json"
  [shard_trial]="$root/fuzz/seeds/shard_trial.json"
  [shard_calibration]="$root/fuzz/seeds/shard_calibration.json"
)
mkdir -p "$build/findings"
# Leaks inside third-party libraries we cannot fix (each explained in the file).
export LSAN_OPTIONS="suppressions=$root/fuzz/lsan_suppressions.txt${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
failed=0
targets=${FUZZ_TARGETS:-$(printf '%s\n' "${!seeds[@]}" | sort)}
for target in $targets; do
  if [ -z "${seeds[$target]+set}" ]; then echo "fuzz: no target '$target'"; exit 2; fi
  corpus=$build/corpus/$target
  rm -rf "$corpus" && mkdir -p "$corpus"
  # shellcheck disable=SC2086  # the globs are meant to expand
  for f in ${seeds[$target]}; do [ -f "$f" ] && cp "$f" "$corpus/"; done
  start=$(date +%s)
  if FORESIGHT_FUZZ_TARGET=$target "$build/fuzz/fuzz_readers" "$corpus" -runs="$runs" -seed="$seed" -timeout=10 \
       -rss_limit_mb=2048 -max_len=65536 -artifact_prefix="$build/findings/$target-" \
       >"$build/findings/$target.log" 2>&1; then
    echo "fuzz $target: $runs inputs, no finding ($(( $(date +%s) - start )) s)"
  else
    echo "fuzz $target: FINDING, see $build/findings/$target.log"
    grep -m 3 -E "ERROR|SUMMARY|uncaught|deadly" "$build/findings/$target.log" || true
    failed=1
  fi
done
exit $failed
