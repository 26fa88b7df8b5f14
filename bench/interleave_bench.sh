#!/usr/bin/env bash
# Compares Google Benchmark binaries side by side on a shared machine: runs them in turn for
# ROUNDS rounds (A B C A B C ...), so a change in the machine's load falls on all of them alike,
# and prints, per benchmark and binary, the range of the rounds' median CPU times and the ratio of
# each binary's best median to the first binary's. Ratios from one run are what
# docs/PERFORMANCE.md compares.
#   bench/interleave_bench.sh ROUNDS 'FILTER' LABEL=BINARY [LABEL=BINARY ...]
# e.g. bench/interleave_bench.sh 3 'BM_Decision/(plain_naoth|optimal_all)$' \
#        before=/tmp/base/bench/planner_bench now=build-march-native/bench/planner_bench
set -euo pipefail

if [ $# -lt 3 ]; then
  echo "usage: $0 ROUNDS FILTER LABEL=BINARY [LABEL=BINARY ...]" >&2
  exit 2
fi
rounds=$1 filter=$2
shift 2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

for round in $(seq 1 "$rounds"); do
  for pair in "$@"; do
    label=${pair%%=*} binary=${pair#*=}
    [ -x "$binary" ] || { echo "$0: $label: '$binary' is not an executable" >&2; exit 2; }
    "$binary" --benchmark_filter="$filter" --benchmark_repetitions=3 \
      --benchmark_report_aggregates_only=true 2>/dev/null |
      awk -v label="$label" '$1 ~ /_median$/ {
        sub(/_median$/, "", $1)
        scale = ($5 == "us") ? 1e3 : ($5 == "ms") ? 1e6 : ($5 == "s") ? 1e9 : 1
        print label, $1, $4 * scale }' \
      >> "$out/medians"
  done
done

# label benchmark cpu_ns -> per benchmark: each label's min..max over rounds, best / first label's best.
awk -v first="${1%%=*}" '
  { key = $2 SUBSEP $1; v = $3 + 0
    if (!(key in lo) || v < lo[key]) lo[key] = v
    if (!(key in hi) || v > hi[key]) hi[key] = v
    if (!($2 in seen)) { seen[$2] = 1; order[++n] = $2 }
    if (!($1 in lseen)) { lseen[$1] = 1; labels[++m] = $1 } }
  END {
    printf "%-44s", "benchmark (CPU ns, range of round medians)"
    for (j = 1; j <= m; ++j) printf " %24s", labels[j]
    printf "\n"
    for (i = 1; i <= n; ++i) {
      b = order[i]; printf "%-44s", b
      for (j = 1; j <= m; ++j) {
        k = b SUBSEP labels[j]
        printf " %11.1f-%-8.1f x%.2f", lo[k], hi[k], lo[k] / lo[b SUBSEP first]
      }
      printf "\n"
    }
  }' "$out/medians"
