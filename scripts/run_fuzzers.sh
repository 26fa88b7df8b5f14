#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build (make fuzz) on its seed corpus from models/.
# Usage: scripts/run_fuzzers.sh BUILD_DIR RUNS [SEED]   (FUZZ_TARGETS="kicks field" runs only those)
#   RUNS inputs per target with libFuzzer seed SEED (default 1): the same inputs on every machine,
#   so a CI run is reproducible. A finding (crash, sanitizer report, uncaught exception, timeout)
#   stops with exit 1 and leaves the input in BUILD_DIR/findings/.
# Every input has FUZZ_TIMEOUT seconds (default 10, libFuzzer -timeout). Fuzzed inputs stay
# small (-max_len), so after fuzzing every target also reads large inputs of several shapes
# (LARGE_BYTES, default 4 MiB: many empty objects, many members, nested arrays, numbers; many
# CSV rows; for the URDF reader elements nested about 280,000 deep, which overflowed urdfdom's
# stack before the nesting scan of models/xml_nesting.h) under the same limit: a reader whose work grows with the square of its input takes
# hours on them and fails here (a linear one takes well under a second).
set -euo pipefail
build=$1
runs=$2
seed=${3:-1}
timeout=${FUZZ_TIMEOUT:-10}
large_bytes=${LARGE_BYTES:-4194304}
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
export LSAN_OPTIONS="suppressions=$root/scripts/lsan_suppressions.txt${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
failed=0
# TARGET NAME WHAT ARGS...: the fuzz binary's TARGET with libFuzzer's ARGS, the log in
# findings/NAME.log, a finding's input as findings/NAME-*.
run() {
  local target=$1 name=$2 what=$3
  shift 3
  local start
  start=$(date +%s)
  if FORESIGHT_FUZZ_TARGET=$target "$build/fuzz/fuzz_readers" -timeout="$timeout" \
       -rss_limit_mb=2048 -artifact_prefix="$build/findings/$name-" "$@" \
       >"$build/findings/$name.log" 2>&1; then
    echo "fuzz $target: $what, no finding ($(( $(date +%s) - start )) s)"
  else
    echo "fuzz $target: FINDING ($what), see $build/findings/$name.log"
    grep -m 3 -E "ERROR|SUMMARY|uncaught|deadly|ALARM|timeout" "$build/findings/$name.log" || true
    failed=1
  fi
}
targets=${FUZZ_TARGETS:-$(printf '%s\n' "${!seeds[@]}" | sort)}
for target in $targets; do
  if [ -z "${seeds[$target]+set}" ]; then echo "fuzz: no target '$target'"; exit 2; fi
  corpus=$build/corpus/$target
  rm -rf "$corpus" && mkdir -p "$corpus"
  # shellcheck disable=SC2086  # the globs are meant to expand
  for f in ${seeds[$target]}; do [ -f "$f" ] && cp "$f" "$corpus/"; done
  run "$target" "$target" "$runs inputs" "$corpus" -runs="$runs" -seed="$seed" -max_len=65536
done

# Large inputs of one shape each, about $large_bytes bytes.
large=$build/large
rm -rf "$large" && mkdir -p "$large"
repeat() {  # TEXT: TEXT repeated to about $large_bytes bytes, ending after a whole TEXT
  yes "$1" | tr -d '\n' | head -c "$large_bytes" | sed "s/,[^,]*\$/,/" || true
}
{ printf '['; repeat '{},'; printf '{}]'; } >"$large/array_of_objects.json"
{ printf '['; repeat '{"a":[{}]},'; printf '{}]'; } >"$large/nested_arrays.json"
{ printf '['; repeat '1.5,'; printf '1]'; } >"$large/numbers.json"
{ printf '{'; seq -f '"k%09.0f":{},' 1 $((large_bytes / 16)); printf '"end":{}}'; } |
  tr -d '\n' >"$large/members.json"
{ head -n 1 "$root/fuzz/seeds/observed_kicks.csv"
  line=$(sed -n 2p "$root/fuzz/seeds/observed_kicks.csv")
  yes "$line" | head -c "$large_bytes" || true; } >"$large/rows.csv"
{ printf '<?xml version="1.0"?>\n<robot name="deep">'; repeat '<link name="a">'; } >"$large/deep.urdf"
for target in $targets; do
  case $target in
    urdf) inputs=("$large/deep.urdf") ;;  # urdfdom: only the nesting its own scan refuses
    mesh) continue ;;  # a third-party reader (assimp)
    observed_kicks) inputs=("$large/rows.csv") ;;
    *) inputs=("$large"/*.json) ;;
  esac
  run "$target" "$target-large" "${#inputs[@]} large inputs within $timeout s each" "${inputs[@]}"
done
exit $failed
