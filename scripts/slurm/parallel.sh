#!/usr/bin/env bash
# The same as scripts/slurm/submit.sh on one big machine, with GNU parallel (issue 17): N shards,
# J at a time, then the merge.
#
#   scripts/slurm/parallel.sh N J OUT COMMAND [ARGS...]
#   scripts/slurm/parallel.sh 8 8 runs/fidelity fidelity --situations default
#
# Each shard gets --threads T (THREADS, default 1: J processes of one thread each keep the
# machine's cores busy without oversubscribing them).
set -euo pipefail
[ $# -ge 4 ] || { sed -n '2,10p' "$0"; exit 2; }
count=$1 jobs=$2 out=$3
shift 3
foresight=${FORESIGHT:-foresight}
mkdir -p "$out"
parallel --will-cite --halt now,fail=1 -j "$jobs" \
  "$foresight" "$@" --threads "${THREADS:-1}" --shard {}/"$count" --out "$out"/shard-{} \
  ">" "$out"/shard-{}.log ::: $(seq 0 $((count - 1)))
shards=()
for ((i = 0; i < count; ++i)); do shards+=("$out/shard-$i"); done
"$foresight" merge --out "$out/report" "${shards[@]}"
