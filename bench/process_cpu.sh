#!/usr/bin/env bash
# CPU time of whole processes (user + system, the kernel's task clock as `perf stat` reads it),
# median of N runs per command, the commands interleaved round by round so that a noisy machine
# hits them alike. Needs perf (Debian: linux-perf).
#
# Usage: bench/process_cpu.sh N 'COMMAND 1' 'COMMAND 2' ...
# Prints one line per command: median and quartiles in ms, then the command.
set -euo pipefail
runs=$1; shift
command -v perf >/dev/null || { echo "process_cpu: perf not found (apt-get install linux-perf)" >&2; exit 2; }
samples=$(mktemp -d)
trap 'rm -rf "$samples"' EXIT
for ((round = 0; round < runs; ++round)); do
  for ((i = 1; i <= $#; ++i)); do
    # shellcheck disable=SC2086  # each command is given as one string of words
    perf stat -x, -e task-clock -o "$samples/stat" -- ${!i} >/dev/null 2>&1
    grep task-clock "$samples/stat" | cut -d, -f1 >>"$samples/$i"
  done
done
for ((i = 1; i <= $#; ++i)); do
  sort -g "$samples/$i" | awk -v cmd="${!i}" '{ v[NR] = $1 }
    END { printf "%.3f ms (quartiles %.3f-%.3f)  %s\n", v[int((NR + 1) / 2)], v[int((NR + 3) / 4)], v[int((3 * NR + 3) / 4)], cmd }'
done
