#!/usr/bin/env bash
# Two builds of the planner, one for the NAO V6's Atom E3845 (-march=silvermont: SSE4.2, two
# SIMD lanes) and one for this machine (-march=native: four lanes, FMA), must decide with the
# same bits (issue 18): builds planner_digest (bench/planner_digest.cc: 480 decisions, every
# double in hexadecimal) in both and compares the outputs. Only the planner's libraries are
# built (about 1.5 min on 2 cores the first time, seconds with ccache).
# Usage: scripts/same_bytes.sh [build-dir-prefix]   (default: build-march)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
prefix="${1:-$root/build-march}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
for march in silvermont native; do
  cmake -S "$root" -B "$prefix-$march" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
    -DFORESIGHT_MARCH="$march" -DFORESIGHT_BUILD_TESTS=OFF >/dev/null
  cmake --build "$prefix-$march" -j "$(nproc)" --target planner_digest >/dev/null
  "$prefix-$march/bench/planner_digest" >"$prefix-$march/digest.txt"
done
if cmp -s "$prefix-silvermont/digest.txt" "$prefix-native/digest.txt"; then
  echo "same bytes: -march=silvermont and -march=native decide alike ($(wc -l <"$prefix-native/digest.txt") decisions)"
else
  echo "DIFFERENT: -march=silvermont and -march=native decide differently:" >&2
  diff "$prefix-silvermont/digest.txt" "$prefix-native/digest.txt" | head -5 >&2
  exit 1
fi
