#!/usr/bin/env bash
# Builds of the planner for every SIMD width and both compilers must decide with the same bits:
# GCC with the compiler's default target (x86-64: SSE2, 2 lanes), GCC for the NAO V6's Atom E3845
# (-march=silvermont: SSE4.2, 2 lanes), GCC for AVX2 (-march=haswell: 4 lanes, FMA available),
# GCC for this machine (-march=native: the widest lanes it has, 8 with AVX-512) and Clang with its
# default target. Each builds planner_digest (bench/planner_digest.cc: 480 decisions, every double
# in hexadecimal; it says on stderr how many lanes it uses) and the outputs are compared. Strict
# IEEE (-ffp-contract=off) keeps the lanes alike; random draws in a written order (never two draws
# as one call's arguments, whose order C++ leaves unspecified) keep the compilers alike. Only the
# planner's libraries are built (about 1.5 min per build on 2 cores the first time, seconds with
# ccache). A CPU without AVX2 skips the haswell build, and says so.
# Usage: scripts/same_bytes.sh [build-dir-prefix]   (default: build-march)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
prefix="${1:-$root/build-march}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
build() {  # name, then extra cmake arguments
  local name=$1 dir="$prefix-$1"
  shift
  cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
    -DFORESIGHT_BUILD_TESTS=OFF "$@" >/dev/null
  cmake --build "$dir" -j "$(nproc)" --target planner_digest >/dev/null
  "$dir/bench/planner_digest" >"$dir/digest.txt" 2>"$dir/lanes.txt"
  built+=("$name ($(grep -o '[0-9]* lanes' "$dir/lanes.txt"))")
}
built=()
others=(default native clang)
build silvermont -DFORESIGHT_MARCH=silvermont
build default
if grep -qw avx2 /proc/cpuinfo; then
  build haswell -DFORESIGHT_MARCH=haswell
  others+=(haswell)
else
  echo "same_bytes: this CPU has no AVX2; the 4-lane build (-march=haswell) is not run" >&2
fi
build native -DFORESIGHT_MARCH=native
build clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang
status=0
for other in "${others[@]}"; do
  if ! cmp -s "$prefix-silvermont/digest.txt" "$prefix-$other/digest.txt"; then
    echo "DIFFERENT: GCC -march=silvermont and $other decide differently:" >&2
    diff "$prefix-silvermont/digest.txt" "$prefix-$other/digest.txt" | head -5 >&2
    status=1
  fi
done
if [ "$status" -eq 0 ]; then
  echo "same bytes: ${built[*]} decide alike ($(wc -l <"$prefix-native/digest.txt") decisions)"
fi
exit "$status"
